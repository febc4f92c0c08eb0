#pragma once
#include <array>
#include <string>

namespace beamsolid {

class CommandArgs;

// The modified Ibarra-Medina-Krawinkler backbone (Ibarra, Medina & Krawinkler 2005; Lignos &
// Krawinkler 2011) shared by Bilin, ModIMKPeakOriented and ModIMKPinching: per side an elastic
// line to theta_y = My/Ke, the hardening line of slope as'*Ke to the cap at theta_y + theta_p
// (moment Mc), the post-capping line of slope ac'*Ke (ac = -Mc/(theta_pc*K0)) down to the
// residual Res*|My|, reported with slope 1e-7. With nFactor n, Ke = (1+n) K0 and any ratio r
// enters as r' = r/(1+n(1-r)) (Ibarra & Krawinkler 2005, appendix B). The lines are fixed in the
// plane; cyclic deterioration moves them (each material applies its own rules).
class ImkBackbone {
 public:
  struct SideInput {
    double as, My, thetaP, thetaPc, res, thetaU, D;  // My signed (negative side negative)
  };
  struct DeteriorationInput {
    double lambdaS, lambdaC, lambdaA, lambdaK, cS, cC, cA, cK;
  };
  enum Branch { kElastic = 0, kHardening, kCapping, kResidual };
  struct Bound {
    double stress, slope;
    Branch branch;
  };
  // The (deteriorating) lines of one side.
  struct Lines {
    double My = 0.0, yield = 0.0;  // My (deteriorated) and the yield point the bound uses
    double residual = 0.0;
    double hardening = 0.0, capIntercept = 0.0, capSlope = 0.0;
    double capFactor = 1.0;     // product of the (1 - D beta_C)
    double as = 0.0, ac = 0.0;  // hardening and post-capping ratios before the nFactor modification
  };
  struct Corner {
    double strain, stress;
  };
  static constexpr double kResidualSlope = 1e-7;  // OpenSees' slope on the residual and after failure
  static constexpr double kFailedStress = 1e-10;

  ImkBackbone(double K0, double nFactor, const SideInput& positive, const SideInput& negative);

  double K0() const { return K0_; }
  double Ke() const { return Ke_; }
  double nFactor() const { return nFactor_; }
  double sign(int side) const { return side == 0 ? 1.0 : -1.0; }
  const SideInput& input(int side) const { return input_[side]; }
  const Lines& initial(int side) const { return initial_[side]; }
  double residual(int side) const { return residual_[side]; }  // Res*|My0| with the side's sign
  // The ratio r' = r/(1+n(1-r)) a spring in series with an n times stiffer member sees.
  double modified(double ratio) const { return ratio / (1.0 + nFactor_ * (1.0 - ratio)); }
  // The outer bound of one side at a strain: the lower of the hardening and post-capping lines,
  // not below the residual.
  Bound bound(const Lines& lines, int side, double strain) const;
  // Scales My and the hardening ratio (basic strength deterioration).
  void scaleStrength(Lines& lines, double factor) const;
  // Corner points of the undeteriorated backbone: yield, cap, start of the residual.
  std::array<Corner, 3> corners(int side) const;
  // beta = (E/(capacity))^c, with what OpenSees does outside the usual range (see the .cpp).
  static double beta(double energy, double capacity, double c);

 private:
  double K0_, Ke_, nFactor_;
  std::array<SideInput, 2> input_;
  std::array<Lines, 2> initial_{};
  std::array<double, 2> residual_{};
};

// The arguments the three commands share, read and checked in the documented order:
// K0, as_Plus, as_Neg, My_Plus, My_Neg, [FprPos, FprNeg, A_pinch,] Lamda_S, Lamda_C, Lamda_A,
// Lamda_K, c_S, c_C, c_A, c_K, theta_p_Plus, theta_p_Neg, theta_pc_Plus, theta_pc_Neg, Res_Pos,
// Res_Neg, theta_u_Plus, theta_u_Neg, D_Plus, D_Neg (the pinching three only with `pinching`).
struct ImkArguments {
  double K0 = 0.0;
  ImkBackbone::SideInput positive{}, negative{};
  ImkBackbone::DeteriorationInput deterioration{};
  double fprPos = 0.0, fprNeg = 0.0, aPinch = 0.0;
};
ImkArguments readImkArguments(CommandArgs& args, bool pinching);
// Fails (naming the argument) on a non-finite value or one outside its range.
void checkImkArguments(CommandArgs& args, const ImkArguments& a, bool pinching);

}  // namespace beamsolid
