#include "elements/SolidElement.h"

#include <charconv>
#include <ostream>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/GaussPointResponse.h"

namespace beamsolid {

namespace {

bool parseIndex(const std::string& s, int& out) {
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size();
}

}  // namespace

template <int Dim, class C>
SolidElement<Dim, C>::SolidElement(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material,
                                const std::string& kind, int points, double thickness, const BodyForce& bodyForce)
    : Element(tag, std::vector<int>(nodeTags.begin(), nodeTags.end())),
      kind_(kind),
      thickness_(thickness),
      bodyForce_(bodyForce) {
  for (int p = 0; p < points; ++p) {
    materials_.push_back(material.clone(kind));
    if (!materials_.back())
      throw OpenSeesError("element " + std::to_string(tag) + ": nDMaterial " + std::to_string(material.tag()) +
                          " (" + material.className() + ") has no " + kind + " form");
  }
}

template <int Dim, class C>
bool SolidElement<Dim, C>::hasConstantTangent() const {
  for (const auto& m : materials_)
    if (!m->isLinear()) return false;
  return true;
}

template <int Dim, class C>
void SolidElement<Dim, C>::setDomain(Domain&) {
  constantTangentValid_ = false;
  for (Node* n : nodes()) {
    if constexpr (Dim == 3) {
      if (n->ndf() != 3)
        throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                            " dofs; " + className() +
                            " needs nodes with ndf 3 (use model('basic', '-ndm', 3, '-ndf', 3))");
    } else {
      if (n->ndf() != 2 || n->ndm() != 2)
        throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has ndm " +
                            std::to_string(n->ndm()) + " and ndf " + std::to_string(n->ndf()) + "; " + className() +
                            " needs nodes of a 2D model with ndf 2 (model('basic', '-ndm', 2, '-ndf', 2))");
    }
  }
  typename Cell::NodeCoordinates X;
  for (int a = 0; a < kNodes; ++a) X.row(a) = nodes()[a]->crd().template head<Dim>().transpose();
  cell_ = Cell(X, context(), Cell::orderHint());
  prepare();
  // Material state follows the current node displacements (nodes may already be displaced).
  update();
}

template <int Dim, class C>
void SolidElement<Dim, C>::update() {
  for (int a = 0; a < kNodes; ++a)
    displacement_.template segment<Dim>(Dim * a) = nodes()[a]->trialDisp().template head<Dim>();
  if (constantTangentValid_) {
    materialsStale_ = true;  // the force is affine (resistingForce)
    return;
  }
  setMaterialStrains(displacement_);
  materialsStale_ = false;
}

template <int Dim, class C>
void SolidElement<Dim, C>::refreshMaterials() const {
  if (!materialsStale_) return;
  const_cast<SolidElement*>(this)->setMaterialStrains(displacement_);
  materialsStale_ = false;
}

template <int Dim, class C>
typename SolidElement<Dim, C>::NodalMatrix& SolidElement<Dim, C>::buffer(std::unique_ptr<NodalMatrix>& m) {
  if (!m) m = std::make_unique<NodalMatrix>();
  return *m;
}

template <int Dim, class C>
MatrixView SolidElement<Dim, C>::tangentStiff() {
  // A linear material's tangent never changes: form it once.
  if (constantTangentValid_) return viewOf(*constantTangent_);
  refreshMaterials();
  if (hasConstantTangent()) {
    formStiffness(false, buffer(constantTangent_));
    formInternalForce(referenceForce_);
    referenceDisplacement_ = displacement_;
    constantTangentValid_ = true;
    return viewOf(*constantTangent_);
  }
  formStiffness(false, buffer(stiffness_));
  return viewOf(*stiffness_);
}

template <int Dim, class C>
MatrixView SolidElement<Dim, C>::initialStiff() {
  refreshMaterials();
  formStiffness(true, buffer(stiffness_));
  return viewOf(*stiffness_);
}

template <int Dim, class C>
typename SolidElement<Dim, C>::NodalVector SolidElement<Dim, C>::appliedLoad() const {
  NodalVector p;
  const BodyForce& perVolume = bodyForceFromLoads_ ? loadedBodyForce_ : bodyForce_;
  for (int a = 0; a < kNodes; ++a)
    p.template segment<Dim>(Dim * a) = thickness_ * cell_.nodalVolume()(a) * perVolume;
  return p;
}

template <int Dim, class C>
VectorView SolidElement<Dim, C>::resistingForce() {
  if (constantTangentValid_) {
    force_.noalias() = referenceForce_ + *constantTangent_ * (displacement_ - referenceDisplacement_);
  } else {
    refreshMaterials();
    formInternalForce(force_);
  }
  force_ -= appliedLoad();
  return viewOf(force_);
}

