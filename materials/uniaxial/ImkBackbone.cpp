#include "materials/uniaxial/ImkBackbone.h"

#include <cmath>

#include "core/CommandArgs.h"

namespace beamsolid {

ImkBackbone::ImkBackbone(double K0, double nFactor, const SideInput& positive, const SideInput& negative)
    : K0_(K0), Ke_((1.0 + nFactor) * K0), nFactor_(nFactor), input_{positive, negative} {
  for (int s = 0; s < 2; ++s) {
    const SideInput& in = input_[s];
    const double sg = sign(s);
    Lines& st = initial_[s];
    st.My = st.yield = in.My;
    st.as = in.as;
    st.hardening = modified(in.as) * Ke_;
    const double thetaY = in.My / Ke_;
    const double thetaC = thetaY + sg * in.thetaP;
    const double Mc = in.My + st.hardening * sg * in.thetaP;
    st.ac = -std::fabs(Mc) / (in.thetaPc * K0);
    st.capSlope = modified(st.ac) * Ke_;
    st.capIntercept = Mc - st.capSlope * thetaC;
    residual_[s] = sg * in.res * std::fabs(in.My);
    st.residual = residual_[s];
  }
}

ImkBackbone::Bound ImkBackbone::bound(const Lines& s, int side, double strain) const {
  const double sg = sign(side);
  const double hardening = s.yield + s.hardening * (strain - s.yield / Ke_);
  const double capping = s.capIntercept + s.capSlope * strain;
  Bound b = sg * hardening <= sg * capping ? Bound{hardening, s.hardening, kHardening}
                                            : Bound{capping, s.capSlope, kCapping};
  if (sg * b.stress < sg * s.residual) b = Bound{s.residual, kResidualSlope, kResidual};
  return b;
}

void ImkBackbone::scaleStrength(Lines& s, double factor) const {
  s.My *= factor;
  s.as *= factor;
  s.hardening = modified(s.as) * Ke_;
}

std::array<ImkBackbone::Corner, 3> ImkBackbone::corners(int side) const {
  const Lines& s = initial_[side];
  const double thetaY = s.My / Ke_;
  const double thetaC = thetaY + sign(side) * input_[side].thetaP;
  const double Mc = s.My + s.hardening * (thetaC - thetaY);
  const double thetaR = (residual_[side] - s.capIntercept) / s.capSlope;
  return {Corner{thetaY, s.My}, Corner{thetaC, Mc}, Corner{thetaR, residual_[side]}};
}

double ImkBackbone::beta(double energy, double capacity, double c) {
  // Past the energy capacity OpenSees' response is erratic; here the mode is exhausted.
  if (!(capacity > 0.0)) return 1.0;
  // An elastic excursion after yielding can end with a little less work than it started
  // with: OpenSees then strengthens by the (negative) beta; with c != 1 its power is not
  // defined and the mode is left alone here.
  if (energy < 0.0) return c == 1.0 ? energy / capacity : 0.0;
  if (!(capacity > energy)) return 1.0;
  return std::pow(energy / capacity, c);
}

ImkArguments readImkArguments(CommandArgs& args, bool pinching) {
  ImkArguments a;
  a.K0 = args.nextDouble("K0");
  a.positive.as = args.nextDouble("as_Plus");
  a.negative.as = args.nextDouble("as_Neg");
  a.positive.My = args.nextDouble("My_Plus");
  a.negative.My = args.nextDouble("My_Neg");
  if (pinching) {
    a.fprPos = args.nextDouble("FprPos");
    a.fprNeg = args.nextDouble("FprNeg");
    a.aPinch = args.nextDouble("A_pinch");
  }
  ImkBackbone::DeteriorationInput& d = a.deterioration;
  d.lambdaS = args.nextDouble("Lamda_S");
  d.lambdaC = args.nextDouble("Lamda_C");
  d.lambdaA = args.nextDouble("Lamda_A");
  d.lambdaK = args.nextDouble("Lamda_K");
  d.cS = args.nextDouble("c_S");
  d.cC = args.nextDouble("c_C");
  d.cA = args.nextDouble("c_A");
  d.cK = args.nextDouble("c_K");
  a.positive.thetaP = args.nextDouble("theta_p_Plus");
  a.negative.thetaP = args.nextDouble("theta_p_Neg");
  a.positive.thetaPc = args.nextDouble("theta_pc_Plus");
  a.negative.thetaPc = args.nextDouble("theta_pc_Neg");
  a.positive.res = args.nextDouble("Res_Pos");
  a.negative.res = args.nextDouble("Res_Neg");
  a.positive.thetaU = args.nextDouble("theta_u_Plus");
  a.negative.thetaU = args.nextDouble("theta_u_Neg");
  a.positive.D = args.nextDouble("D_Plus");
  a.negative.D = args.nextDouble("D_Neg");
  return a;
}

void checkImkArguments(CommandArgs& args, const ImkArguments& a, bool pinching) {
  auto require = [&](bool ok, const char* name, const char* what, double value) {
    if (!ok || !std::isfinite(value))
      args.fail(std::string(name) + " must be " + what + ", got " + std::to_string(value));
  };
  const ImkBackbone::SideInput& pos = a.positive;
  const ImkBackbone::SideInput& neg = a.negative;
  const ImkBackbone::DeteriorationInput& d = a.deterioration;
  require(a.K0 > 0.0, "K0", "positive", a.K0);
  require(pos.My > 0.0, "My_Plus", "positive", pos.My);
  require(neg.My < 0.0, "My_Neg", "negative", neg.My);
  require(pos.as >= 0.0 && pos.as < 1.0, "as_Plus", "in [0, 1)", pos.as);
  require(neg.as >= 0.0 && neg.as < 1.0, "as_Neg", "in [0, 1)", neg.as);
  if (pinching) {
    require(a.fprPos >= 0.0 && a.fprPos <= 1.0, "FprPos", "in [0, 1]", a.fprPos);
    require(a.fprNeg >= 0.0 && a.fprNeg <= 1.0, "FprNeg", "in [0, 1]", a.fprNeg);
    require(a.aPinch >= 0.0 && a.aPinch <= 1.0, "A_pinch", "in [0, 1]", a.aPinch);
  }
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
}

}  // namespace beamsolid
