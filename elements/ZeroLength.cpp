#include "elements/ZeroLength.h"

#include <sstream>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/SpringResponses.h"

namespace beamsolid {

ZeroLength::ZeroLength(int tag, int iNode, int jNode, const std::vector<const UniaxialMaterial*>& materials,
                       const std::vector<int>& directions, const Matrix3& localAxes, bool doRayleigh)
    : Element(tag, {iNode, jNode}), localAxes_(localAxes), doRayleigh_(doRayleigh) {
  if (materials.size() != directions.size() || materials.empty())
    throw OpenSeesError(context() + ": expected one direction per material, got " +
                        std::to_string(materials.size()) + " material(s) and " +
                        std::to_string(directions.size()) + " direction(s)");
  for (std::size_t k = 0; k < materials.size(); ++k) {
    if (directions[k] < 1 || directions[k] > 6)
      throw OpenSeesError(context() + ": direction " + std::to_string(directions[k]) +
                          " is not 1-6 (1-3 translation along local x, y, z; 4-6 rotation about them)");
    springs_.push_back({materials[k]->clone(), directions[k], ForceVector()});
  }
}

Matrix3 ZeroLength::axesFromOrientation(const Vector3& x, const Vector3& givenYp, const std::string& context,
                                        int ndm) {
  const double xNorm = x.norm();
  if (!(xNorm > 0.0)) throw OpenSeesError(context + ": -orient: the x vector has zero length");
  const Vector3 yp = ndm < 3 ? Vector3(-x(1), x(0), 0.0) : givenYp;
  const Vector3 z = x.cross(yp);
  const double zNorm = z.norm();
  if (!(zNorm > 1e-12 * xNorm * yp.norm()) || !(zNorm > 0.0))
    throw OpenSeesError(context + (ndm < 3 ? ": -orient: the x vector has no component in the model's plane"
                                           : ": -orient: the yp vector is zero or parallel to x"));
  Matrix3 axes;
  axes.row(0) = x / xNorm;
  axes.row(2) = z / zNorm;
  axes.row(1) = axes.row(2).cross(axes.row(0));
  return axes;
}

void ZeroLength::setDomain(Domain& domain) {
  const int ndm = domain.spaceDim();
  // Translational and rotational dofs per node of each space.
  const int translations = ndm, rotations = ndm == 2 ? 1 : (ndm == 3 ? 3 : 0);
  for (Node* n : nodes())
    if (n->ndf() != translations && n->ndf() != translations + rotations)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs; zeroLength in " + std::to_string(ndm) + "D needs nodes with ndf " +
                          (rotations ? std::to_string(translations) + " or " + std::to_string(translations + rotations)
                                     : std::to_string(translations)));
  const int jOffset = nodes()[0]->ndf();
  const int n = numDOF();
  for (Spring& s : springs_) {
    // In 2D direction 3 is the in-plane rotation, as 6 is (OpenSees).
    const bool rotation = s.direction > 3 || (ndm == 2 && s.direction == 3);
    const int axisRow = ndm == 2 && s.direction == 3 ? 2 : (s.direction - 1) % 3;
    if (!rotation && s.direction > ndm)
      throw OpenSeesError(context() + ": direction " + std::to_string(s.direction) + " is not a translation of a " +
                          std::to_string(ndm) + "D model (directions 1-" + std::to_string(ndm) +
                          (ndm == 2 ? ", and 3 for the rotation)" : ")"));
    if (rotation)
      for (Node* node : nodes())
        if (node->ndf() != translations + rotations || rotations == 0)
          throw OpenSeesError(context() + ": direction " + std::to_string(s.direction) +
                              " is a rotation, but node " + std::to_string(node->tag()) + " has ndf " +
                              std::to_string(node->ndf()) +
                              (ndm == 3 ? " (rotational directions 4-6 need ndf 6 at both nodes)"
                               : ndm == 2 ? " (the rotation, direction 3, needs ndf 3 at both nodes)"
                                          : " (a 1D model has no rotations)"));
    const Vector3 axis = localAxes_.row(axisRow).transpose();
    s.gradient.setZero(n);
    if (ndm == 3) {
      const int first = rotation ? 3 : 0;
      s.gradient.segment<3>(first) = -axis;
      s.gradient.segment<3>(jOffset + first) = axis;
    } else if (rotation) {
      // The plane's only rotation is about global Z.
      s.gradient(ndm) = -axis(2);
      s.gradient(jOffset + ndm) = axis(2);
    } else {
      s.gradient.head(ndm) = -axis.head(ndm);
      s.gradient.segment(jOffset, ndm) = axis.head(ndm);
    }
  }
  displacement_.setZero(n);
  velocity_.setZero(n);
  force_.setZero(n);
  stiffness_.setZero(n, n);
  update();
}

void ZeroLength::update() {
  const Node& ni = *nodes()[0];
  const Node& nj = *nodes()[1];
  const int jOffset = ni.ndf();
  displacement_.head(jOffset) = ni.trialDisp();
  displacement_.segment(jOffset, nj.ndf()) = nj.trialDisp();
  velocity_.head(jOffset) = ni.trialVel();
  velocity_.segment(jOffset, nj.ndf()) = nj.trialVel();
  for (Spring& s : springs_) s.material->setTrialStrain(s.gradient.dot(displacement_), s.gradient.dot(velocity_));
}

void ZeroLength::formStiffness(bool initial) {
  stiffness_.setZero();
  for (const Spring& s : springs_) {
    const double k = initial ? s.material->initialTangent() : s.material->tangent();
    stiffness_.noalias() += k * (s.gradient * s.gradient.transpose());
  }
}

