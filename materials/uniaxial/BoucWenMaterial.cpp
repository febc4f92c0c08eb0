#include "materials/uniaxial/BoucWenMaterial.h"

#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {
double signOf(double x) { return (x > 0.0) - (x < 0.0); }
}  // namespace

BoucWenMaterial::BoucWenMaterial(int tag, const Parameters& p) : UniaxialMaterial(tag), p_(p) { revertToStart(); }

std::unique_ptr<UniaxialMaterial> BoucWenMaterial::clone() const { return std::make_unique<BoucWenMaterial>(*this); }

void BoucWenMaterial::revertToStart() {
  committed_ = State{};
  committed_.tangent = p_.ko;
  trial_ = committed_;
}

void BoucWenMaterial::setTrialStrain(double strain, double) {
  const State& c = committed_;
  const double d = strain - c.strain;
  if (d == 0.0) {
    trial_ = c;
    return;
  }
  const double hk = (1.0 - p_.alpha) * p_.ko;  // stiffness of the hysteretic part
  // Residual of backward Euler in z, with A, nu, eta at the energy of the
  // step's end, and its derivatives in z and in the strain increment d.
  struct Linearization {
    double f, dfdz, dfdd;
  };
  auto linearize = [&](double z) {
    const double e = c.energy + hk * z * d;
    const double A = p_.Ao - p_.deltaA * e, nu = 1.0 + p_.deltaNu * e, eta = 1.0 + p_.deltaEta * e;
    const double psi = p_.gamma + p_.beta * signOf(d * z);
    const double zn = std::pow(std::fabs(z), p_.n);
    const double num = A - zn * nu * psi;
    const double dzn = z == 0.0 ? 0.0 : p_.n * std::pow(std::fabs(z), p_.n - 1.0) * signOf(z);
    const double deDz = hk * d, deDd = hk * z;
    const double dnumDz = -p_.deltaA * deDz - dzn * nu * psi - zn * p_.deltaNu * deDz * psi;
    const double dnumDd = -p_.deltaA * deDd - zn * p_.deltaNu * deDd * psi;
    Linearization l;
    l.f = z - c.z - d * num / eta;
    l.dfdz = 1.0 - d * (dnumDz * eta - num * p_.deltaEta * deDz) / (eta * eta);
    l.dfdd = -num / eta - d * (dnumDd * eta - num * p_.deltaEta * deDd) / (eta * eta);
    return l;
  };
  double z = c.z;
  for (int k = 0; k < p_.maxIterations; ++k) {
    const Linearization l = linearize(z);
    const double dz = -l.f / l.dfdz;
    z += dz;
    if (std::fabs(dz) < p_.tolerance) break;
  }
  const Linearization l = linearize(z);
  trial_.strain = strain;
  trial_.z = z;
  trial_.energy = c.energy + hk * z * d;
  trial_.stress = p_.alpha * p_.ko * strain + hk * z;
  trial_.tangent = p_.alpha * p_.ko + hk * (-l.dfdd / l.dfdz);
}

Response BoucWenMaterial::setResponse(const std::vector<std::string>& args) {
  if (args.size() == 1 && args[0] == "z") return Response::named({"z"}, [this] { return Vector::Constant(1, trial_.z); });
  if (args.size() == 1 && args[0] == "energy")
    return Response::named({"energy"}, [this] { return Vector::Constant(1, trial_.energy); });
  return UniaxialMaterial::setResponse(args);
}

void BoucWenMaterial::print(std::ostream& os) const {
  os << "BoucWen " << tag() << ": alpha " << p_.alpha << ", ko " << p_.ko << ", n " << p_.n << ", gamma " << p_.gamma
     << ", beta " << p_.beta << ", Ao " << p_.Ao << ", deltaA " << p_.deltaA << ", deltaNu " << p_.deltaNu
     << ", deltaEta " << p_.deltaEta << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildBoucWen(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial BoucWen " + std::to_string(tag));
  BoucWenMaterial::Parameters p;
  std::size_t at = args.position();
  p.alpha = args.nextDouble("alpha");
  if (!(p.alpha >= 0.0 && p.alpha <= 1.0)) args.failAt(at, "alpha", "a stiffness ratio in [0, 1]");
  at = args.position();
  p.ko = args.nextDouble("ko");
  if (!(p.ko > 0.0)) args.failAt(at, "ko", "a positive stiffness");
  at = args.position();
  p.n = args.nextDouble("n");
  if (!(p.n > 0.0)) args.failAt(at, "n", "a positive exponent");
  p.gamma = args.nextDouble("gamma");
  p.beta = args.nextDouble("beta");
  p.Ao = args.nextDouble("Ao");
  p.deltaA = args.nextDouble("deltaA");
  p.deltaNu = args.nextDouble("deltaNu");
  p.deltaEta = args.nextDouble("deltaEta");
  if (!args.done()) {
    at = args.position();
    p.tolerance = args.nextDouble("tolerance");
    if (!(p.tolerance > 0.0)) args.failAt(at, "tolerance", "a positive number");
  }
  if (!args.done()) {
    at = args.position();
    p.maxIterations = args.nextInt("maxNumIter");
    if (p.maxIterations < 1) args.failAt(at, "maxNumIter", "an integer >= 1");
  }
  args.expectEnd();
  return std::make_unique<BoucWenMaterial>(tag, p);
}

void registerBoucWen(Registry& r) { r.uniaxialMaterials.add("BoucWen", &buildBoucWen); }

}  // namespace

BEAMSOLID_REGISTER(registerBoucWen);

}  // namespace beamsolid
