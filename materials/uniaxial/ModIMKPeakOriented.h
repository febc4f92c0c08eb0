#pragma once
#include <array>
#include <optional>

#include "materials/uniaxial/ImkBackbone.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('ModIMKPeakOriented', tag, K0, as_Plus, as_Neg, My_Plus, My_Neg, Lamda_S,
//                  Lamda_C, Lamda_A, Lamda_K, c_S, c_C, c_A, c_K, theta_p_Plus, theta_p_Neg,
//                  theta_pc_Plus, theta_pc_Neg, Res_Pos, Res_Neg, theta_u_Plus, theta_u_Neg,
//                  D_Plus, D_Neg):
// the modified Ibarra-Medina-Krawinkler deterioration model with peak-oriented hysteresis
// (Ibarra, Medina & Krawinkler 2005; Lignos & Krawinkler 2011), backbone ImkBackbone (no
// nFactor); with `Pinching` the reloading of ModIMKPinching (ModIMKPinching.h). The rules below
// were found by driving OpenSeesPy 3.7.1 as a black box.
//
// Unloading follows the stiffness K from the last reversal. Where it reaches zero stress
// (strain z), reloading aims from (z, 0) at the peak of the side being entered: the largest
// strain reached there (the yield strain at first) with the stress of the current backbone at
// that strain; beyond the peak it follows the backbone. When the last unloading on that side
// started from a point that lies outside the line from (z, 0) to the peak (an excursion that
// turned back before reaching the peak), reloading aims at that point first, then along the
// line from it to the peak (unless that point's stress is beyond the peak's). Inside a side,
// reloading after a partial unloading follows K back to the reloading line. The stress is
// never outside the backbone.
// Cyclic deterioration (E_t = Lamda*My_Plus, W the work so far, beta = (E/(E_t - W))^c): the
// excursion's energy E = W - W_c (W_c at the last zero crossing, the crossing step's work
// included) deteriorates the side being entered at each zero crossing after the first yield,
// effective from the step after the crossing: My and the hardening ratio by (1 - D beta_S), the
// post-capping line's intercept at theta = 0 (slope kept) by the product of the (1 - D beta_C),
// the peak strain by (1 + beta_A) (no D; where the backbone at the moved peak is stronger than
// where the side last turned back at its largest strain, or than the yield point, reloading
// aims at that point first, 1e-10 beyond it once the side has yielded); at each reversal after the first yield the unloading stiffness by (1 - beta_K),
// beta_K = (E/(2 Lamda_K My_Plus - W_c - E))^c_K, E = W - W_c - f^2/(2K). Lamda = 0 switches a
// mode off. Differences from OpenSees are listed in docs/commands.md.
// On the residual the stress is Res*|My0| + 1e-7 theta (slope 1e-7, as OpenSees). The first
// step beyond theta_u gives +1e-10 on either side (slope 1e-7); from then on the spring
// carries nothing.
class ModIMKPeakOriented : public UniaxialMaterial {
 public:
  using SideInput = ImkBackbone::SideInput;
  using DeteriorationInput = ImkBackbone::DeteriorationInput;
  // ModIMKPinching's reloading: FprPos/FprNeg and A_pinch.
  struct Pinching {
    std::array<double, 2> fpr;
    double aPinch;
  };
  ModIMKPeakOriented(int tag, double K0, const SideInput& positive, const SideInput& negative,
                     const DeteriorationInput& det, std::optional<Pinching> pinching = std::nullopt);

  std::string className() const override { return "ModIMKPeakOriented"; }
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

  using Corner = ImkBackbone::Corner;
  std::array<Corner, 3> backbone(int side) const { return backbone_.corners(side); }

 private:
  struct Point {
    double strain = 0.0, stress = 0.0;
  };
  // The deteriorating lines of one side and its reloading line.
  struct SideState : ImkBackbone::Lines {
    double peak = 0.0;       // the strain reloading aims at: the largest reached (the yield strain at first),
                             // moved out by Lamda_A
    Point maxReached;        // the largest strain reached and its stress (the yield point at first)
    double zero = 0.0;       // where the current reloading line into this side starts
    Point turn;              // the last point this side unloaded from
    bool turned = false;
  };
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0;
    double K = 0.0;               // unloading stiffness
    double stiffnessRatio = 1.0;  // its loss
    double work = 0.0, workAtCrossing = 0.0;
    double refStrain = 0.0, refStress = 0.0;  // start of the current unloading line
    int direction = 0;                        // sign of the last strain increment
    bool yieldedOnce = false;                 // a step ever ended on the backbone
    bool failed = false;                      // beyond theta_u once
    std::array<SideState, 2> side{};
  };
  struct Candidate {
    double stress, slope;
    bool onBound;
  };
  // The backbone as OpenSees reports it (Res*|My0| + 1e-7 theta on the residual).
  ImkBackbone::Bound backboneAt(const SideState& s, int side, double strain) const;
  // The reloading line into a side at a strain (the backbone beyond the peak).
  Candidate reloading(const SideState& s, int side, double strain, double K) const;
  void deteriorate(SideState& s, int side, double energy, double work) const;

  ImkBackbone backbone_;
  DeteriorationInput det_;
  double energyCapacity_;  // Lamda = 1 times My_Plus
  State trial_, committed_;
  std::optional<Pinching> pinching_;
};

}  // namespace beamsolid
