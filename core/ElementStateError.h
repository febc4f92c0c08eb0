#pragma once
#include "core/OpenSeesError.h"

namespace beamsolid {

// Thrown by an element (or material) whose state determination fails for
// the current trial displacements. The analysis treats it as a failed step:
// the model reverts to its last converged state and analyze returns a
// negative code, so the usual cut-the-step retry loop works. (forceBeamColumn
// does not throw it: as OpenSees' element it warns and goes on with its last
// state, see ForceBeamCompatibility.h.)
class ElementStateError : public OpenSeesError {
 public:
  using OpenSeesError::OpenSeesError;
};

}  // namespace beamsolid
