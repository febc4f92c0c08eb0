#include "analysis/TransientAnalysis.h"

#include <algorithm>

#include "analysis/TransientIntegrator.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

TransientAnalysis::TransientAnalysis(Domain& domain, AnalysisComponents& components, bool variable)
    : Analysis(domain, components), variable_(variable) {}

TransientIntegrator& TransientAnalysis::integrator() {
  auto* t = dynamic_cast<TransientIntegrator*>(components_.integrator.get());
  if (!t) throw OpenSeesError("analyze: integrator " + components_.integrator->name() + " is not transient");
  return *t;
}

int TransientAnalysis::analyze(int numSteps, double dt) {
  domain_.setTransient(true);
  return guarded([&] {
    TransientIntegrator& t = integrator();
    for (int step = 0; step < numSteps; ++step) {
      if (const int code = setupStep()) return code;
      t.setDeltaT(model_, dt);
      if (const int code = oneStep()) return code;
    }
    return 0;
  });
}

int TransientAnalysis::analyze(int numSteps, double dt, double dtMin, double dtMax, int desiredIterations) {
  domain_.setTransient(true);
  return guarded([&] {
    TransientIntegrator& t = integrator();
    // As OpenSees: steps until the elapsed time reaches numSteps * dt
    // (not numSteps steps), the first one of dt.
    const double total = numSteps * dt;
    double current = dt, elapsed = 0.0;
    while (elapsed < total) {
      if (const int code = setupStep()) return code;
      t.setDeltaT(model_, current);
      if (const int code = oneStep()) {
        current *= 0.5;
        if (current < dtMin) return code;
        continue;
      }
      elapsed += current;
      const int iterations = std::max(1, components_.test->numIterations());
      current = std::clamp(current * double(desiredIterations) / double(iterations), dtMin, dtMax);
    }
    lastError_.clear();  // earlier halvings recovered
    return 0;
  });
}

}  // namespace beamsolid
