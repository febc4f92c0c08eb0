#pragma once
#include "core/Types.h"

namespace beamsolid {

class Element;

// An element's tangent next to central differences of its resisting force,
// at the nodes' trial displacements. For element authors (and plugin tests,
// through beamsolid.testing.check_tangent): a tangent that is not the
// derivative of the force costs Newton its quadratic convergence.
struct TangentCheck {
  Matrix tangent;     // tangentStiff() at the trial state
  Matrix difference;  // column j: (R(u + h e_j) - R(u - h e_j)) / 2h

  // Perturbs each of the element's dofs by +-h, one at a time, and restores
  // the trial displacements (and the element's state, by update()) after.
  static TangentCheck of(Element& element, double h);
};

}  // namespace beamsolid
