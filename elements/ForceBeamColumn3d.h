#pragma once
#include <vector>

#include "elements/SectionBeamColumn3d.h"

namespace beamsolid {

// Force-based (flexibility) 3D beam-column, forceBeamColumn:
//   element('forceBeamColumn', tag, iNode, jNode, transfTag, integrationTag,
//           <'-iter', maxIter, tol>, <'-mass', massPerLength>)
//   element('forceBeamColumn'|'nonlinearBeamColumn', tag, iNode, jNode,
//           numIntgrPts, secTag, transfTag, ...)                  (older form)
// Section forces are interpolated exactly from the basic forces,
// s(xi) = b(xi) q + sp(xi) (sp: element loads in the simply supported basic
// system), with Mz(xi) = (xi - 1) Mz_i + xi Mz_j and the same for My.
// Compatibility v = sum w L b^T e is enforced by element-level Newton
// iterations (Spacone, Filippou and Taucer 1996; Neuenhofer and Filippou
// 1997): with section flexibilities f = ks^-1 and unbalances r = b q + sp - s,
//   F = sum w L b^T f b,  dv = v - sum w L b^T (e + f r),  dq = F^-1 dv,
//   q += dq,  e += f (r + b dq),
// which leaves compatibility exact after every iteration; it stops when the
// work of the residuals |dq.dv| + sum w L r.f r is below tol times the larger
// of the first iteration's and q.v (default tol 1e-12, maxIter 10), after at
// least one iteration whenever v or the loads changed. If that
// fails the element restarts from its committed state and approaches v in
// 2, 4, ..., 32 substeps. The basic stiffness is F^-1 of the converged state.
// Default rule of the older form: Lobatto.
class ForceBeamColumn3d : public SectionBeamColumn3d {
 public:
  ForceBeamColumn3d(int tag, Definition&& definition);

  std::string className() const override { return "forceBeamColumn"; }

  void update() override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void zeroLoad() override;
  void addLoad(const ElementLoad& load, double factor) override;

  Vector6 basicForce() override;
  Vector6 plasticDeformation() override;
  const Matrix6& basicStiffness() override;

  // Force interpolation matrix b(xi): section forces from basic forces.
  static Eigen::Matrix<double, 4, 6> forceInterpolation(double xi);
  // Whether the last state determination met the tolerance.
  bool converged() const { return converged_; }
  // Element iterations of the last state determination (all substeps).
  int lastIterations() const { return lastIterations_; }

 protected:
  void initializeState() override;

 private:
  // Brings the element to compatibility with basic deformations v.
  void solveState(const Vector6& v);
  // Newton iterations from the current state; false if not converged.
  bool iterate(const Vector6& v);
  void restoreCommitted();
  // Re-solves when element loads changed since the last solution.
  void ensureState();

  Vector6 q_ = Vector6::Zero();
  Matrix6 kb_ = Matrix6::Zero();
  Vector6 solvedDeformation_ = Vector6::Zero();
  bool converged_ = true;
  bool loadsChanged_ = false;
  int lastIterations_ = 0;

  Vector6 committedForce_ = Vector6::Zero();
  Matrix6 committedStiffness_ = Matrix6::Zero();
  Vector6 committedDeformation_ = Vector6::Zero();

  // Per section: forces of element loads, and iteration workspace.
  std::vector<Vector4> loadForces_;
  std::vector<Matrix4> flexibility_;
  std::vector<Vector4> unbalance_;
};

}  // namespace beamsolid
