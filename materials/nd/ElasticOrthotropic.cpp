#include "materials/nd/ElasticOrthotropic.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "materials/nd/PlaneFromThreeDimensional.h"

namespace beamsolid {

ElasticOrthotropic::ElasticOrthotropic(int tag, const Constants& c) : NDMaterial(tag), c_(c) {
  Eigen::Matrix3d S;
  S << 1.0 / c.Ex, -c.nuXY / c.Ex, -c.nuZX / c.Ez,
      -c.nuXY / c.Ex, 1.0 / c.Ey, -c.nuYZ / c.Ey,
      -c.nuZX / c.Ez, -c.nuYZ / c.Ey, 1.0 / c.Ez;
  const Eigen::LLT<Eigen::Matrix3d> llt(S);
  if (llt.info() != Eigen::Success)
    throw OpenSeesError("nDMaterial ElasticOrthotropic " + std::to_string(tag) +
                        ": the Poisson's ratios give a compliance that is not positive definite (an unstable solid)");
  D_.topLeftCorner<3, 3>() = llt.solve(Eigen::Matrix3d::Identity());
  D_(3, 3) = c.Gxy;
  D_(4, 4) = c.Gyz;
  D_(5, 5) = c.Gzx;
}

std::unique_ptr<NDMaterial> ElasticOrthotropic::clone(const std::string& kind) const {
  if (kind == "ThreeDimensional") return std::make_unique<ElasticOrthotropic>(*this);
  if (kind == "PlaneStrain" || kind == "PlaneStress")
    return std::make_unique<PlaneFromThreeDimensional>(
        std::make_unique<ElasticOrthotropic>(*this),
        kind == "PlaneStrain" ? PlaneFromThreeDimensional::Plane::Strain : PlaneFromThreeDimensional::Plane::Stress);
  return nullptr;
}

void ElasticOrthotropic::setTrialStrain(const Eigen::Ref<const Vector>& strain) {
  if (strain.size() != 6)
    throw OpenSeesError("nDMaterial ElasticOrthotropic " + std::to_string(tag()) +
                        ": expected a strain vector of size 6, got " + std::to_string(strain.size()));
  trialStrain_ = strain;
  trialStress_.noalias() = D_ * trialStrain_;
}

void ElasticOrthotropic::revertToLastCommit() {
  trialStrain_ = committedStrain_;
  trialStress_.noalias() = D_ * trialStrain_;
}

void ElasticOrthotropic::revertToStart() {
  trialStrain_.setZero();
  committedStrain_.setZero();
  trialStress_.setZero();
}

void ElasticOrthotropic::print(std::ostream& os) const {
  os << "NDMaterial " << tag() << " type ElasticOrthotropic Ex " << c_.Ex << " Ey " << c_.Ey << " Ez " << c_.Ez
     << " nuxy " << c_.nuXY << " nuyz " << c_.nuYZ << " nuzx " << c_.nuZX << " Gxy " << c_.Gxy << " Gyz " << c_.Gyz
     << " Gzx " << c_.Gzx << " rho " << c_.rho << '\n';
}

namespace {

std::unique_ptr<NDMaterial> buildElasticOrthotropic(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("nDMaterial ElasticOrthotropic " + std::to_string(tag));
  ElasticOrthotropic::Constants c;
  struct Item {
    double* value;
    const char* name;
    bool positive;
  };
  for (const Item& item : {Item{&c.Ex, "Ex", true}, Item{&c.Ey, "Ey", true}, Item{&c.Ez, "Ez", true},
                           Item{&c.nuXY, "nu_xy", false}, Item{&c.nuYZ, "nu_yz", false}, Item{&c.nuZX, "nu_zx", false},
                           Item{&c.Gxy, "Gxy", true}, Item{&c.Gyz, "Gyz", true}, Item{&c.Gzx, "Gzx", true}}) {
    const std::size_t at = args.position();
    *item.value = args.nextDouble(item.name);
    if (item.positive && !(*item.value > 0.0)) args.failAt(at, item.name, "a positive modulus");
  }
  if (!args.done()) c.rho = args.nextDouble("rho");
  args.expectEnd();
  return std::make_unique<ElasticOrthotropic>(tag, c);
}

void registerElasticOrthotropic(Registry& r) { r.ndMaterials.add("ElasticOrthotropic", &buildElasticOrthotropic); }

}  // namespace

BEAMSOLID_REGISTER(registerElasticOrthotropic);

}  // namespace beamsolid
