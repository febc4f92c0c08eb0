#pragma once
#include <vector>

#include "analysis/TransientIntegrator.h"

namespace beamsolid {

// integrator('Newmark', gamma, beta, <'-form', 'D'|'V'|'A'>) and, with
// alpha < 1, integrator('HHT', alpha, <gamma, beta>) (Hilber-Hughes-Taylor
// 1977 in OpenSees' convention: alpha = 1 is Newmark). The unknown x is the
// increment of the n+1 displacement (D), velocity (V) or acceleration (A);
// the domain is iterated at U = (1-alpha) U_n + alpha U_n+1 (likewise the
// velocity), A = A_n+1 and the loads of t_n + alpha dt, and is set to the
// n+1 state at commit. There is no initial acceleration solve: the first
// step starts from the nodes' accelerations (zero), as OpenSees does.
// integrator('GeneralizedAlpha', alphaM, alphaF, <gamma, beta>) (Chung and
// Hulbert 1993 in OpenSees' convention, alphaM = alphaF = 1 is Newmark, alphaM
// = 1 is HHT): as HHT with alpha = alphaF, and the acceleration iterated at
// A = (1-alphaM) A_n + alphaM A_n+1.
class Newmark : public TransientIntegrator {
 public:
  enum class Form { D, V, A };
  Newmark(double gamma, double beta, Form form, double alpha = 1.0, std::string name = "Newmark",
          double alphaM = 1.0);
  std::string name() const override { return name_; }
  int newStep(AnalysisModel& model) override;
  int update(AnalysisModel& model, const Vector& x) override;
  void commit(AnalysisModel& model, int iterations) override;

 private:
  // Writes the alpha-state of full dof f into its node.
  void setNode(const AnalysisModel& model, int f) const;

  double gamma_, beta_, alpha_;
  double alphaM_;
  Form form_;
  std::string name_;
  double cu_ = 1.0, cv_ = 0.0, ca_ = 0.0;  // d(U, V, A)_n+1 / dx
  double timeAtStart_ = 0.0;
  std::vector<double> un_, vn_, an_, u1_, v1_, a1_;
};

}  // namespace beamsolid
