#pragma once
#include <memory>

#include "core/LoadPattern.h"

namespace beamsolid {

// pattern('UniformExcitation'): the support moves rigidly in one direction
// with ground acceleration a_g(t) = fact * accelSeries(t). Responses are
// relative to the ground, so the pattern loads the model with the effective
// force -M r a_g, r the influence vector (1 at dof `dir` of every node):
// nodal masses and element mass matrices alike, at every node (at a fixed
// node it shows in the reaction, as in OpenSees). Like OpenSees, only the
// acceleration series loads the model: a pattern given only '-vel' or
// '-disp' applies nothing (the series are kept for the record).
// Element masses are turned into nodal loads here, while OpenSees adds them
// inside the element: the nodal equilibrium and reactions are the same, but
// an element's own force output does not include its inertia load.
class UniformExcitation : public LoadPattern {
 public:
  UniformExcitation(int tag, int dof, std::shared_ptr<TimeSeries> accel, std::shared_ptr<TimeSeries> vel,
                    std::shared_ptr<TimeSeries> disp, double fact, double vel0);

  std::string typeName() const override { return "UniformExcitation"; }
  int dof() const { return dof_; }
  double initialVelocity() const { return vel0_; }
  // Ground acceleration, velocity and displacement series values at time t
  // (0 where the series was not given), times fact.
  double groundAccel(double time) const;
  double groundVel(double time) const;
  double groundDisp(double time) const;

  void applyLoad(Domain& domain, double time) const override;
  void setLoadConst(double time) override;
  // '-vel0': every node whose dof `dir` is not fixed starts with this
  // velocity (as OpenSees, which sets it when the pattern is created).
  void applyInitialVelocity(Domain& domain) const;

 private:
  static double value(const std::shared_ptr<TimeSeries>& s, double time) { return s ? s->factor(time) : 0.0; }

  int dof_;
  std::shared_ptr<TimeSeries> accel_, vel_, disp_;
  double fact_;
  double vel0_;
  bool frozen_ = false;
  double frozenTime_ = 0.0;
};

}  // namespace beamsolid
