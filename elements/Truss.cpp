#include "elements/Truss.h"

#include <charconv>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/TrussSection.h"

namespace beamsolid {

Truss::Truss(int tag, int iNode, int jNode, double area, const UniaxialMaterial& material, double rho,
             bool consistentMass, bool doRayleigh)
    : Element(tag, {iNode, jNode}),
      area_(area),
      material_(material.clone()),
      rho_(rho),
      consistentMass_(consistentMass),
      doRayleigh_(doRayleigh) {}

void Truss::setDomain(Domain&) {
  dim_ = nodes()[0]->ndm();
  for (Node* n : nodes()) {
    if (n->ndm() != dim_)
      throw OpenSeesError(context() + ": nodes " + std::to_string(nodeTags()[0]) + " and " +
                          std::to_string(nodeTags()[1]) + " have different numbers of coordinates");
    // Translations alone, or with the rotations of the space.
    const int withRotations = dim_ == 1 ? 1 : dim_ == 2 ? 3 : 6;
    if (n->ndf() != dim_ && n->ndf() != withRotations)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs; a " + std::to_string(dim_) + "D truss needs nodes with ndf " +
                          std::to_string(dim_) +
                          (withRotations != dim_ ? " or " + std::to_string(withRotations) : std::string()));
  }
  const Vector3 d = nodes()[1]->crd() - nodes()[0]->crd();
  initialLength_ = d.norm();
  if (!(initialLength_ > 0.0))
    throw OpenSeesError(context() + ": nodes " + std::to_string(nodeTags()[0]) + " and " +
                        std::to_string(nodeTags()[1]) + " coincide (zero length)");
  initialAxis_ = d / initialLength_;
  axis_ = initialAxis_;
  currentLength_ = initialLength_;
  jOffset_ = nodes()[0]->ndf();
  const int n = numDOF();
  force_.setZero(n);
  stiffness_.setZero(n, n);
  mass_.resize(0, 0);
  update();
}

Vector3 Truss::relative(const Eigen::VectorXd& iValues, const Eigen::VectorXd& jValues) const {
  Vector3 d = Vector3::Zero();
  d.head(dim_) = jValues.head(dim_) - iValues.head(dim_);
  return d;
}

void Truss::update() {
  const Node& ni = *nodes()[0];
  const Node& nj = *nodes()[1];
  const Vector3 du = relative(ni.trialDisp(), nj.trialDisp());
  double strain;
  if (largeDisplacement()) {
    const Vector3 current = nj.crd() - ni.crd() + du;
    currentLength_ = current.norm();
    if (!(currentLength_ > 0.0))
      throw OpenSeesError(context() + ": the element has collapsed to zero length");
    axis_ = current / currentLength_;
    // Engineering strain of the current length; rigid rotations give none.
    strain = (currentLength_ - initialLength_) / initialLength_;
  } else {
    strain = initialAxis_.dot(du) / initialLength_;
  }
  const double strainRate = axis_.dot(relative(ni.trialVel(), nj.trialVel())) / initialLength_;
  material_->setTrialStrain(strain, strainRate);
}

void Truss::formStiffness(const Matrix3& k) {
  const auto kt = k.topLeftCorner(dim_, dim_);
  stiffness_.setZero();
  stiffness_.block(0, 0, dim_, dim_) = kt;
  stiffness_.block(jOffset_, jOffset_, dim_, dim_) = kt;
  stiffness_.block(0, jOffset_, dim_, dim_) = -kt;
  stiffness_.block(jOffset_, 0, dim_, dim_) = -kt;
}

MatrixView Truss::tangentStiff() {
  // d(force at j)/d(u_j): axial stiffness along the axis, plus for the
  // corotational bar the geometric (string) stiffness N/Ln (I - e e^T).
  Matrix3 k = (area_ * material_->tangent() / initialLength_) * (axis_ * axis_.transpose());
  if (largeDisplacement())
    k += (axialForce() / currentLength_) * (Matrix3::Identity() - axis_ * axis_.transpose());
  formStiffness(k);
  return MatrixView(stiffness_.data(), stiffness_.rows(), stiffness_.cols());
}

MatrixView Truss::initialStiff() {
  // The undeformed bar: initial axis, no axial force.
  formStiffness((area_ * material_->initialTangent() / initialLength_) * (initialAxis_ * initialAxis_.transpose()));
  return MatrixView(stiffness_.data(), stiffness_.rows(), stiffness_.cols());
}

Matrix Truss::dampingTangent() {
  // The strain rate is axis . (v_j - v_i) / L0, so d N / d v_j = A eta / L0 axis.
  // Formed in the stiffness buffer, which is then restored: a view of the
  // tangent taken before stays valid.
  const StiffnessMatrix kept = stiffness_;
  formStiffness((area_ * material_->dampingTangent() / initialLength_) * (axis_ * axis_.transpose()));
  Matrix c = stiffness_;
  stiffness_ = kept;
  return c;
}

VectorView Truss::resistingForce() {
  const Vector3 f = axialForce() * axis_;
  force_.setZero();
  force_.segment(0, dim_) = -f.head(dim_);
  force_.segment(jOffset_, dim_) = f.head(dim_);
  return VectorView(force_.data(), force_.size());
}

