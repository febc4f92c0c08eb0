#include "core/ResponseEnvelope.h"

#include <cmath>

namespace beamsolid {

void ResponseEnvelope::add(double time, const std::vector<double>& values) {
  const std::size_t n = values.size();
  if (count_ == 0) {
    min_ = max_ = values;
    absMax_.resize(n);
    for (std::size_t i = 0; i < n; ++i) absMax_[i] = std::fabs(values[i]);
    minTime_.assign(n, time);
    maxTime_.assign(n, time);
    absMaxTime_.assign(n, time);
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const double v = values[i];
      if (v < min_[i]) { min_[i] = v; minTime_[i] = time; }
      if (v > max_[i]) { max_[i] = v; maxTime_[i] = time; }
      if (std::fabs(v) > absMax_[i]) { absMax_[i] = std::fabs(v); absMaxTime_[i] = time; }
    }
  }
  ++count_;
}

std::vector<std::vector<double>> ResponseEnvelope::rows(bool withTimes) const {
  std::vector<std::vector<double>> out;
  const std::vector<double>* values[3] = {&min_, &max_, &absMax_};
  const std::vector<double>* times[3] = {&minTime_, &maxTime_, &absMaxTime_};
  for (int r = 0; r < 3; ++r) {
    std::vector<double> row;
    for (std::size_t i = 0; i < values[r]->size(); ++i) {
      if (withTimes) row.push_back((*times[r])[i]);
      row.push_back((*values[r])[i]);
    }
    out.push_back(std::move(row));
  }
  return out;
}

std::vector<RecorderOutput::Column> ResponseEnvelope::columns(const std::vector<RecorderOutput::Column>& values,
                                                              bool withTimes) {
  std::vector<RecorderOutput::Column> out;
  for (const auto& c : values) {
    if (withTimes) {
      RecorderOutput::Column t = c;
      t.name = "time_" + c.name;
      t.meaning = "time at which the extreme in the next column occurred";
      out.push_back(std::move(t));
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace beamsolid
