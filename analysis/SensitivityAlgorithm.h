#pragma once
#include "analysis/SensitivityResults.h"
#include "core/Parameter.h"

namespace beamsolid {

class AnalysisModel;
class Integrator;

// sensitivityAlgorithm('-computeAtEachStep' | '-computeByCommand'): the
// direct differentiation method (Kleiber et al., Parameter Sensitivity in
// Nonlinear Mechanics, 1997; Conte, Vijalapura and Meghella, J. Eng. Mech.
// 2003). After every converged step, for each parameter theta,
//   K_T du/dtheta = -dR/dtheta |u   (the load does not depend on theta)
// with K_T the tangent at the converged state and dR/dtheta|u the
// elements' resisting forces differentiated at fixed displacements, their
// history's sensitivities of the last step included; then each element
// keeps the sensitivities of its new history. Both options compute at
// every step: a path-dependent history's sensitivity needs every step.
// Under displacement control lambda depends on theta too: with
// a = K_T^-1 P_ref and b = -K_T^-1 dR/dtheta|u, du/dtheta = b + dlambda a
// and dlambda = -(e.b)/(e.a) keeps the controlled dof e.u where it is.
class SensitivityAlgorithm {
 public:
  SensitivityAlgorithm(const ParameterMap& parameters, SensitivityResults& results)
      : parameters_(parameters), results_(results) {}

  // After a converged step, before its commit. Throws OpenSeesError for an
  // integrator, element or material that cannot take part.
  void compute(AnalysisModel& model, Integrator& integrator);

 private:
  const ParameterMap& parameters_;  // the interpreter's
  SensitivityResults& results_;
};

}  // namespace beamsolid
