#pragma once
#include <array>

#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Pinching4', tag, ePf1, ePd1, ..., ePf4, ePd4,
//                  <eNf1, eNd1, ..., eNf4, eNd4>, rDispP, rForceP, uForceP,
//                  <rDispN, rForceN, uForceN>, gK1..gK4, gKLim, gD1..gD4, gDLim,
//                  gF1..gF4, gFLim, gE, dmgType):
// the pinched, degrading load-deformation model of Lowes & Altoontash (2003)
// and Lowes, Mitra & Altoontash (2004) as OpenSees documents it. The rules
// below were found by driving OpenSeesPy 3.7.1 as a black box; they match it
// point by point on the cases of tests/python/test_uniaxial_oracle.py and on
// 31 of 36 cyclic histories with the manual's example ratios and damage
// parameters. Known differences: on some reversal steps OpenSees evaluates
// the first step with a slightly different target (e.g. dD) than every later
// step of the same branch, and parameter sets with uForce beyond rForce can
// take paths (through the origin) not reproduced here; once a step differs,
// the damage history and so the later response differ too.
//
// Envelope (per side, degraded by the strength damage dF): through the
// origin, a point at 1e-4*max(|d1p|, |d1n|) on the line of Kmax =
// max(K0p, K0n) (K0 = f1/d1), then the four points; past the fourth the last slope continues if
// rising, else a tail towards 1.1*f4 at 1e6*d4.
// Unloading stiffness Ku = K0 (1 - dK). After leaving one envelope towards
// the other side, the path runs from the reversal point R along Ku to
// B (force uForce*f3, or uForce*f4 once the historic extreme passed d3),
// then to C = (rDisp*dT, rForce*f(dT)) and on to D = (dT, f(dT)), dT the
// damaged target deformation; C is pulled onto the line of slope Ku through
// D when C-D would be steeper. B is dropped when R is already past its force
// or B lies past C; when B-C is steeper than both sides' Ku, or when an
// interior reversal starts on the side it heads to, the path is the straight
// line R-D. Past dT, or where such a path beyond the historic extreme would
// exceed the envelope, the response is the envelope.
// Damage, evaluated at each reversal: d = g1*dn^g3 + g2*e^g4 <= gLim, with
// dn = max(P, N)/max(d4p, |d4n|), P and N the damage extremes (the
// historic extreme on leaving the envelope, grown by (1 + dD) each time),
// e = dissipated energy/(gE*max monotonic envelope area) for 'energy'
// (energy frozen beyond |d| = max(d4p, |d4n|)), or the equivalent number of
// cycles sum(|excursion|/(4*max(P, N))) for 'cycle'. dK is also capped so
// Ku stays at least the secant stiffness f(P)/P and f(-N)/(-N).
class Pinching4Material : public UniaxialMaterial {
 public:
  struct Side {
    std::array<double, 4> strain, stress;  // signed (negative side negative)
    double rDisp, rForce, uForce;
  };
  struct Degradation {
    double g1, g2, g3, g4, limit;
  };
  Pinching4Material(int tag, const Side& positive, const Side& negative, const Degradation& stiffness,
                    const Degradation& deformation, const Degradation& strength, double gE, bool cycleDamage);

  std::string className() const override { return "Pinching4"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return kmax_; }

  void commitState() override;
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  void print(std::ostream& os) const override;

 private:
  struct Point {
    double strain, stress;
  };
  enum Mode { kPath = 0, kPositiveEnvelope = 1, kNegativeEnvelope = 2 };
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0;
    double maxStrain = 0.0, minStrain = 0.0;        // extremes reached on the envelope
    double damageMax = 0.0, damageMin = 0.0;        // P and N (both positive)
    double targetMax = 0.0, targetMin = 0.0;        // damaged targets (both positive)
    double energy = 0.0, dissipated = 0.0, cycles = 0.0, lastReversal = 0.0;
    double dK = 0.0, dD = 0.0, dF = 0.0;
    int mode = kPath;
    int direction = 0;  // sign of the last strain increment, 0 before the first
    std::array<Point, 4> path{};
    int pathPoints = 0;
  };

  // Envelope stress and slope at `strain`, forces scaled by (1 - dF).
  void envelope(double strain, double dF, double& stress, double& slope) const;
  double envelopeStress(double strain, double dF) const;
  double unloadingStiffness(const State& s, bool positiveSide) const;
  void updateDamage(const State& c, State& t) const;
  void buildPath(State& t, const State& c, bool towardsPositive, bool direct) const;
  static void evaluatePath(const State& t, double strain, double& stress, double& slope);

  std::array<Side, 2> side_;  // 0: positive, 1: negative
  Degradation gK_, gD_, gF_;
  double gE_;
  bool cycleDamage_;
  double k0p_, k0n_, kmax_, energyMono_, failureStrain_, firstPoint_;
  State trial_, committed_;
};

}  // namespace beamsolid
