#pragma once
#include <array>

#include "materials/uniaxial/ImkBackbone.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Bilin', tag, K0, as_Plus, as_Neg, My_Plus, My_Neg, Lamda_S, Lamda_C, Lamda_A,
//                  Lamda_K, c_S, c_C, c_A, c_K, theta_p_Plus, theta_p_Neg, theta_pc_Plus,
//                  theta_pc_Neg, Res_Pos, Res_Neg, theta_u_Plus, theta_u_Neg, D_Plus, D_Neg, <nFactor>):
// the modified Ibarra-Medina-Krawinkler deterioration model with bilinear hysteresis
// (Ibarra, Medina & Krawinkler 2005; Lignos & Krawinkler 2011). The rules below were found by
// driving OpenSeesPy 3.7.1 as a black box (tests/python/test_uniaxial_oracle.py).
//
// Backbone per side: ImkBackbone (n = nFactor, Ke = (1+n) K0).
// While |theta| >= theta_u the stress is +-1e-10 (sign of the step), tangent 1e-7; back
// inside, the spring goes on from there. The lines are fixed in the plane (kinematic, as
// Steel01): the stress moves along the elastic line (slope K, from the last reversal)
// between the positive bound (min of hardening and capping lines, not below the residual)
// and the negative one.
// Cyclic deterioration (E_t = Lamda*My_Plus, W the work done so far by the trapezoid rule,
// W_c its value at the last zero crossing of the stress); nothing happens before the first
// step that ends on a bound (earlier zero crossings do not even reset W_c):
//  - at a zero crossing of the elastic predictor the excursion's energy E_i = W - W_c (the
//    crossing step's work taken with the predictor; W_c is then reset to W with the final
//    stress) deteriorates the side being entered: My and as (before the n modification) by
//    (1 - D beta_S), the post-capping line's intercept at theta = 0 by the product of the
//    (1 - D beta_C), beta = (E_i/(E_t - W))^c (an elastic excursion can give E_i < 0 and, with
//    c = 1, a small strengthening, as in OpenSees). The post-capping line is then rebuilt: the
//    original line, moved, is turned about its meeting point with the hardening line to the
//    slope ac0 (My - Res|My0|)/(My0 - Res|My0|) (n-modified); where it meets the elastic line
//    through the origin before the yield point, that point becomes the yield point (My itself
//    unchanged) and the residual Res times it.
//  - at a reversal of the strain increment after a step on a bound, K's ratio to Ke (before
//    the n modification) deteriorates by (1 - beta_K), beta_K = (E/(2 Lamda_K My_Plus - W_c -
//    E))^c_K, E = W - W_c - f^2/(2K) at the reversal.
// Lamda = 0 switches a mode off; Lamda_A and c_A are read and ignored (no reloading stiffness
// in a bilinear model).
// OpenSees' quirks reproduced: the step that enters the residual gives the (current) residual
// + 1e-7*theta, the steps on it Res*|My0|; the step on which the stress crosses zero reports as
// tangent K if it ends inside the new side's initial elastic range (0 to theta_y) and strength
// did not deteriorate there, else the slope of the new side's bound at the largest strain
// reached on that side (Ke before it yielded); when such a step reaches the bound with the
// zero-stress point beyond the origin and the elastic line meets the hardening line on the
// bound, the stress stops there.
// Known differences from OpenSees (docs/commands.md, benchmarks/bilin_oracle_histories.py):
// other steps that cross zero stress and reach the other side's bound in one step (steps of
// two yield rotations or more), re-entering the residual (OpenSees gives one step at exactly
// Res*|My0| with slope -1e-7, or keeps Res*|My0| + 1e-7 theta after strength deterioration),
// a deteriorated post-capping line below the residual (OpenSees enters the residual later, or
// fails the spring where the line reaches zero), post-capping deterioration after elastic
// excursions (small differences), c != 1 with an elastic excursion of negative energy after
// yield (OpenSees' power is undefined and its response invalid; here the mode is left alone),
// and the energy exceeding E_t (beta is capped at 1 here).
class Bilin : public UniaxialMaterial {
 public:
  using SideInput = ImkBackbone::SideInput;
  using DeteriorationInput = ImkBackbone::DeteriorationInput;
  Bilin(int tag, double K0, const SideInput& positive, const SideInput& negative, const DeteriorationInput& det,
        double nFactor);

  std::string className() const override { return "Bilin"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return backbone_.Ke(); }

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  void print(std::ostream& os) const override;

  // Backbone corner points of the undeteriorated model (for tests): yield, cap, start of the
  // residual (strain, stress), side 0 positive, 1 negative.
  using Corner = ImkBackbone::Corner;
  std::array<Corner, 3> backbone(int side) const { return backbone_.corners(side); }

 private:
  using Branch = ImkBackbone::Branch;
  using Bound = ImkBackbone::Bound;
  // The deteriorating lines of one side.
  struct SideState : ImkBackbone::Lines {
    double extreme = 0.0;         // largest |strain| reached on this side of zero
    Branch lastBound = ImkBackbone::kElastic;  // the bound branch the last step on it ended on
  };
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0;
    double K = 0.0;                      // unloading stiffness
    double stiffnessRatio = 1.0;         // its loss before the nFactor modification
    double work = 0.0, workAtCrossing = 0.0;
    double refStrain = 0.0, refStress = 0.0;  // start of the current elastic line
    int direction = 0;                   // sign of the last strain increment
    bool yielded = false;                // a step of this excursion ended on a bound
    bool yieldedOnce = false;            // a step ever ended on a bound
    bool loadedOnBound = false;          // a step since the last reversal ended on a bound
    std::array<SideState, 2> side{};
  };

  ImkBackbone backbone_;
  DeteriorationInput det_;
  double energyCapacity_;  // Lamda = 1 times My_Plus
  std::array<SideState, 2> initial_{};
  State trial_, committed_;
};

}  // namespace beamsolid
