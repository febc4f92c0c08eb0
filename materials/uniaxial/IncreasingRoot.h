#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

namespace beamsolid {

// The root of an increasing function f on the open interval (lo, hi), where
// f < 0 near lo and f > 0 near hi: Newton steps from `guess`, each kept
// inside the shrinking bracket (a step that leaves it is replaced by
// bisection). `f(x)` returns {value, slope}; the slope may be too small (the
// step overshoots and the bracket catches it) but should not be too large.
// Stops when f is exactly zero, when a Newton step is a few units in the
// last place, or when the bracket has shrunk that far: the root is then as
// accurate as f can be evaluated.
template <class F>
double increasingRoot(F&& f, double lo, double hi, double guess, int maxIter = 400) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double x = (guess > lo && guess < hi) ? guess : 0.5 * (lo + hi);
  for (int i = 0; i < maxIter; ++i) {
    const auto [value, slope] = f(x);
    if (value == 0.0) return x;
    if (value < 0.0)
      lo = x;
    else
      hi = x;
    const double scale = std::max(std::abs(lo), std::abs(hi));
    if (hi - lo <= 4.0 * eps * scale || hi - lo <= std::numeric_limits<double>::min()) return x;
    double next = x - value / slope;
    if (slope > 0.0 && std::isfinite(next) && std::abs(next - x) <= 4.0 * eps * std::abs(x)) return next;
    if (!(slope > 0.0 && next > lo && next < hi)) next = lo + 0.5 * (hi - lo);
    x = next;
  }
  return x;
}

}  // namespace beamsolid
