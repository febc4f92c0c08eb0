#include "materials/uniaxial/Steel02.h"

#include <algorithm>
#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

Steel02::Steel02(int tag, const Parameters& p)
    : UniaxialMaterial(tag), p_(p), yieldStrain_(p.fy / p.E0), initialStrain_(p.sigInit / p.E0) {
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> Steel02::clone() const { return std::make_unique<Steel02>(*this); }

void Steel02::revertToStart() {
  committed_ = State{};
  committed_.strain = initialStrain_;
  committed_.stress = p_.sigInit;
  committed_.tangent = p_.E0;
  // The plastic excursions are measured from the virgin yield strains.
  committed_.maxStrain = yieldStrain_;
  committed_.minStrain = -yieldStrain_;
  trial_ = committed_;
}

double Steel02::curvature() const {
  const double xi = trial_.excursion;
  return p_.R0 * (1.0 - p_.cR1 * xi / (p_.cR2 + xi));
}

// A new branch from the committed point towards `direction`.
void Steel02::startBranch(State& s, int direction) const {
  const State& c = committed_;
  s.direction = direction;
  if (c.direction == 0) {
    // Virgin loading: from the origin to the initial yield point.
    s.reversalStrain = s.reversalStress = 0.0;
    s.asymptoteStrain = direction * yieldStrain_;
    s.asymptoteStress = direction * p_.fy;
    s.excursion = 0.0;
    return;
  }
  s.reversalStrain = c.strain;
  s.reversalStress = c.stress;
  const double range = c.maxStrain - c.minStrain;
  const double a = direction > 0 ? p_.a3 : p_.a1;
  const double aStrain = direction > 0 ? p_.a4 : p_.a2;
  const double growth = a > 0.0 ? a * std::pow(range / (2.0 * aStrain * yieldStrain_), 0.8) : 0.0;
  // Asymptote b*E0*e + offset meets the elastic line sR + E0*(e - eR).
  const double offset = direction * (1.0 - p_.b) * p_.fy * (1.0 + growth);
  const double hardening = p_.b * p_.E0;
  s.asymptoteStrain = (offset - c.stress + p_.E0 * c.strain) / (p_.E0 - hardening);
  s.asymptoteStress = hardening * s.asymptoteStrain + offset;
  const double extreme = direction > 0 ? c.maxStrain : c.minStrain;
  s.excursion = std::abs(extreme - s.asymptoteStrain) / yieldStrain_;
}

void Steel02::setTrialStrain(double strain, double) {
  const State& c = committed_;
  trial_ = c;
  trial_.strain = strain + initialStrain_;
  const double step = trial_.strain - c.strain;
  if (step == 0.0) return;

  const int direction = step > 0.0 ? 1 : -1;
  if (direction != c.direction) startBranch(trial_, direction);

  const double strainSpan = trial_.asymptoteStrain - trial_.reversalStrain;
  const double stressSpan = trial_.asymptoteStress - trial_.reversalStress;
  const double R = curvature();
  const double x = (trial_.strain - trial_.reversalStrain) / strainSpan;
  const double base = 1.0 + std::pow(std::abs(x), R);
  const double root = std::pow(base, 1.0 / R);
  const double y = p_.b * x + (1.0 - p_.b) * x / root;
  trial_.stress = trial_.reversalStress + y * stressSpan;
  // d y/d x = b + (1-b) / base^(1 + 1/R)
  trial_.tangent = (p_.b + (1.0 - p_.b) / (root * base)) * stressSpan / strainSpan;

  trial_.maxStrain = std::max(trial_.maxStrain, trial_.strain);
  trial_.minStrain = std::min(trial_.minStrain, trial_.strain);
}

void Steel02::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Steel02 Fy " << p_.fy << " E0 " << p_.E0 << " b " << p_.b << " R0 "
     << p_.R0 << " cR1 " << p_.cR1 << " cR2 " << p_.cR2 << " a1 " << p_.a1 << " a2 " << p_.a2 << " a3 " << p_.a3
     << " a4 " << p_.a4 << " sigInit " << p_.sigInit << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildSteel02(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Steel02 " + std::to_string(tag));
  Steel02::Parameters p;
  p.fy = args.nextDouble("Fy");
  p.E0 = args.nextDouble("E0");
  p.b = args.nextDouble("b");
  // The optional groups come whole: <R0 cR1 cR2> <a1 a2 a3 a4> <sigInit>.
  const std::size_t optional = args.remaining();
  if (optional != 0 && optional != 3 && optional != 7 && optional != 8)
    args.fail("expected Fy E0 b followed by nothing, <R0 cR1 cR2>, <R0 cR1 cR2 a1 a2 a3 a4> or "
              "<R0 cR1 cR2 a1 a2 a3 a4 sigInit>; got " +
              std::to_string(optional) + " optional values");
  if (optional >= 3) {
    p.R0 = args.nextDouble("R0");
    p.cR1 = args.nextDouble("cR1");
    p.cR2 = args.nextDouble("cR2");
  }
  if (optional >= 7) {
    p.a1 = args.nextDouble("a1");
    p.a2 = args.nextDouble("a2");
    p.a3 = args.nextDouble("a3");
    p.a4 = args.nextDouble("a4");
  }
  if (optional == 8) p.sigInit = args.nextDouble("sigInit");
  args.expectEnd();
  if (!(p.fy > 0.0)) args.fail("Fy must be positive, got " + std::to_string(p.fy));
  if (!(p.E0 > 0.0)) args.fail("E0 must be positive, got " + std::to_string(p.E0));
  if (!(p.b > -1.0 && p.b < 1.0))
    args.fail("b must lie in (-1, 1) (post-yield tangent b*E0), got " + std::to_string(p.b));
  if (!(p.R0 > 0.0)) args.fail("R0 must be positive, got " + std::to_string(p.R0));
  if (!(p.cR1 >= 0.0 && p.cR1 < 1.0)) args.fail("cR1 must lie in [0, 1) so that R stays positive, got " + std::to_string(p.cR1));
  if (!(p.cR2 > 0.0)) args.fail("cR2 must be positive, got " + std::to_string(p.cR2));
  if (!(p.a1 >= 0.0 && p.a3 >= 0.0)) args.fail("a1 and a3 must not be negative");
  if (!(p.a2 > 0.0 && p.a4 > 0.0)) args.fail("a2 and a4 must be positive (strains in units of Fy/E0)");
  return std::make_unique<Steel02>(tag, p);
}

void registerSteel02(Registry& r) { r.uniaxialMaterials.add("Steel02", &buildSteel02); }

}  // namespace

BEAMSOLID_REGISTER(registerSteel02);

}  // namespace beamsolid
