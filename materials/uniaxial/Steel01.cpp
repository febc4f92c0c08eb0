#include "materials/uniaxial/Steel01.h"

#include <cmath>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

Steel01::Steel01(int tag, double fy, double E0, double b, double a1, double a2, double a3, double a4)
    : UniaxialMaterial(tag), fy_(fy), E0_(E0), b_(b), a1_(a1), a2_(a2), a3_(a3), a4_(a4) {
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> Steel01::clone() const { return std::make_unique<Steel01>(*this); }

void Steel01::revertToStart() {
  sensitivity_.clear();
  committed_ = State{};
  committed_.tangent = E0_;
  trial_ = committed_;
}

double Steel01::growth(double a, double aStrain, double strainRange) const {
  if (a == 0.0 || strainRange <= 0.0) return 0.0;
  return a * std::pow(strainRange / (2.0 * aStrain * fy_ / E0_), 0.8);
}

void Steel01::setTrialStrain(double strain, double) {
  const State& c = committed_;
  trial_ = c;
  const double step = strain - c.strain;
  // A change below machine epsilon is no change (as OpenSees, found by running it): the
  // committed state, strain and tangent stay, so round-off in a fiber's strain cannot pick a
  // branch, nor can such changes add up.
  trial_.unchanged = true;
  if (std::fabs(step) < std::numeric_limits<double>::epsilon()) return;
  trial_.unchanged = false;
  trial_.strain = strain;
  trial_.branch = 0;

  // Elastic predictor from the committed state, clipped to the yield lines.
  const double hardening = b_ * E0_;
  const double upper = hardening * strain + (1.0 - b_) * fy_ * (1.0 + c.tensionGrowth);
  const double lower = hardening * strain - (1.0 - b_) * fy_ * (1.0 + c.compressionGrowth);
  trial_.stress = c.stress + E0_ * step;
  trial_.tangent = E0_;
  if (trial_.stress > upper) {
    trial_.stress = upper;
    trial_.tangent = hardening;
    trial_.branch = 1;
  } else if (trial_.stress < lower) {
    trial_.stress = lower;
    trial_.tangent = hardening;
    trial_.branch = -1;
  }

  // A reversal ends an excursion: its extreme strain is the committed one,
  // and the opposite yield line grows with the strain range covered so far.
  if (step > 0.0) {
    if (c.direction < 0) {
      trial_.minStrain = std::min(c.minStrain, c.strain);
      trial_.tensionGrowth = growth(a3_, a4_, c.maxStrain - trial_.minStrain);
    }
    trial_.direction = 1;
  } else {
    if (c.direction > 0) {
      trial_.maxStrain = std::max(c.maxStrain, c.strain);
      trial_.compressionGrowth = growth(a1_, a2_, trial_.maxStrain - c.minStrain);
    }
    trial_.direction = -1;
  }
}

int Steel01::sensitivityParameter(const std::vector<std::string>& args) {
  if (args.empty()) return 0;
  const std::string& n = args[0];
  if (n == "Fy" || n == "fy") return 1;
  if (n == "E0" || n == "E") return 2;
  if (n == "b") return 3;
  if (n == "a1") return 4;
  if (n == "a2") return 5;
  if (n == "a3") return 6;
  if (n == "a4") return 7;
  return 0;
}

bool Steel01::setParameter(const std::vector<std::string>& args, double value) {
  double* targets[] = {&fy_, &E0_, &b_, &a1_, &a2_, &a3_, &a4_};
  const int id = sensitivityParameter(args);
  if (id == 0) return false;
  *targets[id - 1] = value;
  return true;
}

double Steel01::growthSensitivity(int aId, int aStrainId, double a, double aStrain, double range, double dRange,
                                  int parameterId) const {
  if (range <= 0.0) return 0.0;
  // growth = a X^0.8 with X = range E0 / (2 aStrain Fy).
  const double x = range * E0_ / (2.0 * aStrain * fy_);
  const double dLogX = dRange / range + (parameterId == 2 ? 1.0 / E0_ : 0.0) -
                       (parameterId == aStrainId ? 1.0 / aStrain : 0.0) - (parameterId == 1 ? 1.0 / fy_ : 0.0);
  const double power = std::pow(x, 0.8);
  return (parameterId == aId ? power : 0.0) + a * 0.8 * power * dLogX;
}

// setTrialStrain differentiated with its branches (elastic or on a yield
// line, reversal or not) held.
Steel01::Sensitivity Steel01::trialSensitivity(double dStrain, int gradient, int parameterId) const {
  const Sensitivity dc = gradient < static_cast<int>(sensitivity_.size()) ? sensitivity_[gradient] : Sensitivity{};
  if (trial_.unchanged) return dc;
  const State& c = committed_;
  const double dFy = parameterId == 1 ? 1.0 : 0.0, dE0 = parameterId == 2 ? 1.0 : 0.0;
  const double db = parameterId == 3 ? 1.0 : 0.0;
  Sensitivity d = dc;
  d.strain = dStrain;
  const double strain = trial_.strain;
  if (trial_.branch == 0) {
    d.stress = dc.stress + dE0 * (strain - c.strain) + E0_ * (dStrain - dc.strain);
  } else {
    const double sign = trial_.branch;
    const double g = sign > 0 ? c.tensionGrowth : c.compressionGrowth;
    const double dg = sign > 0 ? dc.tensionGrowth : dc.compressionGrowth;
    d.stress = (db * E0_ + b_ * dE0) * strain + b_ * E0_ * dStrain +
               sign * ((1.0 - b_) * dFy * (1.0 + g) - db * fy_ * (1.0 + g) + (1.0 - b_) * fy_ * dg);
  }
  // The reversal's extreme strain and the growth it sets for the next steps.
  if (trial_.strain > c.strain && c.direction < 0) {
    d.minStrain = c.minStrain <= c.strain ? dc.minStrain : dc.strain;
    d.tensionGrowth = growthSensitivity(6, 7, a3_, a4_, c.maxStrain - trial_.minStrain, dc.maxStrain - d.minStrain,
                                        parameterId);
  } else if (trial_.strain < c.strain && c.direction > 0) {
    d.maxStrain = c.maxStrain >= c.strain ? dc.maxStrain : dc.strain;
    d.compressionGrowth = growthSensitivity(4, 5, a1_, a2_, trial_.maxStrain - c.minStrain, d.maxStrain - dc.minStrain,
                                            parameterId);
  }
  return d;
}

double Steel01::stressSensitivity(int gradient, int parameterId) {
  return trialSensitivity(0.0, gradient, parameterId).stress;
}

void Steel01::commitSensitivity(double strainSensitivity, int gradient, int parameterId, int numGradients) {
  const Sensitivity d = trialSensitivity(strainSensitivity, gradient, parameterId);
  if (static_cast<int>(sensitivity_.size()) < numGradients) sensitivity_.resize(numGradients);
  sensitivity_.at(gradient) = d;
}

void Steel01::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Steel01 Fy " << fy_ << " E0 " << E0_ << " b " << b_ << " a1 " << a1_
     << " a2 " << a2_ << " a3 " << a3_ << " a4 " << a4_ << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildSteel01(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Steel01 " + std::to_string(tag));
  const double fy = args.nextDouble("Fy");
  const double E0 = args.nextDouble("E0");
  const double b = args.nextDouble("b");
  double a1 = 0.0, a2 = 1.0, a3 = 0.0, a4 = 1.0;
  if (!args.done()) {
    if (args.remaining() != 4)
      args.fail("isotropic hardening takes all four of a1, a2, a3, a4, got " + std::to_string(args.remaining()) +
                " values");
    a1 = args.nextDouble("a1");
    a2 = args.nextDouble("a2");
    a3 = args.nextDouble("a3");
    a4 = args.nextDouble("a4");
  }
  args.expectEnd();
  if (!(fy > 0.0)) args.fail("Fy must be positive, got " + std::to_string(fy));
  if (!(E0 > 0.0)) args.fail("E0 must be positive, got " + std::to_string(E0));
  if (!(b > -1.0 && b < 1.0)) args.fail("b must lie in (-1, 1) (post-yield tangent b*E0), got " + std::to_string(b));
  if (!(a1 >= 0.0 && a3 >= 0.0)) args.fail("a1 and a3 must not be negative");
  if (!(a2 > 0.0 && a4 > 0.0)) args.fail("a2 and a4 must be positive (strains in units of Fy/E0)");
  return std::make_unique<Steel01>(tag, fy, E0, b, a1, a2, a3, a4);
}

void registerSteel01(Registry& r) { r.uniaxialMaterials.add("Steel01", &buildSteel01); }

}  // namespace

BEAMSOLID_REGISTER(registerSteel01);

}  // namespace beamsolid
