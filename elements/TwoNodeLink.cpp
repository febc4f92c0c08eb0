#include "elements/TwoNodeLink.h"

#include <ostream>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/SpringResponses.h"
#include "elements/ZeroLength.h"

namespace beamsolid {

TwoNodeLink::TwoNodeLink(int tag, int iNode, int jNode, const std::vector<const UniaxialMaterial*>& materials,
                         const std::vector<int>& directions, const Options& options)
    : Element(tag, {iNode, jNode}), options_(options) {
  if (materials.size() != directions.size() || materials.empty())
    throw OpenSeesError(context() + ": expected one direction per material, got " +
                        std::to_string(materials.size()) + " material(s) and " +
                        std::to_string(directions.size()) + " direction(s)");
  for (std::size_t k = 0; k < materials.size(); ++k) {
    springs_.push_back({materials[k]->clone(), directions[k], ForceVector()});
    if (directions[k] == 1 && axial_ < 0) axial_ = static_cast<int>(k);
  }
  if (options_.mass < 0.0) throw OpenSeesError(context() + ": -mass must not be negative");
}

bool TwoNodeLink::hasConstantTangent() const {
  if (pDeltaActive_) return false;
  for (const auto& s : springs_)
    if (!s.material->isLinear()) return false;
  return true;
}

void TwoNodeLink::formAxes(int ndm) {
  Vector3 xi = Vector3::Zero(), xj = Vector3::Zero();
  xi.head(ndm) = nodes()[0]->crd().head(ndm);
  xj.head(ndm) = nodes()[1]->crd().head(ndm);
  const Vector3 d = xj - xi;
  length_ = d.norm();
  const std::vector<double>& o = options_.orient;
  const Vector3 fromNodes = length_ > 0.0 ? d : Vector3::UnitX();
  Vector3 x = fromNodes, yp = Vector3::UnitY();
  if (ndm == 3) {
    if (o.size() == 6) x = Vector3(o[0], o[1], o[2]);
    if (o.size() >= 3) {
      yp = o.size() == 6 ? Vector3(o[3], o[4], o[5]) : Vector3(o[0], o[1], o[2]);
    } else if (x.cross(Vector3::UnitY()).norm() <= 1e-12 * x.norm()) {
      // Along global Y: OpenSees turns yp to (-x2, x1, 0).
      yp = Vector3(-x(1), x(0), 0.0);
    }
  } else if (o.size() >= 3) {
    x = Vector3(o[0], o[1], o[2]);
  }
  axes_ = ZeroLength::axesFromOrientation(x, yp, context(), ndm);
}

void TwoNodeLink::setDomain(Domain& domain) {
  const int ndm = domain.spaceDim();
  const int ndf = nodes()[0]->ndf();
  const bool rotations = ndf > ndm;
  for (Node* n : nodes())
    if (n->ndf() != ndf || (n->ndf() != ndm && n->ndf() != (ndm == 2 ? 3 : 6)))
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has ndf " + std::to_string(n->ndf()) +
                          "; twoNodeLink in " + std::to_string(ndm) + "D needs both nodes with ndf " +
                          (ndm == 2 ? "2 or 3" : "3 or 6") + " (the same at both)");
  if (options_.pDelta.size() != 0 && options_.pDelta.size() != (ndm == 2 ? 2u : 4u))
    throw OpenSeesError(context() + ": -pDelta takes " + (ndm == 2 ? "2 ratios (Mz at i, j)" : "4 ratios (My at i, j, Mz at i, j)") +
                        " in a " + std::to_string(ndm) + "D model, got " + std::to_string(options_.pDelta.size()));
  for (const Spring& s : springs_) {
    const int maxDir = ndm == 2 ? 3 : 6;
    if (s.direction < 1 || s.direction > maxDir)
      throw OpenSeesError(context() + ": direction " + std::to_string(s.direction) + " is not 1-" +
                          std::to_string(maxDir) +
                          (ndm == 2 ? " (1, 2 translations along local x, y; 3 the rotation)"
                                    : " (1-3 translations along local x, y, z; 4-6 rotations about them)"));
    if (s.direction > ndm && !rotations)
      throw OpenSeesError(context() + ": direction " + std::to_string(s.direction) + " is a rotation, but the nodes have ndf " +
                          std::to_string(ndf) + " (rotations need ndf " + (ndm == 2 ? "3)" : "6)"));
  }
  formAxes(ndm);

