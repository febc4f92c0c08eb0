#pragma once

namespace beamsolid {

// The Kent-Scott-Park compression envelope shared by Concrete01 and
// Concrete02 (compression negative): a Hognestad parabola
// fpc*(2*eta - eta^2), eta = strain/epsc0, up to the peak (epsc0, fpc), a
// straight line down to (epsU, fpcu), then the residual strength fpcu.
struct KentParkEnvelope {
  double fpc, epsc0, fpcu, epsU;

  double initialTangent() const { return 2.0 * fpc / epsc0; }

  // Stress and tangent on the envelope at a compressive strain.
  void evaluate(double strain, double& stress, double& tangent) const {
    if (strain > epsc0) {
      const double eta = strain / epsc0;
      stress = fpc * eta * (2.0 - eta);
      tangent = initialTangent() * (1.0 - eta);
    } else if (strain > epsU) {
      tangent = (fpcu - fpc) / (epsU - epsc0);
      stress = fpc + tangent * (strain - epsc0);
    } else {
      stress = fpcu;
      tangent = 0.0;
    }
  }
  double stressAt(double strain) const {
    double s, t;
    evaluate(strain, s, t);
    return s;
  }
};

}  // namespace beamsolid
