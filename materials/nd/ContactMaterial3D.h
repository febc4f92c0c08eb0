#pragma once
#include "materials/nd/NDMaterial.h"

namespace beamsolid {

// nDMaterial('ContactMaterial3D', tag, mu, G, c, t): regularized Coulomb
// friction on a contact surface (beam_contact_formulation.md, C13-C16).
//
// The element hands in, per Newton iteration, the gap, the incremental slip
// s^alpha since the last commit (contravariant components in the surface
// coordinates), the normal force t_n (positive = compression) and the surface
// metric m_ab. The material returns the covariant friction traction T_alpha,
// so that the friction force on the element's dofs is T_alpha ds^alpha/dq:
//   elastic predictor  s_e = s_e,n + s,  T = G m s_e,  |T| = G sqrt(s_e.m s_e)    (C13)
//   slip function      f = |T| - mu t_n - c                                         (C14)
//   radial return      s_e <- (1 - gamma/|s_e|_m) s_e,  gamma = f/G                  (C15)
//   consistent tangent dT/ds, dT/dt_n                                               (C16)
// G is a force per unit (physical) slip, c a force, t a tensile force. The
// tensile strength is bounded by the apex of the Coulomb cone, t <= c/mu:
// a larger t is reduced to c/mu. When t_n <= -t the interface has let go:
// the elastic slip is reset and no traction acts.
//
// Stages (updateMaterialStage / setParameter 'friction'): 1 frictional (the
// default, as in OpenSees), 0 frictionless (mu, c, t taken as zero), as used to
// apply confinement before friction acts. The stage belongs to each copy.
class ContactMaterial3D : public NDMaterial {
 public:
  using Vector2 = Eigen::Vector2d;
  using Matrix2 = Eigen::Matrix2d;
  using Vector3 = Eigen::Vector3d;
  using Vector4 = Eigen::Vector4d;
  using Matrix23 = Eigen::Matrix<double, 2, 3>;

  ContactMaterial3D(int tag, double mu, double G, double c, double t);

  std::string className() const override { return "ContactMaterial3D"; }
  // A copy for kind "ContactMaterial3D"; nullptr for any other kind (a
  // contact material cannot serve a solid).
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override;

  // --- the contact interface used by the elements ---------------------------
  // Trial state for (gap, incremental slip s^alpha since the last commit,
  // normal force t_n, surface metric m).
  void setTrialState(double gap, const Vector2& slip, double normalForce, const Matrix2& metric);
  // The same inside a Newton loop (what the contact elements call): the
  // return map of setTrialState, except that a node that slid in the previous
  // iterate of the step and whose trial elastic traction G m s_e no longer
  // exceeds mu t_n + c along that iterate's traction direction (its plastic
  // multiplier would turn negative: the slip reversed) is held sticking for
  // this iterate, with the elastic traction G m s_e and tangent G m. Without
  // this guard a stiff stick (stick band |s_e| < (mu t_n + c)/G narrower than
  // a Newton correction) makes Newton cycle between sliding one way and the
  // other: the sliding tangent is zero along the slip, so each correction
  // overshoots the band to the opposite side. The next iterate starts from
  // the stick state, so the return map's answer is restored as soon as the
  // slip no longer reverses; a converged step is a solution of the same
  // friction law. The previous iterate is the last call with a different
  // input (repeated calls with the same input give the same answer); the
  // memory is cleared by commit, revert and release.
  void setIterate(double gap, const Vector2& slip, double normalForce, const Matrix2& metric);
  // Whether the last setIterate held a reversing node sticking.
  bool heldSticking() const { return held_; }
  // Out of contact: no traction, and the elastic slip is reset so that
  // friction starts afresh when contact closes again.
  void release();
  // The element's surface coordinates changed between steps (a hand-over to
  // the next pile segment): the committed elastic slip -- the friction
  // state -- is expressed in the new ones, s_e <- map s_e with
  // map(beta, alpha) = g'^beta . g_alpha (new contravariant, old covariant
  // base vectors), which keeps the physical elastic slip s_e^alpha g_alpha
  // wherever it lies in the new tangent plane; the metric becomes newMetric
  // and the trial state returns to the (mapped) committed one.
  void changeSurfaceCoordinates(const Matrix2& map, const Matrix2& newMetric);

