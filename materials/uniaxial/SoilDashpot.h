#pragma once

#include <algorithm>

namespace beamsolid {

// The radiation dashpot c of PySimple1 / TzSimple1 / QzSimple1: in parallel
// with the far-field elastic spring Kf, so it acts on the far field's share
// of the velocity, and the total stress stays inside +-ult.
namespace soildashpot {

// As OpenSees: the far-field share of the increment from the committed state,
// (ye - ye_c) / (y - y_c); with no increment (after commitState) the tangent
// share tangent / Kf.
inline double farFieldShare(double y, double yCommitted, double p, double pCommitted, double tangent,
                            double farStiffness) {
  if (y != yCommitted) return (p - pCommitted) / (farStiffness * (y - yCommitted));
  return tangent / farStiffness;
}

// p + c share rate, bounded just inside +-ult.
inline double stress(double p, double c, double share, double rate, double ult) {
  const double bound = (1.0 - 1.0e-12) * ult;
  return std::clamp(p + c * share * rate, -bound, bound);
}

}  // namespace soildashpot
}  // namespace beamsolid
