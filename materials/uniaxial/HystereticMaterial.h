#pragma once
#include <array>
#include <vector>

#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Hysteretic', tag, s1p, e1p, s2p, e2p, <s3p, e3p>,
//                  s1n, e1n, s2n, e2n, <s3n, e3n>, pinchX, pinchY,
//                  damage1, damage2, <beta=0>):
// a peak-oriented (Clough type) bilinear/trilinear hysteretic model with
// pinching, damage and degraded unloading stiffness, after OpenSees'
// documentation; the rules below were derived from it and confirmed point
// by point against OpenSeesPy on random cyclic histories.
//
// Envelope: through the origin and the two or three points of each side;
// past the last point the last slope continues if it is positive, else the
// stress stays at the last point's (tangent 1e-9 of the elastic one).
// Strains past the largest ones reached (emax, emin) follow the envelope.
// Unloading: slope E1*mu^-beta of the side being unloaded, with E1 = s1/e1
// and mu = max(|e_max|/|e1|, 1) from the committed extremes.
// Reloading (once past zero stress) heads for the other side's target
// (e_t, envelope(e_t)), e_t the extreme strain reached there (at least e1),
// through the pinch point of stress pinchY*s_t and strain
//   e0 + pinchX*(e_t - (1 - pinchY)*s_t/E_t - e0),
// where e0 is the zero-stress strain of the unloading branch; the stress is
// the smaller in magnitude of this reloading path and an elastic step of
// the target side's unloading stiffness.
// Damage: at each reversal with stress on the side just left, the extreme
// strain of the side ahead grows by the factor
//   1 + damage1*(mu_left - 1) + damage2*E/Eult,
// mu_left the ductility of the side just left, E the dissipated energy
// (work minus the elastic energy at the reversal) and Eult the area under
// both envelopes.
class HystereticMaterial : public UniaxialMaterial {
 public:
  struct Point {
    double strain, stress;
  };
  // `positive` and `negative` hold 2 or 3 points each, `negative` with
  // negative strains and stresses.
  HystereticMaterial(int tag, std::vector<Point> positive, std::vector<Point> negative, double pinchX,
                     double pinchY, double damage1, double damage2, double beta);

  std::string className() const override { return "Hysteretic"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return side_[0].E1; }

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  void print(std::ostream& os) const override;

 private:
  // One side of the envelope, stored mirrored to positive strains and
  // stresses (the negative side negated), so one set of rules serves both
  // directions; negation is exact in floating point.
  struct Side {
    std::vector<Point> points;
    double E1 = 0.0;
  };
  // State with each side's quantities in that side's mirrored frame.
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0, energy = 0.0;
    std::array<double, 2> extreme{0.0, 0.0};     // largest mirrored strain reached (or damaged)
    std::array<double, 2> zeroStrain{0.0, 0.0};  // mirrored zero-stress strain before reloading
    int direction = 0;                           // sign of the last strain increment
  };
  void envelope(int side, double strain, double& stress, double& tangent) const;
  double unloadingStiffness(int side, double extreme) const;
  // Reloading or unloading towards `side` (0: positive), in its frame.
  void hysteretic(int side, const State& c, State& t) const;

  std::array<Side, 2> side_;
  double pinchX_, pinchY_, damage1_, damage2_, beta_;
  double energyUlt_ = 0.0;
  State trial_, committed_;
};

}  // namespace beamsolid
