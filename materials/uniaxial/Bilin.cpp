#include "materials/uniaxial/Bilin.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {
constexpr double kResidualSlope = 1e-7;  // OpenSees reports this slope on the residual and after failure
constexpr double kFailedStress = 1e-10;
}  // namespace

Bilin::Bilin(int tag, double K0, const SideInput& positive, const SideInput& negative, const DeteriorationInput& det,
             double nFactor)
    : UniaxialMaterial(tag),
      K0_(K0),
      Ke_((1.0 + nFactor) * K0),
      det_(det),
      energyCapacity_(positive.My),
      nFactor_(nFactor),
      input_{positive, negative} {
  const double n = nFactor;
  for (int s = 0; s < 2; ++s) {
    const SideInput& in = input_[s];
    const double sg = sign_[s];
    // The stiffness modification for a spring in series with an elastic member n times
    // stiffer than the spring's share (Ibarra & Krawinkler 2005, appendix B).
    const double as = in.as / (1.0 + n * (1.0 - in.as));
    SideState& st = initial_[s];
    st.My = st.yield = in.My;
    st.as = in.as;
    st.hardening = as * Ke_;
    const double thetaY = in.My / Ke_;
    const double thetaC = thetaY + sg * in.thetaP;
    const double Mc = in.My + st.hardening * sg * in.thetaP;
    const double ac = -std::fabs(Mc) / (in.thetaPc * K0);
    st.ac = ac;
    st.capSlope = ac / (1.0 + n * (1.0 - ac)) * Ke_;
    st.capIntercept = Mc - st.capSlope * thetaC;
    residual_[s] = sg * in.res * std::fabs(in.My);
    st.residual = residual_[s];
    thetaU_[s] = in.thetaU;
    D_[s] = in.D;
  }
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> Bilin::clone() const { return std::make_unique<Bilin>(*this); }

void Bilin::revertToStart() {
  committed_ = State{};
  committed_.tangent = Ke_;
  committed_.K = Ke_;
  committed_.side = initial_;
  trial_ = committed_;
}

Bilin::Bound Bilin::bound(const SideState& s, int side, double strain) const {
  const double sg = sign_[side];
  const double hardening = s.yield + s.hardening * (strain - s.yield / Ke_);
  const double capping = s.capIntercept + s.capSlope * strain;
  Bound b = sg * hardening <= sg * capping ? Bound{hardening, s.hardening, kHardening}
                                            : Bound{capping, s.capSlope, kCapping};
  if (sg * b.stress < sg * s.residual) b = Bound{s.residual, kResidualSlope, kResidual};
  return b;
}

double Bilin::beta(double energy, double capacity, double c) const {
  const double left = capacity;
  // Past the energy capacity OpenSees' response is erratic; here the mode is exhausted.
  if (!(left > 0.0)) return 1.0;
  // An elastic excursion after yielding can end with a little less work than it started
  // with: OpenSees then strengthens by the (negative) beta; with c != 1 its power is not
  // defined and the mode is left alone here.
  if (energy < 0.0) return c == 1.0 ? energy / left : 0.0;
  if (!(left > energy)) return 1.0;
  return std::pow(energy / left, c);
}

std::array<Bilin::Corner, 3> Bilin::backbone(int side) const {
  const SideState& s = initial_[side];
  const double sg = sign_[side];
  const double thetaY = s.My / Ke_;
  const double thetaC = thetaY + sg * input_[side].thetaP;
  const double Mc = s.My + s.hardening * (thetaC - thetaY);
  const double thetaR = (residual_[side] - s.capIntercept) / s.capSlope;
  return {Corner{thetaY, s.My}, Corner{thetaC, Mc}, Corner{thetaR, residual_[side]}};
}

void Bilin::setTrialStrain(double strain, double) {
  const State& c = committed_;
  trial_ = c;
  const double step = strain - c.strain;
  // A change below machine epsilon is no change (as OpenSees, found by running it).
  if (std::fabs(step) < std::numeric_limits<double>::epsilon()) return;
  State& t = trial_;
  t.strain = strain;
  const int dir = step > 0.0 ? 1 : -1;
  const int side = step > 0.0 ? 0 : 1;

  // Beyond theta_u the spring carries (next to) nothing; back inside, it goes on from there.
  if (strain >= thetaU_[0] || strain <= -thetaU_[1]) {
    t.stress = dir * kFailedStress;
    t.tangent = kResidualSlope;
    t.direction = dir;
    return;
  }

  // Unloading stiffness deterioration at a reversal, from the energy of the excursion so far
  // less the elastic energy that unloading gives back.
  if (c.direction != 0 && dir != c.direction && det_.lambdaK > 0.0 && c.loadedOnBound) {
    const double energy = c.work - c.workAtCrossing - c.stress * c.stress / (2.0 * c.K);
    const double b = beta(energy, 2.0 * det_.lambdaK * energyCapacity_ - c.workAtCrossing - energy, det_.cK);
    // With nFactor the loss applies to the member and reaches the spring scaled (as for as).
    t.stiffnessRatio = c.stiffnessRatio * (1.0 - b);
    t.K = Ke_ * t.stiffnessRatio / (1.0 + nFactor_ * (1.0 - t.stiffnessRatio));
  }
  // The elastic line starts at the last reversal (the origin before any): OpenSees evaluates
  // it from there, not step by step (visible in round-off at the corners).
  if (c.direction != 0 && dir != c.direction) {
    t.loadedOnBound = false;
    t.refStrain = c.strain;
    t.refStress = c.stress;
  }
  const double K = t.K;
  const double predictor = t.refStress + K * (strain - t.refStrain);
  const bool crossing = c.stress * predictor < 0.0;
  SideState& s = t.side[side];
  if (crossing) {
    // The excursion ends: its energy deteriorates the side being entered.
    const double work = c.work + 0.5 * (c.stress + predictor) * step;
    const double energy = work - c.workAtCrossing;
    // Only an excursion that reached a bound deteriorates anything (OpenSees: elastic
    // cycles leave the model as it was).
    t.yielded = false;
    if (c.yieldedOnce && det_.lambdaS > 0.0) {
      const double b = beta(energy, det_.lambdaS * energyCapacity_ - work, det_.cS);
      s.My *= 1.0 - D_[side] * b;
      s.as *= 1.0 - D_[side] * b;
      s.hardening = s.as / (1.0 + nFactor_ * (1.0 - s.as)) * Ke_;
    }
    if (c.yieldedOnce && det_.lambdaC > 0.0) {
      const double b = beta(energy, det_.lambdaC * energyCapacity_ - work, det_.cC);
      s.capFactor *= 1.0 - D_[side] * b;
    }
    if (c.yieldedOnce && (det_.lambdaS > 0.0 || det_.lambdaC > 0.0)) {
      // The post-capping line as OpenSees rebuilds it (found by running it): the original
      // line moved towards the origin (intercept times the product of the (1 - D beta_C)),
      // then turned about its meeting point with the current hardening line to the slope
      // of the original one scaled with My - Res*|My0|.
      const SideState& o = initial_[side];
      const double movedIntercept = o.capIntercept * s.capFactor;
      const double drop = o.My - residual_[side];
      if (drop != 0.0) {
        s.ac = o.ac * (s.My - residual_[side]) / drop;
        s.capSlope = s.ac / (1.0 + nFactor_ * (1.0 - s.ac)) * Ke_;
      }
      const double hardeningIntercept = s.My - s.hardening * s.My / Ke_;
      const double pivot = (movedIntercept - hardeningIntercept) / (s.hardening - o.capSlope);
      s.capIntercept = movedIntercept + (o.capSlope - s.capSlope) * pivot;
      // Where the post-capping line now meets the elastic line before the yield point, that
      // meeting point becomes the yield point (the hardening line moves with it; My itself,
      // which scales the post-capping slope, does not).
      const double meet = s.capIntercept / (Ke_ - s.capSlope);
      const bool cut = sign_[side] * meet < sign_[side] * s.My / Ke_;
      s.yield = cut ? Ke_ * meet : s.My;
      // The residual follows a cut yield point (Res times it), not My's deterioration.
      s.residual = cut ? input_[side].res * s.yield : residual_[side];
    }
  }

  const double sg = sign_[side];
  Bound b = bound(s, side, strain);
  if (sg * predictor > sg * b.stress) {
    if (crossing) {
      // Where the zero-stress point lies beyond the origin and the unloading line meets the
      // hardening line where that is the bound, OpenSees stops at the meeting point.
      const double zeroStress = c.strain - c.stress / K;
      if (sg * zeroStress < 0.0) {
        const double intercept = s.yield - s.hardening * s.yield / Ke_;
        const double x = (intercept - c.stress + K * c.strain) / (K - s.hardening);
        if (std::isfinite(x) && sg * (x - c.strain) >= 0.0 && sg * (x - strain) <= 0.0) {
          const Bound at = bound(s, side, x);
          if (at.branch == kHardening) b = at;
        }
      }
    }
    // The step that enters the residual gives (Res times the current yield point) + 1e-7 theta,
    // the steps on it Res*|My0| (as OpenSees).
    if (b.branch == kResidual)
      b.stress = s.lastBound != kResidual ? s.residual + kResidualSlope * strain : residual_[side];
    t.stress = b.stress;
    t.tangent = b.slope;
    s.lastBound = b.branch;
    t.yielded = t.yieldedOnce = t.loadedOnBound = true;
  } else {
    t.stress = predictor;
    t.tangent = K;
    if (crossing) {
      const double thetaY = s.yield / Ke_;
      const bool insideElasticRange = sg * strain >= 0.0 && sg * (strain - thetaY) <= 0.0;
      if (!insideElasticRange || (c.yieldedOnce && det_.lambdaS > 0.0))
        t.tangent = sg * (s.extreme - thetaY) <= 0.0 ? Ke_ : bound(s, side, s.extreme).slope;
    }
  }
  t.work = c.work + 0.5 * (c.stress + t.stress) * step;
  if (crossing && c.yieldedOnce) t.workAtCrossing = t.work;
  t.direction = dir;
  SideState& reached = t.side[strain > 0.0 ? 0 : 1];
  if (std::fabs(strain) > std::fabs(reached.extreme)) reached.extreme = strain;
}

void Bilin::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Bilin K0 " << K0_ << " nFactor " << nFactor_ << " My+ "
     << input_[0].My << " My- " << input_[1].My << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildBilin(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Bilin " + std::to_string(tag));
  const double K0 = args.nextDouble("K0");
  Bilin::SideInput pos{}, neg{};
  pos.as = args.nextDouble("as_Plus");
  neg.as = args.nextDouble("as_Neg");
  pos.My = args.nextDouble("My_Plus");
  neg.My = args.nextDouble("My_Neg");
  Bilin::DeteriorationInput d{};
  d.lambdaS = args.nextDouble("Lamda_S");
  d.lambdaC = args.nextDouble("Lamda_C");
  d.lambdaA = args.nextDouble("Lamda_A");
  d.lambdaK = args.nextDouble("Lamda_K");
  d.cS = args.nextDouble("c_S");
  d.cC = args.nextDouble("c_C");
  d.cA = args.nextDouble("c_A");
  d.cK = args.nextDouble("c_K");
  pos.thetaP = args.nextDouble("theta_p_Plus");
  neg.thetaP = args.nextDouble("theta_p_Neg");
  pos.thetaPc = args.nextDouble("theta_pc_Plus");
  neg.thetaPc = args.nextDouble("theta_pc_Neg");
  pos.res = args.nextDouble("Res_Pos");
  neg.res = args.nextDouble("Res_Neg");
  pos.thetaU = args.nextDouble("theta_u_Plus");
  neg.thetaU = args.nextDouble("theta_u_Neg");
  pos.D = args.nextDouble("D_Plus");
  neg.D = args.nextDouble("D_Neg");
  double nFactor = 0.0;
  if (!args.done()) nFactor = args.nextDouble("nFactor");
  args.expectEnd();

  auto require = [&](bool ok, const char* name, const char* what, double value) {
    if (!ok || !std::isfinite(value)) args.fail(std::string(name) + " must be " + what + ", got " + std::to_string(value));
  };
  require(K0 > 0.0, "K0", "positive", K0);
  require(pos.My > 0.0, "My_Plus", "positive", pos.My);
  require(neg.My < 0.0, "My_Neg", "negative", neg.My);
  require(pos.as >= 0.0 && pos.as < 1.0, "as_Plus", "in [0, 1)", pos.as);
  require(neg.as >= 0.0 && neg.as < 1.0, "as_Neg", "in [0, 1)", neg.as);
  const double lambdas[4] = {d.lambdaS, d.lambdaC, d.lambdaA, d.lambdaK};
  const char* lambdaNames[4] = {"Lamda_S", "Lamda_C", "Lamda_A", "Lamda_K"};
  for (int i = 0; i < 4; ++i) require(lambdas[i] >= 0.0, lambdaNames[i], "zero or positive", lambdas[i]);
  const double cs[4] = {d.cS, d.cC, d.cA, d.cK};
  const char* cNames[4] = {"c_S", "c_C", "c_A", "c_K"};
  for (int i = 0; i < 4; ++i) require(cs[i] > 0.0, cNames[i], "positive", cs[i]);
  require(pos.thetaP >= 0.0, "theta_p_Plus", "zero or positive", pos.thetaP);
  require(neg.thetaP >= 0.0, "theta_p_Neg", "zero or positive (a magnitude)", neg.thetaP);
  require(pos.thetaPc > 0.0, "theta_pc_Plus", "positive", pos.thetaPc);
  require(neg.thetaPc > 0.0, "theta_pc_Neg", "positive (a magnitude)", neg.thetaPc);
  require(pos.res >= 0.0 && pos.res <= 1.0, "Res_Pos", "in [0, 1]", pos.res);
  require(neg.res >= 0.0 && neg.res <= 1.0, "Res_Neg", "in [0, 1] (a magnitude)", neg.res);
  require(pos.thetaU > 0.0, "theta_u_Plus", "positive", pos.thetaU);
  require(neg.thetaU > 0.0, "theta_u_Neg", "positive (a magnitude)", neg.thetaU);
  require(pos.D > 0.0 && pos.D <= 1.0, "D_Plus", "in (0, 1]", pos.D);
  require(neg.D > 0.0 && neg.D <= 1.0, "D_Neg", "in (0, 1]", neg.D);
  require(nFactor >= 0.0, "nFactor", "zero or positive", nFactor);
  return std::make_unique<Bilin>(tag, K0, pos, neg, d, nFactor);
}

void registerBilin(Registry& r) { r.uniaxialMaterials.add("Bilin", &buildBilin); }

}  // namespace

BEAMSOLID_REGISTER(registerBilin);

}  // namespace beamsolid
