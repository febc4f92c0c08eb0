#pragma once
#include <vector>

#include "analysis/Algorithm.h"
#include "core/Types.h"

namespace beamsolid {

// algorithm('KrylovNewton', '-iterate', t, '-increment', t, '-maxDim', 3),
// t in current | initial | noTangent:
// modified Newton accelerated by a Krylov subspace (Carlson & Miller 1998).
// With the factored tangent K, each iteration computes the preconditioned
// residual v_k = K^-1 R_k. The earlier corrections u_i and the changes
// w_i = v_i - v_{i+1} they caused span a subspace on which the true response
// is known; the correction is
//   c = argmin |v_k - W c|,   du_k = U c + (v_k - W c),
// i.e. the least-squares part is resolved with the measured response and
// only the remainder with K. After maxDim accelerated iterations the
// tangent is reformed as '-iterate' says and the subspace restarts;
// '-increment' chooses the tangent formed at the start of each step.
class KrylovNewton : public Algorithm {
 public:
  enum class Tangent { Current, Initial, NoTangent };
  KrylovNewton(Tangent iterate, Tangent increment, int maxDimension)
      : iterate_(iterate), increment_(increment), maxDimension_(maxDimension) {}
  std::string name() const override { return "KrylovNewton"; }
  int solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) override;

  // Factorizations made during the last step.
  int numFactorizations() const { return factorizations_; }

 private:
  // Forms and factors the tangent `which` asks for; false if singular.
  bool prepareTangent(AnalysisModel& model, Integrator& integrator, Tangent which);

  Tangent iterate_, increment_;
  int maxDimension_;
  int factorizations_ = 0;
  // The subspace: corrections applied and the changes of v they caused.
  std::vector<Vector> corrections_, changes_;
};

}  // namespace beamsolid
