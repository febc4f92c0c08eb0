#include "sections/LayeredPlateSection.h"

#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "sections/BeamIntegration.h"

namespace beamsolid {

LayeredPlateSection::LayeredPlateSection(int tag, std::string className, std::vector<Layer> layers,
                                         double shearFactor)
    : PlateSection(tag), className_(std::move(className)), layers_(std::move(layers)),
      shearRoot_(std::sqrt(shearFactor)) {
  integrate(true);
  initialTangent_ = tangent_;
  integrate(false);
}

LayeredPlateSection::LayeredPlateSection(const LayeredPlateSection& other)
    : PlateSection(other.tag()),
      className_(other.className_),
      shearRoot_(other.shearRoot_),
      deformation_(other.deformation_),
      committedDeformation_(other.committedDeformation_),
      force_(other.force_),
      tangent_(other.tangent_),
      initialTangent_(other.initialTangent_) {
  for (const Layer& l : other.layers_) layers_.push_back({l.material->clone("PlateFiber"), l.z, l.weight});
}

std::unique_ptr<PlateSection> LayeredPlateSection::clone() const { return std::make_unique<LayeredPlateSection>(*this); }

LayeredPlateSection::Matrix58 LayeredPlateSection::strainMap(double z) const {
  // Section e = [e11, e22, g12, k11, k22, k12, g13, g23] -> fiber [e11, e22, g12, g23, g31].
  Matrix58 B = Matrix58::Zero();
  for (int i = 0; i < 3; ++i) {
    B(i, i) = 1.0;
    B(i, i + 3) = z;
  }
  B(3, 7) = shearRoot_;
  B(4, 6) = shearRoot_;
  return B;
}

void LayeredPlateSection::integrate(bool initial) {
  force_.setZero();
  tangent_.setZero();
  for (Layer& l : layers_) {
    const Matrix58 B = strainMap(l.z);
    if (!initial) l.material->setTrialStrain(B * deformation_);
    // The fiber's 5 x 5 tangent seen as fixed-size: no heap copy per fiber and iteration.
    const MatrixView view = initial ? l.material->initialTangent() : l.material->tangent();
    const Eigen::Map<const Eigen::Matrix<double, 5, 5>> C(view.data());
    tangent_.noalias() += l.weight * B.transpose() * (C * B);
    if (!initial) force_ += l.weight * B.transpose() * l.material->stress();
  }
}

void LayeredPlateSection::setTrialDeformation(const Vector8& e) {
  deformation_ = e;
  integrate(false);
}

double LayeredPlateSection::areaDensity() const {
  double rhoH = 0.0;
  for (const Layer& l : layers_) rhoH += l.weight * l.material->density();
  return rhoH;
}

void LayeredPlateSection::commitState() {
  for (Layer& l : layers_) l.material->commitState();
  committedDeformation_ = deformation_;
}

void LayeredPlateSection::revertToLastCommit() {
  for (Layer& l : layers_) l.material->revertToLastCommit();
  deformation_ = committedDeformation_;
  integrate(false);
}

void LayeredPlateSection::revertToStart() {
  for (Layer& l : layers_) l.material->revertToStart();
  deformation_.setZero();
  committedDeformation_.setZero();
  integrate(false);
}

void LayeredPlateSection::print(std::ostream& os) const {
  os << "Section " << tag() << " type " << className_ << ", " << layers_.size() << " points through the thickness\n";
}

namespace {

std::unique_ptr<NDMaterial> plateFiber(CommandArgs& args, Domain& domain, int matTag, std::size_t at) {
  const NDMaterial& m = domain.ndMaterials.get(matTag, args.context());
  auto copy = m.clone("PlateFiber");
  if (!copy)
    args.failAt(at, "matTag",
                "a plate fiber material (nDMaterial('PlateFiber', tag, mat3DTag)); nDMaterial " +
                    std::to_string(matTag) + " is " + m.className());
  return copy;
}

std::unique_ptr<BeamSection> buildPlateFiberSection(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("secTag");
  args.setContext("section PlateFiber " + std::to_string(tag));
  if (domain.spaceDim() != 3) args.fail("a plate section is for shells in a 3D model (-ndm 3, -ndf 6)");
  const std::size_t atMat = args.position();
  const int matTag = args.nextInt("matTag");
  const std::size_t atH = args.position();
  const double h = args.nextDouble("h");
  if (!(h > 0.0)) args.failAt(atH, "h", "a positive thickness");
  args.expectEnd();
  auto prototype = plateFiber(args, domain, matTag, atMat);
  std::vector<double> xi, w;
  BeamIntegration::gaussLobatto(5, xi, w);  // on [0, 1]
  std::vector<LayeredPlateSection::Layer> layers;
  for (std::size_t i = 0; i < xi.size(); ++i)
    layers.push_back({prototype->clone("PlateFiber"), (xi[i] - 0.5) * h, w[i] * h});
  return std::make_unique<LayeredPlateSection>(tag, "PlateFiber", std::move(layers), 5.0 / 6.0);
}

std::unique_ptr<BeamSection> buildLayeredShell(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("secTag");
  args.setContext("section LayeredShell " + std::to_string(tag));
  if (domain.spaceDim() != 3) args.fail("a plate section is for shells in a 3D model (-ndm 3, -ndf 6)");
  const std::size_t atN = args.position();
  const int n = args.nextInt("nLayers");
  // OpenSees asks for at least three layers.
  if (n < 3 || n > 10000) args.failAt(atN, "nLayers", "a number of layers in 3..10000");
  struct Given {
    std::unique_ptr<NDMaterial> material;
    double thickness;
  };
  std::vector<Given> given;
  double h = 0.0;
  for (int k = 0; k < n; ++k) {
    const std::size_t atMat = args.position();
    const int matTag = args.nextInt("matTag");
    const std::size_t atT = args.position();
    const double t = args.nextDouble("thickness");
    if (!(t > 0.0)) args.failAt(atT, "thickness", "a positive layer thickness");
    given.push_back({plateFiber(args, domain, matTag, atMat), t});
    h += t;
  }
  args.expectEnd();
  std::vector<LayeredPlateSection::Layer> layers;
  double bottom = -0.5 * h;
  for (Given& g : given) {
    layers.push_back({std::move(g.material), bottom + 0.5 * g.thickness, g.thickness});
    bottom += g.thickness;
  }
  return std::make_unique<LayeredPlateSection>(tag, "LayeredShell", std::move(layers), 1.0);
}

void registerLayeredPlateSections(Registry& r) {
  r.sections.add("PlateFiber", &buildPlateFiberSection);
  r.sections.add("LayeredShell", &buildLayeredShell);
}

}  // namespace

BEAMSOLID_REGISTER(registerLayeredPlateSections);

}  // namespace beamsolid
