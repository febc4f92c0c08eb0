#pragma once
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Concrete04', tag, fc, ec, ecu, Ec, <fct, et>, <beta=0.1>):
// Popovics (1973) concrete. Compression envelope
//   stress = fc x n / (n - 1 + x^n),  x = strain/ec,  n = Ec/(Ec - fc/ec),
// down to the crushing strain ecu, past which the concrete carries nothing in
// compression for good. Unloading and reloading in compression follow a line
// from the most compressive point to the Karsan-Jirsa plastic strain
// (ec (0.145 r^2 + 0.13 r) for r = strain/ec < 2, ec (0.707 (r - 2) + 0.834)
// beyond, as Concrete01), no steeper than Ec; between that strain and zero the
// crack is open. Tension, measured from zero strain: linear to fct at fct/Ec,
// then fct beta^((strain - fct/Ec)/(et - fct/Ec)) down to et, nothing past et
// (cracked for good); unloading and reloading along the secant to the largest
// tensile point. Without fct there is no tensile strength. Found by running
// OpenSees: a point exactly at the largest compressive or tensile strain is on
// the envelope, exactly ecu or et still carries stress, zero strain before any
// compression is the compression envelope (tangent Ec), and a strain change
// below machine epsilon keeps the committed state.
class Concrete04 : public UniaxialMaterial {
 public:
  Concrete04(int tag, double fc, double ec, double ecu, double Ec, double fct, double et, double beta);

  std::string className() const override { return "Concrete04"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return Ec_; }

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  void print(std::ostream& os) const override;

 private:
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0;
    double minStrain = 0.0, minStress = 0.0;  // most compressive point reached
    double maxStrain = 0.0, maxStress = 0.0;  // largest tensile point reached
  };
  void compressionEnvelope(double strain);
  void tensionEnvelope(double strain);

  double fc_, ec_, ecu_, Ec_, fct_, et_, beta_;
  State trial_, committed_;
};

}  // namespace beamsolid
