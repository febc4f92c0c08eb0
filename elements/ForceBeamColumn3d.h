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
// system), with Mz(xi) = (xi - 1) Mz_i + xi Mz_j and the same for My; the
// shear of a shear-deformable section is V = dM/dx, Vy = (Mz_i + Mz_j) / L
// and Vz = (My_i + My_j) / L (signs as OpenSeesPy 3.7.1's section forces).
// Compatibility v = sum w L b^T e is enforced by the element iterations of
// ForceBeamCompatibility (as OpenSees' element; shared with the 2D element).
// Default rule of the older form: Lobatto.
// Two kinds of state determination: sections without shear use fixed 4x4
// sizes (the common, fast case); an element with any shear section uses
// ForceBeamTraits3dShear, whose section vectors are
// [P, Mz, My, T, shear components of the section].
struct ForceBeamTraits3d {
  using Section = SectionForceDeformation;
  using SectionVector = SectionForceDeformation::Vector4;
  using SectionMatrix = SectionForceDeformation::Matrix4;
  using Interpolation = Eigen::Matrix<double, 4, 6>;
  static constexpr int kBasic = 6;
  static const SectionVector& deformation(const Section& s) { return s.deformation(); }
  static const SectionVector& force(const Section& s) { return s.force(); }
  static const SectionMatrix& tangent(const Section& s) { return s.tangent(); }
  static const SectionMatrix& initialTangent(const Section& s) { return s.initialTangent(); }
  static void setTrialDeformation(Section& s, const SectionVector& e) { s.setTrialDeformation(e); }
};

struct ForceBeamTraits3dShear {
  using Section = SectionForceDeformation;
  static constexpr int kMaxOrder = 4 + SectionForceDeformation::kMaxShear;
  using SectionVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxOrder, 1>;
  using SectionMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxOrder, kMaxOrder>;
  using Interpolation = Eigen::Matrix<double, Eigen::Dynamic, 6, 0, kMaxOrder, 6>;
  static constexpr int kBasic = 6;
  static SectionVector deformation(const Section& s) { return join(s.deformation(), s.shearDeformation()); }
  static SectionVector force(const Section& s) { return join(s.force(), s.shearForce()); }
  static SectionMatrix tangent(const Section& s) { return join(s.tangent(), s.shearTangent()); }
  static SectionMatrix initialTangent(const Section& s) { return join(s.initialTangent(), s.shearInitialTangent()); }
  static void setTrialDeformation(Section& s, const SectionVector& e) {
    s.setTrialDeformation(e.head<4>());
    s.setTrialShear(e.tail(e.size() - 4));
  }

 private:
  static SectionVector join(const SectionForceDeformation::Vector4& main,
                            const SectionForceDeformation::ShearVector& shear) {
    SectionVector out(4 + shear.size());
    out << main, shear;
    return out;
  }
  static SectionMatrix join(const SectionForceDeformation::Matrix4& main,
                            const SectionForceDeformation::ShearVector& shear) {
    const int n = 4 + static_cast<int>(shear.size());
    SectionMatrix out = SectionMatrix::Zero(n, n);
    out.topLeftCorner<4, 4>() = main;
    for (int k = 0; k < shear.size(); ++k) out(4 + k, 4 + k) = shear[k];
    return out;
  }
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
  // The same for `section` with its shear components (rows 4, ...), L the length.
  static ForceBeamTraits3dShear::Interpolation forceInterpolation(const SectionForceDeformation& section, double xi,
                                                                  double L);
  // Whether the last state determination met the tolerance.
  bool converged() const { return shear_ ? shearState_.converged() : state_.converged(); }
  // Element iterations of the last state determination (all attempts).
  int lastIterations() const { return shear_ ? shearState_.iterations() : state_.iterations(); }
  // Whether some section has shear components (the shear state determination).
  bool shearDeformable() const { return shear_; }

 protected:
  void initializeState() override;

 private:
  void solveState(const Vector6& v);
  // Re-solves when element loads changed since the last solution.
  void ensureState();

  // Calls f with the state determination in use.
  template <class F>
  decltype(auto) withState(F&& f) {
    return shear_ ? f(shearState_) : f(state_);
  }

  bool shear_ = false;
  ForceBeamCompatibility<ForceBeamTraits3d> state_;
  ForceBeamCompatibility<ForceBeamTraits3dShear> shearState_;
};

}  // namespace beamsolid
