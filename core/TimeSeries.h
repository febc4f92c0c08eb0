#pragma once
#include <memory>
#include <optional>
#include <ostream>
#include <string>

namespace beamsolid {

// Maps (pseudo) time to a load factor. slope() is d factor / d t, used by
// DisplacementControl and ArcLength to form the reference load.
class TimeSeries {
 public:
  explicit TimeSeries(int tag) : tag_(tag) {}
  virtual ~TimeSeries() = default;
  int tag() const { return tag_; }
  virtual std::string className() const = 0;
  virtual double factor(double time) const = 0;
  virtual double slope(double time) const = 0;
  // The time after which the series stays 0 (or constant), if it has one;
  // a ground motion integrates its accelerations up to it.
  virtual std::optional<double> lastTime() const { return std::nullopt; }
  virtual void print(std::ostream& os) const { os << "TimeSeries " << tag_ << " type " << className() << '\n'; }

 private:
  int tag_;
};

}  // namespace beamsolid
