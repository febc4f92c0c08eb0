#include "materials/uniaxial/Concrete04.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

Concrete04::Concrete04(int tag, double fc, double ec, double ecu, double Ec, double fct, double et, double beta)
    : UniaxialMaterial(tag), fc_(fc), ec_(ec), ecu_(ecu), Ec_(Ec), fct_(fct), et_(et), beta_(beta) {
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> Concrete04::clone() const { return std::make_unique<Concrete04>(*this); }

void Concrete04::revertToStart() {
  committed_ = State{};
  committed_.tangent = Ec_;
  trial_ = committed_;
}

void Concrete04::compressionEnvelope(double strain) {
  if (strain < ecu_) {  // crushed
    trial_.stress = 0.0;
    trial_.tangent = 0.0;
    return;
  }
  const double secant = fc_ / ec_;
  const double n = Ec_ / (Ec_ - secant);
  const double x = strain / ec_;
  const double xn = std::pow(x, n);
  const double d = n - 1.0 + xn;
  trial_.stress = fc_ * x * n / d;
  trial_.tangent = secant * n * (n - 1.0) * (1.0 - xn) / (d * d);
}

void Concrete04::tensionEnvelope(double strain) {
  const double crackStrain = fct_ / Ec_;
  if (fct_ > 0.0 && strain <= crackStrain) {
    trial_.stress = Ec_ * strain;
    trial_.tangent = Ec_;
  } else if (fct_ > 0.0 && strain <= et_) {
    const double span = et_ - crackStrain;
    trial_.stress = fct_ * std::pow(beta_, (strain - crackStrain) / span);
    trial_.tangent = trial_.stress * std::log(beta_) / span;
  } else if (strain <= 0.0) {  // no tensile strength: zero strain still starts elastic
    trial_.stress = 0.0;
    trial_.tangent = Ec_;
  } else {
    trial_.stress = 0.0;
    trial_.tangent = 0.0;
  }
}

void Concrete04::setTrialStrain(double strain, double) {
  const State& c = committed_;
  trial_ = c;
  if (std::fabs(strain - c.strain) < std::numeric_limits<double>::epsilon()) return;
  trial_.strain = strain;

  if (strain <= c.minStrain) {
    compressionEnvelope(strain);
    trial_.minStrain = strain;
    trial_.minStress = trial_.stress;
    return;
  }
  if (strain >= 0.0) {
    if (strain < c.maxStrain) {
      const double slope = c.maxStress / c.maxStrain;
      trial_.stress = slope * strain;
      trial_.tangent = slope;
    } else {
      tensionEnvelope(strain);
      trial_.maxStrain = strain;
      trial_.maxStress = trial_.stress;
    }
    return;
  }
  // Unloading or reloading in compression.
  const double r = c.minStrain / ec_;
  const double plasticStrain = ec_ * (r < 2.0 ? (0.145 * r + 0.13) * r : 0.707 * (r - 2.0) + 0.834);
  const double slope = std::min(Ec_, c.minStress / (c.minStrain - plasticStrain));
  const double stress = c.minStress + slope * (strain - c.minStrain);
  if (stress < 0.0) {
    trial_.stress = stress;
    trial_.tangent = slope;
  } else {  // open crack
    trial_.stress = 0.0;
    trial_.tangent = 0.0;
  }
}

void Concrete04::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Concrete04 fc " << fc_ << " ec " << ec_ << " ecu " << ecu_ << " Ec "
     << Ec_ << " fct " << fct_ << " et " << et_ << " beta " << beta_ << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildConcrete04(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Concrete04 " + std::to_string(tag));
  // Compression is negative; positive input means compression too, as OpenSees.
  const double fc = -std::fabs(args.nextDouble("fc"));
  const double ec = -std::fabs(args.nextDouble("ec"));
  const double ecu = -std::fabs(args.nextDouble("ecu"));
  const double Ec = args.nextDouble("Ec");
  double fct = 0.0, et = 0.0, beta = 0.1;
  if (!args.done()) {
    fct = args.nextDouble("fct");
    et = args.nextDouble("et");
    if (!args.done()) beta = args.nextDouble("beta");
  }
  args.expectEnd();
  if (!(fc < 0.0)) args.fail("fc must be nonzero (compressive strength)");
  if (!(ec < 0.0)) args.fail("ec must be nonzero (strain at the compressive strength)");
  if (!(ecu < 0.0)) args.fail("ecu must be nonzero (crushing strain)");
  if (!(Ec > fc / ec))
    args.fail("Ec must exceed the secant modulus fc/ec = " + std::to_string(fc / ec) + " (Popovics' n), got " +
              std::to_string(Ec));
  // A negative tensile strength means none, as OpenSees (which warns).
  fct = std::max(fct, 0.0);
  if (fct > 0.0 && !(et > fct / Ec))
    args.fail("et must exceed the cracking strain fct/Ec = " + std::to_string(fct / Ec) + ", got " +
              std::to_string(et));
  if (fct > 0.0 && !(beta > 0.0)) args.fail("beta must be positive, got " + std::to_string(beta));
  return std::make_unique<Concrete04>(tag, fc, ec, ecu, Ec, fct, et, beta);
}

void registerConcrete04(Registry& r) { r.uniaxialMaterials.add("Concrete04", &buildConcrete04); }

}  // namespace

BEAMSOLID_REGISTER(registerConcrete04);

}  // namespace beamsolid
