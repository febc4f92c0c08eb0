#pragma once
#include "analysis/Integrator.h"

namespace beamsolid {

// The transient half of the Integrator family: each step advances time by
// dt (set by the TransientAnalysis before newStep), the tangent is
// cK K + cC C + cM M and the residual includes inertia M a and Rayleigh
// damping C v of the nodes' trial velocities and accelerations.
class TransientIntegrator : public Integrator {
 public:
  bool isStatic() const override { return false; }
  // The next step's time increment; a new dt invalidates kept factorizations.
  void setDeltaT(AnalysisModel& model, double dt) {
    if (dt != dt_) model.system().invalidateFactor();
    dt_ = dt;
  }
  void formTangent(AnalysisModel& model, AnalysisModel::Stiffness which) override {
    model.formDynamicTangent(which, cK_, cC_, cM_);
  }
  void formUnbalance(AnalysisModel& model) override {
    model.formUnbalance();
    model.subtractInertiaAndDamping();
  }

 protected:
  double dt_ = 0.0;
  double cK_ = 1.0, cC_ = 0.0, cM_ = 0.0;
};

}  // namespace beamsolid