template <int Dim, class C>
MatrixView SolidElement<Dim, C>::massMatrix() {
  NodalMatrix& mass = buffer(mass_);
  mass.setZero();
  const double rho = density();
  if (rho == 0.0) return viewOf(mass);
  const double scale = rho * thickness_;
  switch (massKind()) {
    case MassKind::Consistent: {
      const typename Cell::NodalScalars m = cell_.shapeProducts();
      for (int a = 0; a < kNodes; ++a)
        for (int b = 0; b < kNodes; ++b)
          for (int i = 0; i < Dim; ++i) mass(Dim * a + i, Dim * b + i) = scale * m(a, b);
      break;
    }
    case MassKind::RowSum:
      for (int a = 0; a < kNodes; ++a)
        for (int i = 0; i < Dim; ++i) mass(Dim * a + i, Dim * a + i) = scale * cell_.nodalVolume()(a);
      break;
    case MassKind::Uniform:
      for (int k = 0; k < kDofs; ++k) mass(k, k) = scale * cell_.volume() / kNodes;
      break;
  }
  return viewOf(mass);
}

template <int Dim, class C>
void SolidElement<Dim, C>::commitState() {
  refreshMaterials();
  for (auto& m : materials_) m->commitState();
}

template <int Dim, class C>
void SolidElement<Dim, C>::revertToLastCommit() {
  materialsStale_ = false;  // back to the committed state, which they hold
  for (auto& m : materials_) m->revertToLastCommit();
}

template <int Dim, class C>
void SolidElement<Dim, C>::revertToStart() {
  materialsStale_ = false;
  for (auto& m : materials_) m->revertToStart();
  materialsChanged();
}

template <int Dim, class C>
void SolidElement<Dim, C>::addLoad(const ElementLoad& load, double factor) {
  if (load.type != ElementLoad::Type::SelfWeight) {
    Element::addLoad(load, factor);
    return;
  }
  // ElementLoad keeps the 3D layout {bx, by, bz}; bz is 0 in 2D.
  if (load.values.size() < static_cast<std::size_t>(Dim) || (Dim == 3 && load.values.size() != 3))
    throw OpenSeesError(context() + ": -selfWeight expects " + std::to_string(Dim) + " values (factors on b1, b2" +
                        (Dim == 3 ? ", b3" : "") + "), got " + std::to_string(load.values.size()));
  bodyForceFromLoads_ = true;
  for (int i = 0; i < Dim; ++i) loadedBodyForce_(i) += factor * load.values[i] * bodyForce_(i);
}

template <int Dim, class C>
void SolidElement<Dim, C>::zeroLoad() {
  loadedBodyForce_.setZero();
  bodyForceFromLoads_ = false;
}

template <int Dim, class C>
std::vector<std::string> SolidElement<Dim, C>::pointComponentNames(bool stress) const {
  const Eigen::Index size = materials_[0]->stress().size();
  if (size == 6) {
    static const char* const stresses[6] = {"sigma11", "sigma22", "sigma33", "sigma12", "sigma23", "sigma13"};
    static const char* const strains[6] = {"eps11", "eps22", "eps33", "eps12", "eps23", "eps13"};
    return std::vector<std::string>(stress ? stresses : strains, (stress ? stresses : strains) + 6);
  }
  if (size == 3) return stress ? std::vector<std::string>{"sigma11", "sigma22", "sigma12"}
                               : std::vector<std::string>{"eta11", "eta22", "eta12"};
  return Response::numberedNames(stress ? "sigma" : "eps", static_cast<int>(size));
}

template <int Dim, class C>
Vector SolidElement<Dim, C>::pointVectors(bool stress) const {
  refreshMaterials();
  const Eigen::Index size = materials_[0]->stress().size();
  Vector out(size * materialPoints());
  for (int p = 0; p < materialPoints(); ++p)
    out.segment(size * p, size) = stress ? materials_[p]->stress() : materials_[p]->strain();
  return out;
}

template <int Dim, class C>
Response SolidElement<Dim, C>::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  refreshMaterials();
  const std::string& what = args[0];
  const bool stresses = what == "stresses" || what == "stress";
  if (stresses || what == "strains" || what == "strain") {
    // OpenSees repeats the component names for every point; bricks with
    // several points suffix the point (sigma11_1 ...) so that recorder
    // sidecar columns stay unique.
    const std::vector<std::string> component = pointComponentNames(stresses);
    std::vector<std::string> names;
    for (int p = 1; p <= materialPoints(); ++p)
      for (const std::string& c : component)
        names.push_back(Dim == 3 && materialPoints() > 1 ? c + "_" + std::to_string(p) : c);
    return {names, [this, stresses] { return pointVectors(stresses); }};
  }
  if (what == "force" || what == "forces" || what == "globalForce" || what == "globalForces") {
    std::vector<std::string> names;
    for (int a = 1; a <= kNodes; ++a)
      for (int i = 1; i <= Dim; ++i) {
        std::string name = "P";
        name += std::to_string(i);
        name += '_';
        name += std::to_string(a);
        names.push_back(std::move(name));
      }
    return {names, [this] { return Vector(resistingForce()); }};
  }
  // Plastic state of every material point (materials that have one:
  // J2Plasticity, DruckerPrager): 6 components (engineering shears) or 1 per point.
  if (what == "plasticStrains" || what == "plasticStrain") return gaussPointResponse(materials_, {"plasticStrain"});
  if (what == "equivalentPlasticStrains" || what == "equivalentPlasticStrain")
    return gaussPointResponse(materials_, {"equivalentPlasticStrain"});
  if ((what == "material" || what == "integrPoint") && args.size() >= 2) {
    int point = 0;
    if (!parseIndex(args[1], point) || point < 1 || point > materialPoints()) return {};
    return materials_[point - 1]->setResponse(std::vector<std::string>(args.begin() + 2, args.end()));
  }
  return {};
}

