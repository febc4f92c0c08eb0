#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace beamsolid {

// The argument list of one command, read front to back by a parser.
// Every read names what it expects, so errors read like
//   "element stdBrick 7: argument 10 (matTag): expected an integer, got 'abc'".
class CommandArgs {
 public:
  using Value = std::variant<long long, double, std::string>;

  CommandArgs(std::string command, std::vector<Value> values);

  const std::string& command() const { return command_; }
  // Context printed before every message, e.g. "element stdBrick 7".
  void setContext(std::string context) { context_ = std::move(context); }
  const std::string& context() const { return context_; }

  std::size_t size() const { return values_.size(); }
  std::size_t position() const { return pos_; }
  void seek(std::size_t pos) { pos_ = pos; }
  std::size_t remaining() const { return values_.size() - pos_; }
  bool done() const { return pos_ >= values_.size(); }
  const Value& at(std::size_t i) const { return values_.at(i); }

  bool nextIsString() const;
  bool nextIsNumber() const;
  // The next argument if it is a string (not consumed).
  std::optional<std::string> peekString() const;

  int nextInt(const char* what);
  double nextDouble(const char* what);
  std::string nextString(const char* what);
  // Consumes the next argument when it is the string `flag`.
  bool nextFlag(const char* flag);
  // Reads numbers until a string or the end; at least `minCount`.
  std::vector<double> nextDoubles(const char* what, std::size_t minCount = 0);
  std::vector<int> nextInts(const char* what, std::size_t minCount = 0);
  // All remaining arguments as strings (numbers printed), consumed.
  std::vector<std::string> restAsStrings();

  // Throws if any argument is left unread.
  void expectEnd() const;
  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void failAt(std::size_t index, const char* what, const std::string& expected) const;

  static std::string describe(const Value& v);

 private:
  std::string command_;
  std::string context_;
  std::vector<Value> values_;
  std::size_t pos_ = 0;
};

}  // namespace beamsolid
