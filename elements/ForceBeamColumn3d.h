#pragma once
#include <vector>

#include "elements/ForceBeamCompatibility.h"
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
// Compatibility v = sum w L b^T e is enforced by the element iterations of
// ForceBeamCompatibility (as OpenSees' element; shared with the 2D element).
// Default rule of the older form: Lobatto.
struct ForceBeamTraits3d {
  using Section = SectionForceDeformation;
  using SectionVector = SectionForceDeformation::Vector4;
  using SectionMatrix = SectionForceDeformation::Matrix4;
  using Interpolation = Eigen::Matrix<double, 4, 6>;
  static constexpr int kBasic = 6;
};

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
  bool converged() const { return state_.converged(); }
  // Element iterations of the last state determination (all attempts).
  int lastIterations() const { return state_.iterations(); }

 protected:
  void initializeState() override;

 private:
  void solveState(const Vector6& v);
  // Re-solves when element loads changed since the last solution.
  void ensureState();

  ForceBeamCompatibility<ForceBeamTraits3d> state_;
};

}  // namespace beamsolid
