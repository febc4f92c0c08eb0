#pragma once
// Drives the Interpreter from C++ tests with OpenSeesPy-like calls:
//   Script s; s("node", 1, 0.0, 0.0, 0.0);
#include <string>
#include <variant>
#include <vector>

#include "bindings/Interpreter.h"

namespace beamsolid::testing {

class Script {
 public:
  template <class... A>
  Interpreter::Result operator()(const std::string& command, A... args) {
    std::vector<CommandArgs::Value> values{toValue(args)...};
    return interp.call(command, std::move(values));
  }
  template <class... A>
  double number(const std::string& command, A... args) {
    return std::get<double>((*this)(command, args...));
  }
  template <class... A>
  std::vector<double> list(const std::string& command, A... args) {
    return std::get<std::vector<double>>((*this)(command, args...));
  }
  template <class... A>
  long long integer(const std::string& command, A... args) {
    return std::get<long long>((*this)(command, args...));
  }
  Interpreter interp;

 private:
  static CommandArgs::Value toValue(int v) { return static_cast<long long>(v); }
  static CommandArgs::Value toValue(double v) { return v; }
  static CommandArgs::Value toValue(const char* v) { return std::string(v); }
  static CommandArgs::Value toValue(const std::string& v) { return v; }
};

}  // namespace beamsolid::testing
