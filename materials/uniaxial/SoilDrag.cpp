#include "materials/uniaxial/SoilDrag.h"

#include <cmath>

namespace beamsolid {

SoilDrag::Cycle SoilDrag::cycle(double y) const {
  const State& c = committed_;
  if (y == c.y) return c.direction != 0 ? Cycle{c.direction, c.y0, c.p0} : Cycle{1, c.y, c.p};
  const int d = y > c.y ? 1 : -1;
  if (c.direction == d) return {d, c.y0, c.p0};
  return {d, c.y, c.p};
}

double SoilDrag::force(double y, const Cycle& c) const {
  const double limit = c.direction * dragUlt_;
  return limit - (limit - c.p0) * y50_ / (y50_ + 2.0 * std::abs(y - c.y0));
}

double SoilDrag::tangent(double y, const Cycle& c) const {
  const double limit = c.direction * dragUlt_;
  const double r = y50_ + 2.0 * std::abs(y - c.y0);
  return c.direction * (limit - c.p0) * 2.0 * y50_ / (r * r);
}

void SoilDrag::setTrial(double y) {
  if (y == committed_.y) {
    trial_ = committed_;
    return;
  }
  const Cycle c = cycle(y);
  trial_ = {y, force(y, c), c.y0, c.p0, c.direction};
}

}  // namespace beamsolid
