#pragma once

namespace beamsolid {

// rayleigh(alphaM, betaK, betaKinit, betaKcomm): C = alphaM M + betaK K
// (current) + betaKinit K(initial) + betaKcomm K(last committed).
struct RayleighFactors {
  double alphaM = 0.0, betaK = 0.0, betaKinit = 0.0, betaKcomm = 0.0;
  bool any() const { return alphaM != 0.0 || betaK != 0.0 || betaKinit != 0.0 || betaKcomm != 0.0; }
};

}  // namespace beamsolid
