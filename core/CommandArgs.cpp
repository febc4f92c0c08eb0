#include "core/CommandArgs.h"

#include <cmath>
#include <sstream>

#include "core/OpenSeesError.h"

namespace beamsolid {

CommandArgs::CommandArgs(std::string command, std::vector<Value> values)
    : command_(command), context_(std::move(command)), values_(std::move(values)) {}

std::string CommandArgs::describe(const Value& v) {
  std::ostringstream os;
  if (auto* i = std::get_if<long long>(&v)) os << *i;
  else if (auto* d = std::get_if<double>(&v)) os << *d;
  else os << "'" << std::get<std::string>(v) << "'";
  return os.str();
}

bool CommandArgs::nextIsString() const {
  return !done() && std::holds_alternative<std::string>(values_[pos_]);
}

bool CommandArgs::nextIsNumber() const { return !done() && !nextIsString(); }

std::optional<std::string> CommandArgs::peekString() const {
  if (!nextIsString()) return std::nullopt;
  return std::get<std::string>(values_[pos_]);
}

void CommandArgs::fail(const std::string& message) const {
  throw OpenSeesError(context_ + ": " + message);
}

void CommandArgs::failAt(std::size_t index, const char* what, const std::string& expected) const {
  std::ostringstream os;
  os << "argument " << index + 1 << " (" << what << "): expected " << expected;
  if (index < values_.size()) os << ", got " << describe(values_[index]);
  else os << ", but the command has only " << values_.size() << " argument(s)";
  fail(os.str());
}

int CommandArgs::nextInt(const char* what) {
  if (done()) failAt(pos_, what, "an integer");
  const Value& v = values_[pos_];
  if (auto* i = std::get_if<long long>(&v)) {
    if (*i > 2147483647LL || *i < -2147483648LL) failAt(pos_, what, "an integer in the 32-bit range");
    ++pos_;
    return static_cast<int>(*i);
  }
  // A float with an integral value (1.0) is accepted, as Tcl scripts translated to Python often pass them.
  if (auto* d = std::get_if<double>(&v); d && std::isfinite(*d) && std::floor(*d) == *d &&
                                          std::fabs(*d) < 2147483647.0) {
    ++pos_;
    return static_cast<int>(*d);
  }
  failAt(pos_, what, "an integer");
}

double CommandArgs::nextDouble(const char* what) {
  if (done()) failAt(pos_, what, "a number");
  const Value& v = values_[pos_];
  if (auto* i = std::get_if<long long>(&v)) { ++pos_; return static_cast<double>(*i); }
  if (auto* d = std::get_if<double>(&v)) {
    if (!std::isfinite(*d)) failAt(pos_, what, "a finite number");
    ++pos_;
    return *d;
  }
  failAt(pos_, what, "a number");
}

std::string CommandArgs::nextString(const char* what) {
  if (done()) failAt(pos_, what, "a string");
  const Value& v = values_[pos_];
  if (auto* s = std::get_if<std::string>(&v)) { ++pos_; return *s; }
  failAt(pos_, what, "a string");
}

bool CommandArgs::nextFlag(const char* flag) {
  if (nextIsString() && std::get<std::string>(values_[pos_]) == flag) { ++pos_; return true; }
  return false;
}

std::vector<double> CommandArgs::nextDoubles(const char* what, std::size_t minCount) {
  std::vector<double> out;
  while (nextIsNumber()) out.push_back(nextDouble(what));
  if (out.size() < minCount) failAt(pos_, what, "at least " + std::to_string(minCount) + " number(s)");
  return out;
}

std::vector<int> CommandArgs::nextInts(const char* what, std::size_t minCount) {
  std::vector<int> out;
  while (nextIsNumber()) out.push_back(nextInt(what));
  if (out.size() < minCount) failAt(pos_, what, "at least " + std::to_string(minCount) + " integer(s)");
  return out;
}

std::vector<std::string> CommandArgs::restAsStrings() {
  std::vector<std::string> out;
  while (!done()) {
    const Value& v = values_[pos_++];
    if (auto* s = std::get_if<std::string>(&v)) out.push_back(*s);
    else if (auto* i = std::get_if<long long>(&v)) out.push_back(std::to_string(*i));
    else {
      std::ostringstream os;
      os.precision(17);
      os << std::get<double>(v);
      out.push_back(os.str());
    }
  }
  return out;
}

void CommandArgs::expectEnd() const {
  if (!done()) {
    std::ostringstream os;
    os << "unexpected extra argument " << pos_ + 1 << " (" << describe(values_[pos_]) << ")";
    fail(os.str());
  }
}

}  // namespace beamsolid