MatrixView Truss::massMatrix() {
  mass_.setZero(numDOF(), numDOF());
  const double total = rho_ * initialLength_;
  if (total != 0.0) {
    const double diagonal = consistentMass_ ? total / 3.0 : total / 2.0;
    const double coupling = consistentMass_ ? total / 6.0 : 0.0;
    for (int k = 0; k < dim_; ++k) {
      mass_(k, k) = diagonal;
      mass_(jOffset_ + k, jOffset_ + k) = diagonal;
      mass_(k, jOffset_ + k) = coupling;
      mass_(jOffset_ + k, k) = coupling;
    }
  }
  return MatrixView(mass_.data(), mass_.rows(), mass_.cols());
}

Response Truss::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "axialForce" || what == "basicForce" || what == "basicForces")
    return {{"N"}, [this] { return Vector::Constant(1, axialForce()); }};
  if (what == "force" || what == "forces" || what == "globalForce" || what == "globalForces") {
    // OpenSees' names: P<node>_<dof>.
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
  if (what == "localForce" || what == "localForces") {
    // OpenSees' layouts: the truss gives end forces in local axes, ndf per
    // node with only the axial ones non-zero (-N at i, +N at j); the
    // corotational truss gives the axial force alone.
    if (largeDisplacement()) return {{"N"}, [this] { return Vector::Constant(1, axialForce()); }};
    const int ndf = nodes()[0]->ndf();
    std::vector<std::string> names;
    // A 2D node's third dof is the rotation about z.
    const char* const labels3d[6] = {"N_", "Vy_", "Vz_", "T_", "My_", "Mz_"};
    const char* const labels2d[3] = {"N_", "Vy_", "Mz_"};
    const char* const* labels = dim_ == 2 ? labels2d : labels3d;
    for (int a = 1; a <= 2; ++a)
      for (int k = 0; k < ndf; ++k) names.push_back(labels[k] + std::to_string(a));
    return {names, [this, ndf] {
              Vector v = Vector::Zero(2 * ndf);
              v[0] = -axialForce();
              v[ndf] = axialForce();
              return v;
            }};
  }
  if ((what == "basicStiffness") && !largeDisplacement())
    return {{"k"}, [this] { return Vector::Constant(1, area_ * material_->tangent() / initialLength_); }};
  if (what == "basicDeformation" || what == "basicDeformations" || what == "deformation" ||
      what == "deformations")
    return {{"U"}, [this] { return Vector::Constant(1, elongation()); }};
  if (what == "material" || what == "-material" || what == "section") {
    std::size_t first = 1;
    // eleResponse(t, 'material', 1, 'stress'): a truss has one material, index 1.
    int index = 0;
    if (args.size() > 1) {
      const std::string& s = args[1];
      auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), index);
      if (ec == std::errc() && ptr == s.data() + s.size()) {
        if (index != 1) return {};
        first = 2;
      }
    }
    return material_->setResponse(std::vector<std::string>(args.begin() + first, args.end()));
  }
  return {};
}

bool Truss::setParameter(const std::vector<std::string>& args, double value) {
  if (args.empty()) return false;
  if (args[0] == "A") {
    area_ = value;
    return true;
  }
  if (args[0] == "rho") {
    rho_ = value;
    return true;
  }
  return material_->setParameter(args, value);
}

void Truss::print(std::ostream& os) const {
  os << "Element " << tag() << " type " << className() << " nodes " << nodeTags()[0] << ' ' << nodeTags()[1]
     << " A " << area_ << " material " << material_->tag() << " (" << material_->className() << ") rho " << rho_
     << '\n';
}

Truss::Options Truss::readOptions(CommandArgs& args) {
  Options o{};
  o.area = args.nextDouble("A");
  o.matTag = args.nextInt("matTag");
  while (!args.done()) {
    if (args.nextFlag("-rho")) o.rho = args.nextDouble("rho");
    else if (args.nextFlag("-cMass")) o.consistentMass = args.nextInt("cFlag") != 0;
    else if (args.nextFlag("-doRayleigh")) o.doRayleigh = args.nextInt("rFlag") != 0;
    else args.failAt(args.position(), "option", "'-rho', '-cMass' or '-doRayleigh'");
  }
  if (!(o.area > 0.0)) args.fail("A must be positive, got " + std::to_string(o.area));
  return o;
}

namespace {

std::unique_ptr<Element> buildTruss(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element truss " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  // element('Truss', tag, i, j, secTag, ...): OpenSees takes it as the section truss.
  if (TrussSection::isSectionForm(args)) return TrussSection::build(args, domain, tag, iNode, jNode);
  const Truss::Options o = Truss::readOptions(args);
  const UniaxialMaterial& material = domain.uniaxialMaterials.get(o.matTag, args.context());
  return std::make_unique<Truss>(tag, iNode, jNode, o.area, material, o.rho, o.consistentMass, o.doRayleigh);
}

void registerTruss(Registry& r) {
  r.elements.add("truss", &buildTruss);
  r.elements.add("Truss", &buildTruss);
}

}  // namespace

BEAMSOLID_REGISTER(registerTruss);

}  // namespace beamsolid
