#pragma once
#include <array>

#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Bilin', tag, K0, as_Plus, as_Neg, My_Plus, My_Neg, Lamda_S, Lamda_C, Lamda_A,
//                  Lamda_K, c_S, c_C, c_A, c_K, theta_p_Plus, theta_p_Neg, theta_pc_Plus,
//                  theta_pc_Neg, Res_Pos, Res_Neg, theta_u_Plus, theta_u_Neg, D_Plus, D_Neg, <nFactor>):
// the modified Ibarra-Medina-Krawinkler deterioration model with bilinear hysteresis
// (Ibarra, Medina & Krawinkler 2005; Lignos & Krawinkler 2011). The rules below were found by
// driving OpenSeesPy 3.7.1 as a black box (tests/python/test_uniaxial_oracle.py).
//
// Backbone per side (n = nFactor, Ke = (1+n) K0, as' = as/(1+n(1-as))): elastic to
// theta_y = My/Ke, the hardening line of slope as'*Ke to the cap at theta_y + theta_p
// (moment Mc), the post-capping line of slope ac'*Ke (ac = -Mc/(theta_pc*K0),
// ac' = ac/(1+n(1-ac))) down to the residual Res*|My|, whose slope is reported as 1e-7; at
// |theta| >= theta_u the spring fails for good (stress +-1e-10 with the sign of the step,
// tangent 1e-7). These lines are fixed in the plane (kinematic, as Steel01): the stress moves
// with the unloading stiffness K between the positive bound (min of hardening and capping lines,
// not below the residual) and the negative one.
// Cyclic deterioration, E_t = Lamda*My_Plus, W the work done so far (trapezoid rule over the
// committed steps), W_c its value at the last zero crossing of the stress:
//  - at each zero crossing of the stress (elastic predictor) the excursion that ends,
//    E_i = W - W_c (W including the crossing step), deteriorates the side being entered:
//    My and the hardening slope by (1 - D*beta_S), the post-capping line's intercept at
//    theta = 0 by (1 - D*beta_C), beta = (E_i/(E_t - W))^c;
//  - at each reversal of the strain increment the unloading stiffness K deteriorates by
//    (1 - beta_K), beta_K = (E/(2*E_t,K - W_c - E))^c_K, E = W - W_c - f^2/(2K) at the reversal.
// Lamda = 0 switches a mode off; Lamda_A and c_A are read and ignored (no reloading stiffness
// in a bilinear model).
// OpenSees' quirks reproduced: the step that enters the residual gives Res*|My| + 1e-7*theta
// (later steps Res*|My|); on the step where the stress crosses zero the tangent is the slope of
// the new side's bound at the largest strain reached on that side (Ke before it yielded), and
// when such a step hits the bound while the zero-stress point lies beyond the origin the stress
// is the bound's value where the unloading line meets it.
// Known differences from OpenSees (docs/commands.md): strength deterioration also changes
// OpenSees' post-capping slope (not reproduced), the energy exceeding E_t, a step that crosses
// zero and lands on the post-capping line (OpenSees fails the spring there), unloading from the
// first residual step, and a one-step 1e-8 difference on some entries to the residual after
// cycling.
class Bilin : public UniaxialMaterial {
 public:
  struct SideInput {
    double as, My, thetaP, thetaPc, res, thetaU, D;  // My signed (negative side negative)
  };
  struct DeteriorationInput {
    double lambdaS, lambdaC, lambdaA, lambdaK, cS, cC, cA, cK;
  };
  Bilin(int tag, double K0, const SideInput& positive, const SideInput& negative, const DeteriorationInput& det,
        double nFactor);

  std::string className() const override { return "Bilin"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return Ke_; }

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  void print(std::ostream& os) const override;

  // Backbone corner points of the undeteriorated model (for tests): yield, cap, start of the
  // residual (strain, stress), side 0 positive, 1 negative.
  struct Corner {
    double strain, stress;
  };
  std::array<Corner, 3> backbone(int side) const;

 private:
  enum Branch { kElastic = 0, kHardening, kCapping, kResidual };
  struct Bound {
    double stress, slope;
    Branch branch;
  };
  // The deteriorating lines of one side.
  struct SideState {
    double My = 0.0, yield = 0.0;  // My (deteriorated) and the yield point the bound uses
    double residual = 0.0;
    double hardening = 0.0, capIntercept = 0.0, capSlope = 0.0;
    double capFactor = 1.0;  // product of the (1 - D beta_C)
    double as = 0.0, ac = 0.0;  // hardening and post-capping ratios before the nFactor modification
    double extreme = 0.0;         // largest |strain| reached on this side of zero
    Branch lastBound = kElastic;  // the bound branch the last step on it ended on
  };
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0;
    double K = 0.0;                      // unloading stiffness
    double stiffnessRatio = 1.0;         // its loss before the nFactor modification
    double work = 0.0, workAtCrossing = 0.0;
    double refStrain = 0.0, refStress = 0.0;  // start of the current elastic line
    int direction = 0;                   // sign of the last strain increment
    std::array<SideState, 2> side{};
  };

  Bound bound(const SideState& s, int side, double strain) const;
  double beta(double energy, double capacity, double c) const;

  double K0_, Ke_;
  DeteriorationInput det_;
  double energyCapacity_;                  // Lamda = 1 times My_Plus
  std::array<double, 2> sign_{1.0, -1.0};
  std::array<double, 2> residual_{}, thetaU_{}, D_{};
  std::array<SideState, 2> initial_{};
  State trial_, committed_;
  double nFactor_;
  std::array<SideInput, 2> input_;
};

}  // namespace beamsolid