template <int Dim, class C>
void SolidElement<Dim, C>::materialsChanged() {
  constantTangentValid_ = false;
}

template <int Dim, class C>
bool SolidElement<Dim, C>::setParameter(const std::vector<std::string>& args, double value) {
  bool accepted = false;
  refreshMaterials();
  for (auto& m : materials_) accepted = m->setParameter(args, value) || accepted;
  if (accepted) materialsChanged();
  return accepted;
}

template <int Dim, class C>
void SolidElement<Dim, C>::updateMaterialStage(int materialTag, int stage) {
  bool any = false;
  refreshMaterials();
  for (auto& m : materials_)
    if (m->tag() == materialTag) {
      m->updateStage(stage);
      any = true;
    }
  if (any) materialsChanged();
}

template <int Dim, class C>
void SolidElement<Dim, C>::initialStateAnalysis(bool on) {
  refreshMaterials();
  for (auto& m : materials_) m->initialStateAnalysis(on);
  materialsChanged();
}

template <int Dim, class C>
void SolidElement<Dim, C>::print(std::ostream& os) const {
  os << "Element " << tag() << " type " << className() << " nodes";
  for (int t : nodeTags()) os << ' ' << t;
  if (Dim == 2) os << " thick " << thickness_;
  os << " material " << materials_[0]->tag() << " (" << materials_[0]->className() << ", " << kind_
     << ") body force " << bodyForce_.transpose() << '\n';
}

template class SolidElement<2>;
template class SolidElement<3>;
template class SolidElement<2, SimplexCell<2>>;
template class SolidElement<3, SimplexCell<3>>;

namespace solidargs {

template <std::size_t N>
std::array<int, N> nodeTags(CommandArgs& args) {
  std::array<int, N> tags{};
  for (std::size_t a = 0; a < N; ++a) {
    const std::string what = "node" + std::to_string(a + 1);
    tags[a] = args.nextInt(what.c_str());
  }
  return tags;
}
template std::array<int, 3> nodeTags<3>(CommandArgs&);
template std::array<int, 4> nodeTags<4>(CommandArgs&);
template std::array<int, 8> nodeTags<8>(CommandArgs&);

std::vector<double> bodyForce(CommandArgs& args, std::size_t count, const char* names) {
  const std::vector<double> b = args.nextDoubles(names);
  if (!b.empty() && b.size() != count)
    args.fail("expected 0 or " + std::to_string(count) + " body force components (" + names + "), got " +
              std::to_string(b.size()));
  return b;
}

double thickness(CommandArgs& args) {
  const std::size_t at = args.position();
  const double t = args.nextDouble("thick");
  if (!(t > 0.0)) args.failAt(at, "thick", "a positive thickness");
  return t;
}

std::string planeType(CommandArgs& args) {
  const std::size_t at = args.position();
  std::string type = args.nextString("type");
  if (type != "PlaneStrain" && type != "PlaneStress") args.failAt(at, "type", "'PlaneStrain' or 'PlaneStress'");
  return type;
}

void requireSpace(CommandArgs& args, const Domain& domain, int ndm, const std::string& type) {
  if (domain.spaceDim() == ndm) return;
  args.fail(type + " is a " + std::to_string(ndm) + "D element; it needs model('basic', '-ndm', " +
            std::to_string(ndm) + ", '-ndf', " + std::to_string(ndm) + "), this model has -ndm " +
            std::to_string(domain.spaceDim()));
}

std::pair<int, std::array<int, 4>> quadTagAndNodes(CommandArgs& args, const Domain& domain, const std::string& type) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element " + type + " " + std::to_string(tag));
  requireSpace(args, domain, 2, type);
  return {tag, nodeTags<4>(args)};
}

const NDMaterial& material(CommandArgs& args, Domain& domain, const std::string& kind, const std::string& forWhat) {
  const int matTag = args.nextInt("matTag");
  return materialOfTag(args, domain, matTag, kind, forWhat);
}

const NDMaterial& materialOfTag(CommandArgs& args, Domain& domain, int matTag, const std::string& kind,
                                const std::string& forWhat) {
  const NDMaterial& m = domain.ndMaterials.get(matTag, args.context());
  if (!m.clone(kind))
    args.fail("nDMaterial " + std::to_string(matTag) + " (" + m.className() + ") has no " + kind + " form for " +
              forWhat);
  return m;
}

}  // namespace solidargs

}  // namespace beamsolid
