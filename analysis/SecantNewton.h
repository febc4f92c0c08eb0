#pragma once
#include "analysis/Algorithm.h"
#include "core/Types.h"

namespace beamsolid {

// algorithm('SecantNewton', '-iterate', t, '-increment', t, '-maxDim', 3,
// '-numTerms', 2, '-cutOut', R1, R2), t in current | initial | noTangent:
// modified Newton accelerated by Crisfield's secant update (Crisfield 1991,
// vol. 1, ch. 9), a BFGS update of K^-1 by the last pair only. With v_i =
// K^-1 b_i the modified-Newton correction, s the previous correction and
// y = b_{i-1} - b_i the unbalance change it caused (rho = 1/(y's)):
//   q = v_i - rho (s'b_i) z,   du = q + rho s (s'b_i - y'q),
// where z = K^-1 y is v_{i-1} - v_i (three terms) or, as Crisfield's
// two-term form assumes, s - v_i. '-cutOut' R1, R2 drops the update (plain
// modified Newton) when the secant ratio s'b_{i-1} / (s'y) leaves [R2, R1].
// After maxDim accelerated iterations the tangent is reformed per '-iterate';
// '-increment' chooses the tangent formed at the start of each step.
class SecantNewton : public Algorithm {
 public:
  enum class Tangent { Current, Initial, NoTangent };
  SecantNewton(Tangent iterate, Tangent increment, int maxDimension, int numTerms, double cutOutHigh,
               double cutOutLow)
      : iterate_(iterate),
        increment_(increment),
        maxDimension_(maxDimension),
        numTerms_(numTerms),
        cutOutHigh_(cutOutHigh),
        cutOutLow_(cutOutLow) {}
  std::string name() const override { return "SecantNewton"; }
  int solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) override;

 private:
  bool prepareTangent(AnalysisModel& model, Integrator& integrator, Tangent which);

  Tangent iterate_, increment_;
  int maxDimension_;
  int numTerms_;
  double cutOutHigh_, cutOutLow_;  // 0, 0: no cut-out
};

}  // namespace beamsolid
