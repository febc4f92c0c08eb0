#pragma once
#include "elements/SectionBeamColumn2d.h"

namespace beamsolid {

// Force-based 2D beam-column (forceBeamColumn, nonlinearBeamColumn in a
// model with -ndm 2): the section forces follow the basic forces exactly,
// s(xi) = b(xi) q + s_load(xi) with, per section component,
//   P: N,   Mz: (xi - 1) M_i + xi M_j,   Vy: (M_i + M_j) / L,
// and compatibility v = sum w L b^T e is restored by Newton iterations on q
// (Spacone, Filippou and Taucer 1996), in substeps from the committed state
// when they do not converge. Default rule of the older form: Lobatto.
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
  bool converged() const { return converged_; }
  int lastIterations() const { return lastIterations_; }

 protected:
  void initializeState() override;

 private:
  void solveState(const Vector3& v);
  bool iterate(const Vector3& v);
  void restoreCommitted();
  void ensureState();

  Vector3 q_ = Vector3::Zero();
  Matrix3 kb_ = Matrix3::Zero();
  Vector3 solvedDeformation_ = Vector3::Zero();
  bool converged_ = true;
  bool loadsChanged_ = false;
  int lastIterations_ = 0;

  Vector3 committedForce_ = Vector3::Zero();
  Matrix3 committedStiffness_ = Matrix3::Zero();
  Vector3 committedDeformation_ = Vector3::Zero();

  // Per section: b(xi), forces of element loads, and iteration workspace.
  std::vector<Interpolation> interpolation_;
  std::vector<SectionVector> loadForces_;
  std::vector<SectionMatrix> flexibility_;
  std::vector<SectionVector> unbalance_;
};

}  // namespace beamsolid
