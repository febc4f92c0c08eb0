#pragma once
#include "elements/ForceBeamCompatibility.h"
#include "elements/SectionBeamColumn2d.h"

namespace beamsolid {

// Force-based 2D beam-column (forceBeamColumn, nonlinearBeamColumn in a
// model with -ndm 2): the section forces follow the basic forces exactly,
// s(xi) = b(xi) q + s_load(xi) with, per section component,
//   P: N,   Mz: (xi - 1) M_i + xi M_j,   Vy: (M_i + M_j) / L,
// and compatibility v = sum w L b^T e is restored by the iterations of
// ForceBeamCompatibility (as OpenSees' element). Default rule of the older
// form: Lobatto.
struct ForceBeamTraits2d {
  using Section = SectionForceDeformation2d;
  using SectionVector = SectionForceDeformation2d::Vector;
  using SectionMatrix = SectionForceDeformation2d::Matrix;
  using Interpolation = SectionBeamColumn2d::Interpolation;
  static constexpr int kBasic = 3;
  static const SectionVector& deformation(const Section& s) { return s.deformation(); }
  static const SectionVector& force(const Section& s) { return s.force(); }
  static const SectionMatrix& tangent(const Section& s) { return s.tangent(); }
  static const SectionMatrix& initialTangent(const Section& s) { return s.initialTangent(); }
  static void setTrialDeformation(Section& s, const SectionVector& e) { s.setTrialDeformation(e); }
};

class ForceBeamColumn2d : public SectionBeamColumn2d {
 public:
  ForceBeamColumn2d(int tag, Definition&& definition);
  static std::unique_ptr<Element> build(CommandArgs& args, Domain& domain, const std::string& type);

  std::string className() const override { return "forceBeamColumn"; }

  void update() override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void zeroLoad() override;
  void addLoad(const ElementLoad& load, double factor) override;

  Vector3 basicForce() override;
  const Matrix3& basicStiffness() override;
  Vector3 plasticDeformation() override;

  // Force interpolation b(xi) of one section (rows follow its codes).
  static Interpolation forceInterpolation(const std::vector<SectionCode>& codes, double xi, double length);
  bool converged() const { return state_.converged(); }
  int lastIterations() const { return state_.iterations(); }

 protected:
  void initializeState() override;

 private:
  void solveState(const Vector3& v);
  void ensureState();

  ForceBeamCompatibility<ForceBeamTraits2d> state_;
  std::vector<Interpolation> interpolation_;
};

}  // namespace beamsolid
