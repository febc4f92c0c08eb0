#pragma once
// The message of the OpenSeesError a call throws, or "(no error)": tests assert on
// what bad input is told.
#include <functional>
#include <string>

#include "core/OpenSeesError.h"

namespace beamsolid::testsupport {

inline std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const OpenSeesError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace beamsolid::testsupport
