#pragma once
// Checks shared by the uniaxial material tests: a finite-difference tangent
// along a cyclic strain path, and exact restoration by revertToLastCommit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../SolidsTestSupport.h"

namespace beamsolid::uniaxialtest {

inline std::unique_ptr<UniaxialMaterial> build(Domain& d, const std::string& type, CommandArgs a) {
  return Registry::global().uniaxialMaterials.get(type)(a, d);
}

// Sensitivities (direct differentiation) along a strain path that does not
// depend on the parameters: at every step d stress / d theta (history's
// sensitivity carried by commitSensitivity) must match the central
// difference of the whole path run with theta +- h (h = 1e-6 theta) within
// rtol of the largest sensitivity. `make(values)` builds the material from
// its argument values; `names` are the parameters' names, one per value.
template <class Make>
void expectSensitivitiesMatchFiniteDifferences(Make make, const std::vector<double>& values,
                                               const std::vector<std::string>& names,
                                               const std::vector<double>& path, double rtol) {
  auto stresses = [&](const std::vector<double>& v) {
    std::unique_ptr<UniaxialMaterial> m = make(v);
    std::vector<double> out;
    for (double e : path) {
      m->setTrialStrain(e);
      out.push_back(m->stress());
      m->commitState();
    }
    return out;
  };
  for (std::size_t p = 0; p < names.size(); ++p) {
    std::unique_ptr<UniaxialMaterial> m = make(values);
    const int id = m->sensitivityParameter({names[p]});
    ASSERT_GT(id, 0) << names[p];
    std::vector<double> ddm;
    for (double e : path) {
      m->setTrialStrain(e);
      ddm.push_back(m->stressSensitivity(0, id));
      m->commitSensitivity(0.0, 0, id, 1);
      m->commitState();
    }
    std::vector<double> plus = values, minus = values;
    const double h = 1e-6 * values[p];
    plus[p] += h;
    minus[p] -= h;
    const std::vector<double> sp = stresses(plus), sm = stresses(minus);
    double scale = 0.0;
    for (double x : ddm) scale = std::max(scale, std::fabs(x));
    ASSERT_GT(scale, 0.0) << names[p];
    for (std::size_t i = 0; i < path.size(); ++i)
      EXPECT_NEAR(ddm[i], (sp[i] - sm[i]) / (2.0 * h), rtol * scale) << names[p] << " step " << i;
  }
}

// Strains on `turns` in steps of at most `step`, each committed; at every
// point (away from a kink by more than h) the tangent must match the central
// difference of the stress about the committed state within rtol of `scale`.
inline void expectTangentMatchesFiniteDifference(UniaxialMaterial& m, const std::vector<double>& turns,
                                                 double step, double h, double scale, double rtol = 1e-6) {
  double current = 0.0;
  int checked = 0;
  for (double target : turns) {
    while (std::abs(target - current) > 1e-15) {
      const double size = std::min(step, std::abs(target - current));
      current += target > current ? size : -size;
      m.setTrialStrain(current + h);
      const double plus = m.stress();
      m.setTrialStrain(current - h);
      const double minus = m.stress();
      m.setTrialStrain(current);
      const double fd = (plus - minus) / (2.0 * h);
      // One-sided differences agree only off a kink; test where both sides do.
      m.setTrialStrain(current + 2 * h);
      const double plus2 = m.stress();
      m.setTrialStrain(current);
      const double fdRight = (plus2 - m.stress()) / (2 * h);
      if (std::abs(fdRight - fd) <= rtol * scale) {
        EXPECT_NEAR(m.tangent(), fd, rtol * scale) << "at strain " << current;
        ++checked;
      }
      m.commitState();
    }
  }
  EXPECT_GT(checked, 10);
}

// A trial away from the committed state and back by revertToLastCommit leaves
// stress, strain and tangent as they were, and the next step is unchanged.
inline void expectRevertRestoresExactly(UniaxialMaterial& a, const std::vector<double>& path, double excursion) {
  std::unique_ptr<UniaxialMaterial> b = a.clone();
  for (double e : path) {
    a.setTrialStrain(e);
    a.commitState();
    b->setTrialStrain(e);
    b->commitState();
    a.setTrialStrain(e + excursion);
    a.setTrialStrain(e - 0.5 * excursion);
    a.revertToLastCommit();
    EXPECT_EQ(a.stress(), b->stress()) << "after revert at " << e;
    EXPECT_EQ(a.strain(), b->strain());
    EXPECT_EQ(a.tangent(), b->tangent());
  }
  a.revertToStart();
  a.setTrialStrain(path.front());
  b->revertToStart();
  b->setTrialStrain(path.front());
  EXPECT_EQ(a.stress(), b->stress());
}

}  // namespace beamsolid::uniaxialtest
