#include "analysis/ResponseSpectrumAnalysis.h"

#include <cmath>

#include "analysis/ModalProperties.h"
#include "core/Domain.h"

namespace beamsolid {

void ResponseSpectrumAnalysis::run(Domain& domain, const ModalProperties& properties, int direction,
                                   const std::function<double(double)>& spectrum, int mode) {
  const std::vector<double>& lambda = domain.eigenvalues();
  const int first = mode == 0 ? 1 : mode;
  const int last = mode == 0 ? static_cast<int>(lambda.size()) : mode;
  for (int m = first; m <= last; ++m) {
    const double omega2 = lambda[m - 1];
    const double period = 2.0 * M_PI / std::sqrt(omega2);
    const double amplitude = properties.participationFactor(m - 1, direction - 1) * spectrum(period) / omega2;
    for (const auto& [tag, node] : domain.nodes()) {
      const Matrix& phi = node->eigenvectors();
      Vector u = Vector::Zero(node->ndf());
      if (phi.cols() >= m) u = amplitude * phi.col(m - 1);
      node->setTrialDisp(u);
    }
    domain.update();
    domain.commit();  // records
  }
}

}  // namespace beamsolid
