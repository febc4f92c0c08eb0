#pragma once
#include "materials/uniaxial/ModIMKPeakOriented.h"

namespace beamsolid {

// uniaxialMaterial('ModIMKPinching', tag, K0, as_Plus, as_Neg, My_Plus, My_Neg, FprPos, FprNeg,
//                  A_pinch, Lamda_S, Lamda_C, Lamda_A, Lamda_K, c_S, c_C, c_A, c_K, theta_p_Plus,
//                  theta_p_Neg, theta_pc_Plus, theta_pc_Neg, Res_Pos, Res_Neg, theta_u_Plus,
//                  theta_u_Neg, D_Plus, D_Neg):
// the modified Ibarra-Medina-Krawinkler deterioration model with pinched hysteresis (Ibarra,
// Medina & Krawinkler 2005): ModIMKPeakOriented's backbone, unloading and deterioration, with
// reloading in two parts (found by driving OpenSeesPy 3.7.1 as a black box). From zero stress
// at z, reloading aims at (theta_peak, Fpr * F_peak) until the break strain
// A_pinch * (theta_peak - F_peak/K) (A_pinch times where unloading from the peak with the
// current K would reach zero stress), then along the line from there to the peak; reloading
// that starts beyond the break strain aims straight at the peak. No turning-point rule.
class ModIMKPinching : public ModIMKPeakOriented {
 public:
  ModIMKPinching(int tag, double K0, const SideInput& positive, const SideInput& negative,
                 const DeteriorationInput& det, const Pinching& pinching)
      : ModIMKPeakOriented(tag, K0, positive, negative, det, pinching) {}

  std::string className() const override { return "ModIMKPinching"; }
  std::unique_ptr<UniaxialMaterial> clone() const override { return std::make_unique<ModIMKPinching>(*this); }
};

}  // namespace beamsolid