  // Covariant friction traction T_alpha.
  const Vector2& traction() const { return traction_; }
  // dT/ds (2x2) and dT/dt_n (2) of the trial state.
  const Matrix2& tangentSlip() const { return tangentSlip_; }
  const Vector2& tangentNormal() const { return tangentNormal_; }
  bool sliding() const { return sliding_; }
  // Elastic slip of the trial state and of the last commit (contravariant).
  const Vector2& elasticSlip() const { return elasticSlip_; }
  const Vector2& committedElasticSlip() const { return committedElasticSlip_; }
  // Plastic (sliding) part of the trial slip increment, contravariant.
  const Vector2& plasticSlipIncrement() const { return plasticSlip_; }
  // Frictional work of the trial increment, T . ds_plastic (never negative).
  double dissipation() const { return traction_.dot(plasticSlip_); }
  // |T| of the trial state in the metric: sqrt(T . m^-1 T).
  double tractionNorm() const;
  // mu t_n + c of the trial state (zero in the frictionless stage).
  double slipResistance() const { return slipResistance_; }

  bool frictional() const { return frictional_; }
  double frictionCoefficient() const { return mu_; }
  double stiffness() const { return G_; }
  double cohesion() const { return c_; }
  // The tensile strength in use: min(t, c/mu).
  double tensileStrength() const;
  const Matrix2& metric() const { return metric_; }
  void setMetric(const Matrix2& metric);

  // --- the generic NDMaterial interface --------------------------------------
  // strain = [gap, s^1, s^2, t_n] (with the metric last set),
  // stress = [t_n, T_1, T_2], tangent = [dT/ds | dT/dt_n] (2x3).
  void setTrialStrain(const Eigen::Ref<const Vector>& strain) override;
  VectorView strain() const override { return viewOf(strain_); }
  VectorView stress() const override { return viewOf(stress_); }
  MatrixView tangent() const override { return viewOf(tangent23_); }
  MatrixView initialTangent() const override { return viewOf(initialTangent23_); }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // 0: frictionless, 1: frictional; anything else is an error.
  void updateStage(int stage) override;
  // 'friction' (0|1), 'mu', 'G', 'c' / 'cohesion', 't' / 'tensileStrength'.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void print(std::ostream& os) const override;

 private:
  std::string context() const;
  void setFrictional(double flag);
  void fillGeneric(double gap, const Vector2& slip, double normalForce);
  void forgetIterates();

  double mu_, G_, c_, t_;
  bool frictional_ = true;
  Matrix2 metric_ = Matrix2::Identity();

  // Trial state.
  Vector2 elasticSlip_ = Vector2::Zero();
  Vector2 plasticSlip_ = Vector2::Zero();
  Vector2 traction_ = Vector2::Zero();
  Matrix2 tangentSlip_ = Matrix2::Zero();
  Vector2 tangentNormal_ = Vector2::Zero();
  double slipResistance_ = 0.0;
  bool sliding_ = false;
  // Committed state.
  Vector2 committedElasticSlip_ = Vector2::Zero();
  bool committedSliding_ = false;
  // An incremental slip below this fraction of the elastic slip is no motion
  // (the round-off of the re-projection).
  static constexpr double kUnmoved = 1e-9;
  // setIterate's memory: the input and outcome of the last call, and the
  // outcome of the iterate before it (sliding, unit traction direction).
  bool held_ = false;
  bool haveLast_ = false;
  int iterates_ = 0;  // distinct inputs since the last commit or revert
  Vector2 lastSlip_ = Vector2::Zero();
  double lastNormalForce_ = 0.0;
  bool lastSliding_ = false, previousSliding_ = false;
  Vector2 lastDirection_ = Vector2::Zero(), previousDirection_ = Vector2::Zero();

  // For the generic interface only.
  Vector4 strain_ = Vector4::Zero();
  Vector3 stress_ = Vector3::Zero();
  Matrix23 tangent23_ = Matrix23::Zero();
  Matrix23 initialTangent23_ = Matrix23::Zero();
};

}  // namespace beamsolid
