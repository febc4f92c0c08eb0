#include "materials/uniaxial/SoilNearField.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace beamsolid {

SoilNearField::SoilNearField(double ult, double cY50, double n, double Cr, double elasticStiffness, Range range)
    : ult_(ult), cY50_(cY50), n_(n), Cr_(Cr), elasticFlexibility_(1.0 / elasticStiffness), range_(range) {
  revertToStart();
}

void SoilNearField::revertToStart() {
  committed_ = State{};
  committed_.lower = -Cr_ * ult_;
  committed_.upper = Cr_ * ult_;
  committed_.width = 2.0 * Cr_ * ult_;
  trial_ = committed_;
}

SoilNearField::Trial SoilNearField::at(double p) const {
  const State& c = committed_;
  if (p >= c.lower && p <= c.upper) return {c.y + (p - c.p) * elasticFlexibility_, false, c.direction, c.p0, c.y0};
  const int d = p > c.upper ? 1 : -1;
  double p0, y0;
  if (c.direction == d && c.p == (d > 0 ? c.upper : c.lower)) {
    p0 = c.p0;  // the committed state is in plastic flow this way: same excursion
    y0 = c.y0;
  } else {
    p0 = d > 0 ? c.upper : c.lower;
    y0 = c.y + (p0 - c.p) * elasticFlexibility_;
  }
  // (d ult - p0) / (d ult - p) = [(c y50 + |y - y0|) / c y50]^n
  const double y = y0 + d * cY50_ * (std::pow((ult_ - d * p0) / (ult_ - d * p), 1.0 / n_) - 1.0);
  return {y, true, d, p0, y0};
}

double SoilNearField::plasticTangent(double p, double y, double y0, int d) const {
  return n_ * (ult_ - d * p) / (cY50_ + std::abs(y - y0));
}

double SoilNearField::flexibility(double p, const Trial& t) const {
  if (!t.plastic) return elasticFlexibility_;
  return 1.0 / plasticTangent(p, t.y, t.y0, t.direction);
}

void SoilNearField::setTrial(double p) {
  const Trial t = at(p);
  State s = committed_;
  s.p = p;
  s.y = t.y;
  if (t.plastic) {
    const int d = t.direction;
    s.direction = d;
    s.p0 = t.p0;
    s.y0 = t.y0;
    switch (range_) {
      case Range::PySimple1:
        if (d > 0) {
          s.upper = p;
          s.lower = std::min(p - 2.0 * Cr_ * ult_, -0.25 * ult_);
        } else {
          s.lower = p;
          s.upper = std::max(p + 2.0 * Cr_ * ult_, 0.25 * ult_);
        }
        break;
      case Range::QzSimple1:
        s.width = std::min(0.7 * ult_, std::max(committed_.width, std::abs(p) + Cr_ * ult_));
        if (d > 0) {
          s.upper = p;
          s.lower = p - s.width;
        } else {
          s.lower = p;
          s.upper = p + s.width;
        }
        break;
      case Range::TzSimple1:
        s.lower = s.upper = p;
        break;
    }
  }
  trial_ = s;
}

double SoilNearField::tangent() const {
  const State& s = trial_;
  if (s.direction != 0 && s.p == (s.direction > 0 ? s.upper : s.lower))
    return plasticTangent(s.p, s.y, s.y0, s.direction);
  // A rigid range of zero width (TzSimple1) before any loading: the virgin
  // plastic tangent n ult / (c y50), the same in both directions.
  if (s.lower == s.upper) return n_ * (ult_ - std::abs(s.p)) / cY50_;
  return 1.0 / elasticFlexibility_;
}

}  // namespace beamsolid
