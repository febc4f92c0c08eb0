#pragma once
#include <stdexcept>
#include <string>

namespace beamsolid {

// Every user-facing failure is an OpenSeesError whose message names the
// command, the argument and what was expected. Python sees it as
// beamsolid.OpenSeesError (a RuntimeError).
class OpenSeesError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace beamsolid