  const int n = 2 * ndf;
  const int j = ndf;
  const double L = length_;
  toLocal_.setZero(n, n);
  for (int o : {0, j}) {
    for (int r = 0; r < ndm; ++r)
      for (int c = 0; c < ndm; ++c) toLocal_(o + r, o + c) = axes_(r, c);
    if (rotations) {
      if (ndm == 3) {
        toLocal_.block<3, 3>(o + 3, o + 3) = axes_;
      } else {
        toLocal_(o + 2, o + 2) = 1.0;
      }
    }
  }
  // Basic deformations of local end displacements (see the header).
  const double sy = options_.shearDist[0], sz = options_.shearDist[1];
  Matrix basic = Matrix::Zero(ndm == 2 ? 3 : 6, n);
  for (int r = 0; r < (ndm == 2 ? 2 : 3); ++r) {
    basic(r, j + r) = 1.0;
    basic(r, r) = -1.0;
  }
  if (rotations) {
    const int thetaZ = ndm == 2 ? 2 : 5;
    basic(1, thetaZ) = -sy * L;
    basic(1, j + thetaZ) = -(1.0 - sy) * L;
    if (ndm == 3) {
      basic(2, 4) = sz * L;
      basic(2, j + 4) = (1.0 - sz) * L;
      for (int r = 0; r < 3; ++r) {
        basic(3 + r, j + 3 + r) = 1.0;
        basic(3 + r, 3 + r) = -1.0;
      }
    } else {
      basic(2, j + 2) = 1.0;
      basic(2, 2) = -1.0;
    }
  }
  for (Spring& s : springs_) s.gradient = (basic.row(s.direction - 1) * toLocal_).transpose();

  // P-Delta: local end forces P * G * local displacements.
  pDeltaActive_ = !options_.pDelta.empty() && axial_ >= 0;
  pDelta_.setZero(n, n);
  if (pDeltaActive_) {
    StiffnessMatrix G = StiffnessMatrix::Zero(n, n);
    const std::vector<double>& r = options_.pDelta;
    auto transverse = [&](int c) {  // row vector of u_cj - u_ci
      ForceVector e = ForceVector::Zero(n);
      e(j + c) = 1.0;
      e(c) = -1.0;
      return e;
    };
    // (moment ratios at i and j, the translation whose Delta it is, the
    // rotation dof the moments act on, their sign)
    struct Plane {
      double ri, rj;
      int translation, rotation;
      double sign;
    };
    std::vector<Plane> planes;
    if (ndm == 2) {
      planes.push_back({r[0], r[1], 1, 2, 1.0});
    } else {
      planes.push_back({r[0], r[1], 2, 4, -1.0});  // My from Delta z
      planes.push_back({r[2], r[3], 1, 5, 1.0});   // Mz from Delta y
    }
    for (const Plane& p : planes) {
      const ForceVector e = transverse(p.translation);
      const double couple = 1.0 - p.ri - p.rj;
      if (L > 0.0) {
        G.row(p.translation) -= couple / L * e.transpose();
        G.row(j + p.translation) += couple / L * e.transpose();
      }
      if (rotations) {
        G.row(p.rotation) += p.sign * p.ri * e.transpose();
        G.row(j + p.rotation) += p.sign * p.rj * e.transpose();
      }
    }
    pDelta_ = toLocal_.transpose() * G * toLocal_;
  }

  mass_.setZero(n, n);
  for (int o : {0, j})
    for (int r = 0; r < ndm; ++r) mass_(o + r, o + r) = 0.5 * options_.mass;
  displacement_.setZero(n);
  velocity_.setZero(n);
  force_.setZero(n);
  stiffness_.setZero(n, n);
  update();
}

void TwoNodeLink::update() {
  const Node& ni = *nodes()[0];
  const Node& nj = *nodes()[1];
  const int ndf = ni.ndf();
  displacement_.head(ndf) = ni.trialDisp();
  displacement_.segment(ndf, ndf) = nj.trialDisp();
  velocity_.head(ndf) = ni.trialVel();
  velocity_.segment(ndf, ndf) = nj.trialVel();
  for (Spring& s : springs_) s.material->setTrialStrain(s.gradient.dot(displacement_), s.gradient.dot(velocity_));
}

