#pragma once
#include <memory>
#include <string>
#include <vector>

#include "analysis/DofMap.h"
#include "analysis/LinearSystem.h"
#include "core/Types.h"

namespace beamsolid {

class ConstraintHandler;
class Domain;
class LinearSolver;
class Numberer;

// The bridge between the Domain and the equations: assembles tangent,
// residual and mass through the DofMap's cached scatter positions, and maps
// a solution back to node trial displacements. It writes nothing in the
// Domain but node trial displacements.
class CondensedSolver;

class AnalysisModel {
 public:
  enum class Stiffness { Current, Initial };

  explicit AnalysisModel(Domain& domain);
  ~AnalysisModel();
  Domain& domain() { return domain_; }

  // Renumbers and rebuilds the pattern when the Domain, the handler, the
  // numberer or the solver changed since the last call. True if rebuilt.
  bool setup(const ConstraintHandler& handler, const Numberer& numberer, LinearSolver& solver);
  void invalidate() { builtStamp_ = -1; builtConfiguration_.clear(); }

  const DofMap& dofMap() const { return map_; }
  LinearSystem& system() { return system_; }
  int numEquations() const { return map_.numEquations(); }

  // A = K (current or initial) of all elements, plus penalty terms.
  void formTangent(Stiffness which);
  // Transient analysis: A = cK K + cC C + cM M, C the Domain's Rayleigh
  // damping (penalty terms scale with cK, as stiffness does).
  void formDynamicTangent(Stiffness which, double cK, double cC, double cM);
  // b -= M a + C v of the nodes' trial accelerations and velocities (after formUnbalance).
  void subtractInertiaAndDamping();
  // Adds the element mass matrices and nodal masses into `values` (pattern layout).
  void assembleMass(std::vector<double>& values) const;
  // b = P(t) - F(u) (+ penalty terms), reduced to the equations.
  void formUnbalance();
  // d P / d lambda: the reference load of path-following integrators.
  void formReferenceLoad(Vector& out) const;
  // Node trial displacements += T dU, then elements update.
  void applyIncrement(const Vector& dU);
  // Sets fixed/imposed and MP-constrained dofs to their values at the
  // Domain's current time (elimination handlers).
  void enforcePrescribed();
  // Reduced vector of the nodes' trial displacements (free equations).
  void trialDisplacement(Vector& out) const;

  // Which stiffness the system's current factorization holds.
  bool factoredIs(Stiffness which) const { return system_.isFactored() && factoredKind_ == int(which); }
  bool factor(Stiffness which);
  // A readable account of why the last factorization failed, naming dofs.
  std::string describeFactorFailure() const;

  // The condensing solver when one is in use (else null), and why not.
  const CondensedSolver* condensedSolver() const { return condensedActive_ ? condensed_.get() : nullptr; }
  const std::string& condensationNote() const { return condensationNote_; }

 private:
  void scatterElementMatrix(std::vector<double>& values, int e, const double* k) const;
  void addPenaltyTangent(std::vector<double>& values, double factor) const;
  // Chooses between the user's solver and the condensing one (setup()).
  void chooseSolver(LinearSolver& solver);

  Domain& domain_;
  DofMap map_;
  LinearSystem system_;
  long builtStamp_ = -1;
  std::string builtConfiguration_;
  int factoredKind_ = -1;
  double penaltyAlphaS_ = 0.0;
  double penaltyAlphaM_ = 0.0;
  std::vector<double> imposedValues_;
  LinearSolver* outer_ = nullptr;
  std::unique_ptr<CondensedSolver> condensed_;
  bool condensedActive_ = false;
  long condensationRefusedStamp_ = -1;  // pattern on which condensation failed
  std::string condensationNote_;
};

}  // namespace beamsolid
