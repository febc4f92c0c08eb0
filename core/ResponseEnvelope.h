#pragma once
#include <vector>

#include "core/RecorderOutput.h"

namespace beamsolid {

// Running min, max and max |value| of each column of a recorder's rows, with
// the time at which each was reached: the three rows of an envelope recorder.
class ResponseEnvelope {
 public:
  void add(double time, const std::vector<double>& values);
  bool empty() const { return count_ == 0; }

  // Rows min, max, absmax. With times, each value is preceded by the time at
  // which that extreme occurred (2 columns per value).
  std::vector<std::vector<double>> rows(bool withTimes) const;
  // The columns of rows(withTimes) for value columns `values`.
  static std::vector<RecorderOutput::Column> columns(const std::vector<RecorderOutput::Column>& values,
                                                     bool withTimes);

 private:
  long count_ = 0;
  std::vector<double> min_, max_, absMax_;
  std::vector<double> minTime_, maxTime_, absMaxTime_;
};

}  // namespace beamsolid