MatrixView ZeroLength::tangentStiff() {
  formStiffness(false);
  return MatrixView(stiffness_.data(), stiffness_.rows(), stiffness_.cols());
}

MatrixView ZeroLength::initialStiff() {
  formStiffness(true);
  return MatrixView(stiffness_.data(), stiffness_.rows(), stiffness_.cols());
}

Matrix ZeroLength::dampingTangent() {
  Matrix c = Matrix::Zero(numDOF(), numDOF());
  for (const Spring& s : springs_)
    if (const double eta = s.material->dampingTangent(); eta != 0.0) c += eta * (s.gradient * s.gradient.transpose());
  return c;
}

VectorView ZeroLength::resistingForce() {
  force_.setZero();
  for (const Spring& s : springs_) force_ += s.material->stress() * s.gradient;
  return VectorView(force_.data(), force_.size());
}

void ZeroLength::commitState() {
  for (Spring& s : springs_) s.material->commitState();
}

void ZeroLength::revertToLastCommit() {
  for (Spring& s : springs_) s.material->revertToLastCommit();
}

void ZeroLength::revertToStart() {
  for (Spring& s : springs_) s.material->revertToStart();
}

Vector ZeroLength::springForces() const {
  Vector v(springs_.size());
  for (std::size_t k = 0; k < springs_.size(); ++k) v(k) = springs_[k].material->stress();
  return v;
}

Vector ZeroLength::springDeformations() const {
  Vector v(springs_.size());
  for (std::size_t k = 0; k < springs_.size(); ++k) v(k) = springs_[k].material->strain();
  return v;
}

Response ZeroLength::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "force" || what == "forces" || what == "globalForce" || what == "globalForces") {
    // OpenSees' names: P<node>_<dof>, and P<spring> for the spring forces.
    std::vector<std::string> names;
    for (int a = 0; a < 2; ++a)
      for (int k = 0; k < nodes()[a]->ndf(); ++k) {
        std::string name = "P";  // built in steps: GCC 12 misreports a chain of + (-Wrestrict)
        name += std::to_string(a + 1);
        name += '_';
        name += std::to_string(k + 1);
        names.push_back(std::move(name));
      }
    return {names, [this] { return Vector(resistingForce()); }};
  }
  if (what == "basicForce" || what == "basicForces" || what == "localForce" || what == "localForces")
    return {Response::numberedNames("P", numSprings()), [this] { return springForces(); }};
  if (what == "deformation" || what == "deformations" || what == "basicDeformation" ||
      what == "basicDeformations")
    return {Response::numberedNames("e", numSprings()), [this] { return springDeformations(); }};
  if (what == "basicStiffness") {
    // n x n (one row per spring, row by row), the springs' tangents on the diagonal.
    const int n = numSprings();
    return {Response::numberedNames("k", n * n), [this, n] {
              Vector v = Vector::Zero(n * n);
              for (int k = 0; k < n; ++k) v[k * n + k] = springs_[k].material->tangent();
              return v;
            }};
  }
  if (Response r = SpringResponses::axis(what, localAxes_)) return r;
  if (Response r = SpringResponses::material(args, springs_)) return r;
  return {};
}

bool ZeroLength::setParameter(const std::vector<std::string>& args, double value) {
  return SpringResponses::setParameter(springs_, args, value);
}

void ZeroLength::print(std::ostream& os) const {
  os << "Element " << tag() << " type zeroLength nodes " << nodeTags()[0] << ' ' << nodeTags()[1] << " springs";
  for (const Spring& s : springs_) os << " (material " << s.material->tag() << ", dir " << s.direction << ')';
  os << '\n';
}

namespace {

std::unique_ptr<Element> buildZeroLength(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element zeroLength " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  std::vector<int> matTags, dirs;
  Matrix3 axes = Matrix3::Identity();
  const int ndm = domain.spaceDim();
  bool doRayleigh = false;
  while (!args.done()) {
    if (args.nextFlag("-mat")) {
      matTags = args.nextInts("matTags", 1);
    } else if (args.nextFlag("-dir")) {
      dirs = args.nextInts("dirs", 1);
    } else if (args.nextFlag("-doRayleigh")) {
      doRayleigh = args.nextInt("rFlag") != 0;
    } else if (args.nextFlag("-orient")) {
      const std::size_t at = args.position();
      const std::vector<double> v = args.nextDoubles("orientation vectors x and yp", 6);
      if (v.size() != 6) args.failAt(at + 6, "orientation vectors x and yp", "exactly 6 numbers (x1 x2 x3 yp1 yp2 yp3)");
      axes = ZeroLength::axesFromOrientation(Vector3(v[0], v[1], v[2]), Vector3(v[3], v[4], v[5]), args.context(),
                                            ndm);
    } else {
      args.failAt(args.position(), "option", "'-mat', '-dir', '-doRayleigh' or '-orient'");
    }
  }
  if (matTags.empty()) args.fail("missing '-mat' followed by material tags");
  if (dirs.empty()) args.fail("missing '-dir' followed by directions");
  if (matTags.size() != dirs.size())
    args.fail("expected one direction per material, got " + std::to_string(matTags.size()) + " material(s) and " +
              std::to_string(dirs.size()) + " direction(s)");
  std::vector<const UniaxialMaterial*> materials;
  for (int t : matTags) materials.push_back(&domain.uniaxialMaterials.get(t, args.context()));
  return std::make_unique<ZeroLength>(tag, iNode, jNode, materials, dirs, axes, doRayleigh);
}

void registerZeroLength(Registry& r) { r.elements.add("zeroLength", &buildZeroLength); }

}  // namespace

BEAMSOLID_REGISTER(registerZeroLength);

}  // namespace beamsolid
