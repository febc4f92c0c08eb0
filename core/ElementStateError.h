#pragma once
#include "core/OpenSeesError.h"

namespace beamsolid {

// Thrown by an element (or material) whose state determination fails for
// the current trial displacements (e.g. a force-based element that cannot
// reach compatibility). The analysis treats it as a failed step: the model
// reverts to its last converged state and analyze returns a negative code,
// as in OpenSees, so the usual cut-the-step retry loop works.
class ElementStateError : public OpenSeesError {
 public:
  using OpenSeesError::OpenSeesError;
};

}  // namespace beamsolid