void TwoNodeLink::formStiffness(bool initial) {
  stiffness_.setZero();
  for (const Spring& s : springs_) {
    const double k = initial ? s.material->initialTangent() : s.material->tangent();
    stiffness_.noalias() += k * (s.gradient * s.gradient.transpose());
  }
  if (pDeltaActive_ && !initial) {
    const Spring& a = springs_[axial_];
    stiffness_.noalias() += a.material->stress() * pDelta_;
    stiffness_.noalias() += (pDelta_ * displacement_) * (a.material->tangent() * a.gradient).transpose();
  }
}

MatrixView TwoNodeLink::tangentStiff() {
  formStiffness(false);
  return MatrixView(stiffness_.data(), stiffness_.rows(), stiffness_.cols());
}

MatrixView TwoNodeLink::initialStiff() {
  formStiffness(true);
  return MatrixView(stiffness_.data(), stiffness_.rows(), stiffness_.cols());
}

VectorView TwoNodeLink::resistingForce() {
  force_.setZero();
  for (const Spring& s : springs_) force_ += s.material->stress() * s.gradient;
  if (pDeltaActive_) force_ += springs_[axial_].material->stress() * (pDelta_ * displacement_);
  return VectorView(force_.data(), force_.size());
}

MatrixView TwoNodeLink::massMatrix() { return MatrixView(mass_.data(), mass_.rows(), mass_.cols()); }

Matrix TwoNodeLink::dampingTangent() {
  Matrix c = Matrix::Zero(numDOF(), numDOF());
  for (const Spring& s : springs_)
    if (const double eta = s.material->dampingTangent(); eta != 0.0) c += eta * (s.gradient * s.gradient.transpose());
  return c;
}

void TwoNodeLink::commitState() {
  for (Spring& s : springs_) s.material->commitState();
}

void TwoNodeLink::revertToLastCommit() {
  for (Spring& s : springs_) s.material->revertToLastCommit();
}

void TwoNodeLink::revertToStart() {
  for (Spring& s : springs_) s.material->revertToStart();
}

TwoNodeLink::ForceVector TwoNodeLink::toLocal(const ForceVector& global) const { return toLocal_ * global; }

Vector TwoNodeLink::springValues(bool forces) const {
  Vector v(springs_.size());
  for (std::size_t k = 0; k < springs_.size(); ++k)
    v(k) = forces ? springs_[k].material->stress() : springs_[k].material->strain();
  return v;
}

Response TwoNodeLink::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  auto endNames = [this](const char* prefix) {
    std::vector<std::string> names;
    for (int a = 0; a < 2; ++a)
      for (int k = 0; k < nodes()[a]->ndf(); ++k) {
        std::string name = prefix;
        name += std::to_string(a + 1);
        name += '_';
        name += std::to_string(k + 1);
        names.push_back(std::move(name));
      }
    return names;
  };
  if (what == "force" || what == "forces" || what == "globalForce" || what == "globalForces")
    return {endNames("P"), [this] { return Vector(resistingForce()); }};
  if (what == "localForce" || what == "localForces")
    return {endNames("p"), [this] {
              resistingForce();
              return Vector(toLocal(force_));
            }};
  if (what == "basicForce" || what == "basicForces")
    return {Response::numberedNames("q", numSprings()), [this] { return springValues(true); }};
  if (what == "deformation" || what == "deformations" || what == "basicDeformation" ||
      what == "basicDeformations" || what == "basicDisplacement" || what == "basicDisplacements")
    return {Response::numberedNames("db", numSprings()), [this] { return springValues(false); }};
  if (what == "localDisplacement" || what == "localDisplacements")
    return {endNames("u"), [this] { return Vector(toLocal(displacement_)); }};
  if (Response r = SpringResponses::axis(what, axes_)) return r;
  if (Response r = SpringResponses::material(args, springs_)) return r;
  return {};
}

bool TwoNodeLink::setParameter(const std::vector<std::string>& args, double value) {
  return SpringResponses::setParameter(springs_, args, value);
}

