#pragma once
#include <string>

namespace beamsolid {

// How single- and multi-point constraints enter the equations.
// Plain and Transformation eliminate constrained dofs (u = T u_free + g);
// Penalty keeps every dof and adds alphaS / alphaM springs. Lagrange enforces
// the constraints exactly, as multipliers would: by the same elimination, which
// gives the multipliers' answer without an indefinite system (only a fix on a
// dof an equalDOF/rigidLink also constrains, where Transformation drops the fix,
// is refused).
class ConstraintHandler {
 public:
  enum class Method { Plain, Transformation, Penalty, Lagrange };

  ConstraintHandler(Method method, double alphaS = 0.0, double alphaM = 0.0)
      : method_(method), alphaS_(alphaS), alphaM_(alphaM) {}

  Method method() const { return method_; }
  bool eliminates() const { return method_ != Method::Penalty; }
  double alphaS() const { return alphaS_; }
  double alphaM() const { return alphaM_; }
  std::string name() const;

 private:
  Method method_;
  double alphaS_;
  double alphaM_;
};

}  // namespace beamsolid
