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
  if (std::fabs(step) < std::numeric_limits<double>::epsilon()) return;
  trial_.strain = strain;

  // Elastic predictor from the committed state, clipped to the yield lines.
  const double hardening = b_ * E0_;
  const double upper = hardening * strain + (1.0 - b_) * fy_ * (1.0 + c.tensionGrowth);
  const double lower = hardening * strain - (1.0 - b_) * fy_ * (1.0 + c.compressionGrowth);
  trial_.stress = c.stress + E0_ * step;
  trial_.tangent = E0_;
  if (trial_.stress > upper) {
    trial_.stress = upper;
    trial_.tangent = hardening;
  } else if (trial_.stress < lower) {
    trial_.stress = lower;
    trial_.tangent = hardening;
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