void TwoNodeLink::print(std::ostream& os) const {
  os << "Element " << tag() << " type twoNodeLink nodes " << nodeTags()[0] << ' ' << nodeTags()[1] << " length "
     << length_ << " springs";
  for (const Spring& s : springs_) os << " (material " << s.material->tag() << ", dir " << s.direction << ')';
  if (options_.mass != 0.0) os << " mass " << options_.mass;
  os << '\n';
}

namespace {

std::unique_ptr<Element> buildTwoNodeLink(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element twoNodeLink " + std::to_string(tag));
  const int ndm = domain.spaceDim();
  if (ndm != 2 && ndm != 3)
    args.fail("twoNodeLink works in 2D and 3D models, this model has -ndm " + std::to_string(ndm));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  if (args.nextIsNumber())
    args.failAt(args.position(), "option", "'-mat' after the two nodes (twoNodeLink has exactly 2 nodes)");
  std::vector<int> matTags, dirs;
  TwoNodeLink::Options o;
  while (!args.done()) {
    const std::size_t at = args.position();
    if (args.nextFlag("-mat")) {
      matTags = args.nextInts("matTags", 1);
    } else if (args.nextFlag("-dir")) {
      dirs = args.nextInts("dirs", 1);
    } else if (args.nextFlag("-orient")) {
      o.orient = args.nextDoubles("orientation vectors", 3);
      if (o.orient.size() != 3 && o.orient.size() != 6)
        args.failAt(at + 1, "orientation vectors",
                    ndm == 3 ? "3 numbers (yp) or 6 (x, yp)" : "3 numbers (x) or 6 (x, yp; yp is not used in 2D)");
    } else if (args.nextFlag("-pDelta")) {
      o.pDelta = args.nextDoubles("pDeltaVals", 1);
      if (o.pDelta.size() != (ndm == 2 ? 2u : 4u))
        args.failAt(at + 1, "pDeltaVals", ndm == 2 ? "2 moment ratios (node i, node j)"
                                                    : "4 moment ratios (My at i, j, Mz at i, j)");
    } else if (args.nextFlag("-shearDist")) {
      const std::vector<double> s = args.nextDoubles("sDratios", 1);
      if (s.size() != (ndm == 2 ? 1u : 2u))
        args.failAt(at + 1, "sDratios", ndm == 2 ? "1 ratio (sDy)" : "2 ratios (sDy, sDz)");
      o.shearDist[0] = s[0];
      o.shearDist[1] = ndm == 3 ? s[1] : 0.5;
    } else if (args.nextFlag("-doRayleigh")) {
      o.doRayleigh = true;
    } else if (args.nextFlag("-mass")) {
      const std::size_t mAt = args.position();
      o.mass = args.nextDouble("m");
      if (o.mass < 0.0) args.failAt(mAt, "m", "a mass >= 0");
    } else {
      args.failAt(at, "option", "'-mat', '-dir', '-orient', '-pDelta', '-shearDist', '-doRayleigh' or '-mass'");
    }
  }
  if (matTags.empty()) args.fail("missing '-mat' followed by material tags");
  if (dirs.empty()) args.fail("missing '-dir' followed by directions");
  if (matTags.size() != dirs.size())
    args.fail("expected one direction per material, got " + std::to_string(matTags.size()) + " material(s) and " +
              std::to_string(dirs.size()) + " direction(s)");
  for (int d : dirs)
    if (d < 1 || d > (ndm == 2 ? 3 : 6))
      args.fail("direction " + std::to_string(d) + " is not 1-" + (ndm == 2 ? "3" : "6") +
                (ndm == 2 ? " (1, 2 translations along local x, y; 3 the rotation)"
                          : " (1-3 translations along local x, y, z; 4-6 rotations about them)"));
  std::vector<const UniaxialMaterial*> materials;
  for (int t : matTags) materials.push_back(&domain.uniaxialMaterials.get(t, args.context()));
  return std::make_unique<TwoNodeLink>(tag, iNode, jNode, materials, dirs, o);
}

void registerTwoNodeLink(Registry& r) { r.elements.add("twoNodeLink", &buildTwoNodeLink); }

}  // namespace

BEAMSOLID_REGISTER(registerTwoNodeLink);

}  // namespace beamsolid
