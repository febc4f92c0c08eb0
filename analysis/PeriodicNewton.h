#pragma once
#include "analysis/Newton.h"

namespace beamsolid {

// PeriodicNewton: the tangent is formed at the first two iterations of a
// step and then again every maxDim iterations (2, 2 + maxDim, ...); in
// between the last factorization is reused, as in modified Newton.
class PeriodicNewton : public Newton {
 public:
  PeriodicNewton(Tangent tangent, int maxDim) : Newton(tangent, false), maxDim_(maxDim) {}
  std::string name() const override { return "PeriodicNewton"; }

 protected:
  bool prepareTangent(AnalysisModel& model, Integrator& integrator, int iteration) override;

 private:
  int maxDim_;
};

}  // namespace beamsolid
