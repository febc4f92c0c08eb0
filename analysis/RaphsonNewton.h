#pragma once
#include "analysis/Newton.h"

namespace beamsolid {

// RaphsonNewton: Newton-Raphson whose first iteration of a step uses the
// '-increment' tangent and later iterations the '-iterate' tangent, each
// current, initial or noTangent (keep the last factorization).
class RaphsonNewton : public Newton {
 public:
  enum class Choice { Current, Initial, NoTangent };
  RaphsonNewton(Choice iterate, Choice increment)
      : Newton(Tangent::Current, false), iterate_(iterate), increment_(increment) {}
  std::string name() const override { return "RaphsonNewton"; }

 protected:
  bool prepareTangent(AnalysisModel& model, Integrator& integrator, int iteration) override;

 private:
  Choice iterate_;
  Choice increment_;
};

}  // namespace beamsolid
