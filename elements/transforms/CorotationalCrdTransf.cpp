#include "elements/transforms/CorotationalCrdTransf.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/transforms/CorotationalCrdTransf2d.h"
#include "elements/transforms/LinearCrdTransf.h"

namespace beamsolid {

namespace {

using Matrix3x12 = CorotationalCrdTransf::Matrix3x12;
using Row12 = Eigen::Matrix<double, 1, 12>;

Matrix3 skew(const Vector3& a) {
  Matrix3 s;
  s << 0.0, -a.z(), a.y(),  //
      a.z(), 0.0, -a.x(),   //
      -a.y(), a.x(), 0.0;
  return s;
}

std::string format(const Vector3& v) {
  std::ostringstream os;
  os.precision(10);
  os << '(' << v.x() << ", " << v.y() << ", " << v.z() << ')';
  return os.str();
}

// exp of the rotation vector w as a unit quaternion (Rodrigues' formula).
Eigen::Quaterniond exponential(const Vector3& w) {
  const double angle = w.norm();
  // sin(angle/2)/angle, by its series where the quotient loses digits.
  const double s = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(0.5 * angle) / angle;
  return Eigen::Quaterniond(std::cos(0.5 * angle), s * w.x(), s * w.y(), s * w.z());
}

// The rotation vector of R, of length at most pi.
Vector3 logarithm(const Matrix3& r) {
  Eigen::Quaterniond q(r);
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const Vector3 v = q.vec();
  const double s = v.norm();
  // 2 atan2(s, w) / s -> 2 / w with a relative error s^2 / 3.
  if (s < 1e-8) return (2.0 / q.w()) * v;
  return (2.0 * std::atan2(s, q.w()) / s) * v;
}

// eta(t) = (1 - (t/2) cot(t/2)) / t^2 and mu(t) = eta'(t) / t, the
// coefficients of T_s^-1 and of its derivative; series below 0.1 where the
// closed forms cancel (the series of (t/2) cot(t/2) has the Bernoulli numbers).
double eta(double t) {
  const double t2 = t * t;
  if (t < 0.1) return 1.0 / 12.0 + t2 * (1.0 / 720.0 + t2 * (1.0 / 30240.0 + t2 / 1209600.0));
  return 1.0 / t2 - 0.5 / (t * std::tan(0.5 * t));
}

double mu(double t) {
  const double t2 = t * t;
  if (t < 0.1) return 1.0 / 360.0 + t2 * (1.0 / 7560.0 + t2 * (1.0 / 201600.0 + t2 / 5987520.0));
  const double s = std::sin(0.5 * t);
  return -2.0 / (t2 * t2) + 0.5 / (t2 * t * std::tan(0.5 * t)) + 0.25 / (t2 * s * s);
}

// T_s^-1(theta): maps the spatial spin dw of R = exp(theta) to d(theta),
// d(theta) = T_s^-1 dw, T_s^-1 = I - 1/2 [theta] + eta [theta]^2.
Matrix3 rotationRateInverse(const Vector3& theta) {
  const Matrix3 t = skew(theta);
  return Matrix3::Identity() - 0.5 * t + eta(theta.norm()) * t * t;
}

// d(T_s^-T(theta) m) / d(theta) for a fixed m (Battini & Pacoste's K_m).
Matrix3 rotationRateInverseTransposeDerivative(const Vector3& theta, const Vector3& m) {
  const double t = theta.norm();
  const double tm = theta.dot(m);
  return -0.5 * skew(m) + eta(t) * (theta * m.transpose() + tm * Matrix3::Identity() - 2.0 * m * theta.transpose()) +
         mu(t) * (tm * theta - t * t * m) * theta.transpose();
}

// The columns of the rotation increment of `end` (0 or 1) in the end dofs.
Matrix3x12 spinOf(int end) {
  Matrix3x12 s = Matrix3x12::Zero();
  s.block<3, 3>(0, 6 * end + 3).setIdentity();
  return s;
}

}  // namespace

CorotationalCrdTransf::CorotationalCrdTransf(int tag, const Vector3& vecxz, const Vector3& jointOffsetI,
                                             const Vector3& jointOffsetJ)
    : CrdTransf(tag), vecxz_(vecxz), offset_{jointOffsetI, jointOffsetJ} {}

std::unique_ptr<CrdTransf> CorotationalCrdTransf::clone() const {
  return std::make_unique<CorotationalCrdTransf>(tag(), vecxz_, offset_[0], offset_[1]);
}

std::string CorotationalCrdTransf::context() const {
  return "geomTransf " + className() + " " + std::to_string(tag());
}

void CorotationalCrdTransf::initialize(const Node& nodeI, const Node& nodeJ) {
  for (const Node* n : {&nodeI, &nodeJ})
    if (n->ndf() != 6)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs, a 3D beam needs 6");
  node_[0] = &nodeI;
  node_[1] = &nodeJ;

  const Vector3 endI = nodeI.crd() + offset_[0];
  const Vector3 endJ = nodeJ.crd() + offset_[1];
  const Vector3 chord = endJ - endI;
  initialLength_ = chord.norm();
  const bool offsets = offset_[0].norm() > 0.0 || offset_[1].norm() > 0.0;
  if (initialLength_ == 0.0 || initialLength_ <= 1e-12 * std::max(endI.norm(), endJ.norm()))
    throw OpenSeesError(context() + ": element has zero length: the ends at node " + std::to_string(nodeI.tag()) +
                        " " + format(endI) + " and node " + std::to_string(nodeJ.tag()) + " " + format(endJ) +
                        " coincide" + (offsets ? " (after joint offsets)" : ""));
  const Vector3 x = chord / initialLength_;
  Vector3 y = vecxz_.cross(x);
  if (y.norm() <= 1e-10 * vecxz_.norm())
    throw OpenSeesError(context() + ": vecxz " + format(vecxz_) + " is parallel to the element axis " + format(x) +
                        " from node " + std::to_string(nodeI.tag()) + " to node " + std::to_string(nodeJ.tag()) +
                        "; choose a vecxz that is not parallel to the element");
  y.normalize();
  initialAxes_.col(0) = x;
  initialAxes_.col(1) = y;
  initialAxes_.col(2) = x.cross(y);

  // The undeformed configuration: identity triads, unturned arms.
  start_ = State{};
  for (int k = 0; k < 2; ++k) {
    start_.arm[k] = offset_[k];
    start_.nodalY[k] = initialAxes_.col(1);
  }
  formGeometry(start_, endI, endJ);

  // A node may already be displaced when the element is created: its
  // committed rotation is taken as one increment from the start.
  committed_ = start_;
  formState(committed_, nodeI.committedDisp(), nodeJ.committedDisp());
  trial_ = committed_;
  update();
  basicIncrDelta_.setZero();
}

void CorotationalCrdTransf::formState(State& s, const Vector& dispI, const Vector& dispJ) const {
  const Vector* disp[2] = {&dispI, &dispJ};
  Vector3 end[2];
  for (int k = 0; k < 2; ++k) {
    const Vector3 rotationDofs = disp[k]->segment<3>(3);
    const Vector3 increment = rotationDofs - s.appliedRotation[k];
    if (increment.squaredNorm() > 0.0) {
      // Spatial increment: the new triad is exp(increment) times the old one.
      s.rotation[k] = (exponential(increment) * s.rotation[k]).normalized();
      s.appliedRotation[k] = rotationDofs;
    }
    const Matrix3 r = s.rotation[k].toRotationMatrix();
    s.arm[k] = r * offset_[k];
    s.nodalY[k] = r * initialAxes_.col(1);
    end[k] = node_[k]->crd() + disp[k]->head<3>() + s.arm[k];
  }
  formGeometry(s, end[0], end[1]);
}

void CorotationalCrdTransf::formGeometry(State& s, const Vector3& endI, const Vector3& endJ) const {
  const Vector3 chord = endJ - endI;
  s.length = chord.norm();
  const Vector3 r1 = chord / s.length;
  const Vector3 q = 0.5 * (s.nodalY[0] + s.nodalY[1]);
  // NaN when q is along the chord (local rotations near 90 degrees): the
  // convergence test then fails the step instead of throwing mid-analysis.
  const Vector3 r3 = r1.cross(q).normalized();
  const Vector3 r2 = r3.cross(r1);
  s.frame.col(0) = r1;
  s.frame.col(1) = r2;
  s.frame.col(2) = r3;

  // Spin of the frame in its own components, from the end dofs:
  //   about r1: (dq . r3 - (q . r1) r3 . dr1) / (q . r2), dq = (dwI x qI + dwJ x qJ) / 2,
  //   about r2: -r3 . (duJ - duI) / ln,   about r3: r2 . (duJ - duI) / ln.
  const double qr2 = q.dot(r2);
  const double ratio = q.dot(r1) / qr2;
  const double invL = 1.0 / s.length;
  Matrix3x12 w = Matrix3x12::Zero();
  w.block<1, 3>(0, 0) = ratio * invL * r3.transpose();
  w.block<1, 3>(0, 3) = (0.5 / qr2) * s.nodalY[0].cross(r3).transpose();
  w.block<1, 3>(0, 6) = -ratio * invL * r3.transpose();
  w.block<1, 3>(0, 9) = (0.5 / qr2) * s.nodalY[1].cross(r3).transpose();
  w.block<1, 3>(1, 0) = invL * r3.transpose();
  w.block<1, 3>(1, 6) = -invL * r3.transpose();
  w.block<1, 3>(2, 0) = -invL * r2.transpose();
  w.block<1, 3>(2, 6) = invL * r2.transpose();
  s.frameSpin = s.frame * w;

  for (int k = 0; k < 2; ++k) {
    // The nodal triad seen from the corotated frame.
    const Matrix3 relative = s.frame.transpose() * s.rotation[k].toRotationMatrix() * initialAxes_;
    s.theta[k] = logarithm(relative);
    s.thetaRateInverse[k] = rotationRateInverse(s.theta[k]);
    s.thetaRate[k] = s.thetaRateInverse[k] * s.frame.transpose() * (spinOf(k) - s.frameSpin);
  }

  s.basic << s.length - initialLength_, s.theta[0][2], s.theta[1][2], s.theta[0][1], s.theta[1][1],
      s.theta[1][0] - s.theta[0][0];
  s.basicFromEnd.setZero();
  s.basicFromEnd.block<1, 3>(0, 0) = -r1.transpose();
  s.basicFromEnd.block<1, 3>(0, 6) = r1.transpose();
  s.basicFromEnd.row(1) = s.thetaRate[0].row(2);
  s.basicFromEnd.row(2) = s.thetaRate[1].row(2);
  s.basicFromEnd.row(3) = s.thetaRate[0].row(1);
  s.basicFromEnd.row(4) = s.thetaRate[1].row(1);
  s.basicFromEnd.row(5) = s.thetaRate[1].row(0) - s.thetaRate[0].row(0);
}

void CorotationalCrdTransf::update() {
  if (!node_[0]) throw OpenSeesError(context() + ": update() before initialize()");
  const Vector6 previous = trial_.basic;
  formState(trial_, node_[0]->trialDisp(), node_[1]->trialDisp());
  basicIncrDelta_ = trial_.basic - previous;
}

void CorotationalCrdTransf::commitState() { committed_ = trial_; }

void CorotationalCrdTransf::revertToLastCommit() {
  trial_ = committed_;
  basicIncrDelta_.setZero();
}

void CorotationalCrdTransf::revertToStart() {
  committed_ = trial_ = start_;
  basicIncrDelta_.setZero();
}

CorotationalCrdTransf::Vector12 CorotationalCrdTransf::endForce(const State& s, const Vector6& q,
                                                                const Vector12& p0) const {
  Vector12 f = s.basicFromEnd.transpose() * q;
  // The basic system's reactions act in the corotated frame.
  for (int b = 0; b < 4; ++b) f.segment<3>(3 * b) += s.frame * p0.segment<3>(3 * b);
  return f;
}

CorotationalCrdTransf::Vector12 CorotationalCrdTransf::endToNode(const State& s, const Vector12& endForce) const {
  // A rigid arm c carries the end force f to the node as f and c x f.
  Vector12 f = endForce;
  f.segment<3>(3) += s.arm[0].cross(endForce.segment<3>(0));
  f.segment<3>(9) += s.arm[1].cross(endForce.segment<3>(6));
  return f;
}

CorotationalCrdTransf::Vector12 CorotationalCrdTransf::globalResistingForce(const Vector6& q,
                                                                            const Vector12& p0) const {
  return endToNode(trial_, endForce(trial_, q, p0));
}

CorotationalCrdTransf::Vector12 CorotationalCrdTransf::localResistingForce(const Vector6& q,
                                                                           const Vector12& p0) const {
  const Vector12 f = endForce(trial_, q, p0);
  Vector12 local;
  for (int b = 0; b < 4; ++b) local.segment<3>(3 * b) = trial_.frame.transpose() * f.segment<3>(3 * b);
  return local;
}

CorotationalCrdTransf::Matrix12 CorotationalCrdTransf::globalStiffMatrix(const Matrix6& kb, const Vector6& q) const {
  return stiffness(trial_, kb, q);
}

CorotationalCrdTransf::Matrix12 CorotationalCrdTransf::initialGlobalStiffMatrix(const Matrix6& kb) const {
  return stiffness(start_, kb, Vector6::Zero());
}

CorotationalCrdTransf::Matrix12 CorotationalCrdTransf::stiffness(const State& s, const Matrix6& kb,
                                                                 const Vector6& q) const {
  const Vector3 r1 = s.frame.col(0), r2 = s.frame.col(1), r3 = s.frame.col(2);
  const double invL = 1.0 / s.length;
  const Matrix6x12& b = s.basicFromEnd;

  // Material part.
  Matrix12 k = b.transpose() * kb * b;

  // Axial force on the turning chord: N/ln (I - r1 r1^T) on the translations.
  const Matrix3 chordNormal = q[0] * invL * (Matrix3::Identity() - r1 * r1.transpose());
  k.block<3, 3>(0, 0) += chordNormal;
  k.block<3, 3>(0, 6) -= chordNormal;
  k.block<3, 3>(6, 0) -= chordNormal;
  k.block<3, 3>(6, 6) += chordNormal;

  // End moments conjugate to theta_k, and their global vectors
  // g_k = R_r T_s^-T m_k: the force is ... + sum_k (S_k - frameSpin)^T g_k.
  const Vector3 moment[2] = {Vector3(-q[5], q[3], q[1]), Vector3(q[5], q[4], q[2])};
  Vector3 g[2];
  for (int e = 0; e < 2; ++e) {
    g[e] = s.frame * (s.thetaRateInverse[e].transpose() * moment[e]);
    // g_k turns with the frame and T_s^-T changes with theta_k.
    const Matrix3x12 dg = -skew(g[e]) * s.frameSpin +
                          s.frame * rotationRateInverseTransposeDerivative(s.theta[e], moment[e]) * s.thetaRate[e];
    k.noalias() += (spinOf(e) - s.frameSpin).transpose() * dg;
  }

  // Variation of frameSpin^T a for the fixed vector a = g_I + g_J.
  const Vector3 a = g[0] + g[1];
  const Vector3& qI = s.nodalY[0];
  const Vector3& qJ = s.nodalY[1];
  const Vector3 qm = 0.5 * (qI + qJ);
  Matrix3x12 dr1 = Matrix3x12::Zero();
  dr1.block<3, 3>(0, 0) = -invL * (Matrix3::Identity() - r1 * r1.transpose());
  dr1.block<3, 3>(0, 6) = -dr1.block<3, 3>(0, 0);
  const Matrix3x12 dr2 = -skew(r2) * s.frameSpin;
  const Matrix3x12 dr3 = -skew(r3) * s.frameSpin;
  Row12 dLength = Row12::Zero();
  dLength.segment<3>(0) = -r1.transpose();
  dLength.segment<3>(6) = r1.transpose();
  Matrix3x12 dqI = Matrix3x12::Zero(), dqJ = Matrix3x12::Zero();
  dqI.block<3, 3>(0, 3) = -skew(qI);
  dqJ.block<3, 3>(0, 9) = -skew(qJ);
  const Matrix3x12 dq = 0.5 * (dqI + dqJ);

  const double a1 = a.dot(r1), a2 = a.dot(r2), a3 = a.dot(r3);
  const Row12 da1 = a.transpose() * dr1, da2 = a.transpose() * dr2, da3 = a.transpose() * dr3;
  const double qr2 = qm.dot(r2);
  const double ratio = qm.dot(r1) / qr2;
  const Row12 dqr1 = r1.transpose() * dq + qm.transpose() * dr1;
  const Row12 dqr2 = r2.transpose() * dq + qm.transpose() * dr2;
  const Row12 dRatio = (dqr1 - ratio * dqr2) / qr2;

  // Translations: V_uI = -V_uJ = ((a1 ratio + a2) r3 - a3 r2) / ln.
  const Vector3 wv = (a1 * ratio + a2) * r3 - a3 * r2;
  const Matrix3x12 dwv = r3 * (ratio * da1 + a1 * dRatio + da2) + (a1 * ratio + a2) * dr3 - r2 * da3 - a3 * dr2;
  const Matrix3x12 dvu = invL * dwv - (invL * invL) * wv * dLength;
  // Rotations: V_wk = c (q_k x r3), c = a1 / (2 q . r2).
  const double c = 0.5 * a1 / qr2;
  const Row12 dc = (0.5 / qr2) * da1 - (c / qr2) * dqr2;
  const Matrix3x12 dvwI = qI.cross(r3) * dc + c * (-skew(r3) * dqI + skew(qI) * dr3);
  const Matrix3x12 dvwJ = qJ.cross(r3) * dc + c * (-skew(r3) * dqJ + skew(qJ) * dr3);
  k.block<3, 12>(0, 0) -= dvu;
  k.block<3, 12>(3, 0) -= dvwI;
  k.block<3, 12>(6, 0) += dvu;
  k.block<3, 12>(9, 0) -= dvwJ;

  // Rigid arms: end dofs = T node dofs, du_end = du - [c] dw; the force
  // c x f on the rotations adds [f] [c] as c turns with the node.
  if (offset_[0].squaredNorm() > 0.0 || offset_[1].squaredNorm() > 0.0) {
    const Vector12 f = s.basicFromEnd.transpose() * q;
    Matrix12 t = Matrix12::Identity();
    t.block<3, 3>(0, 3) = -skew(s.arm[0]);
    t.block<3, 3>(6, 9) = -skew(s.arm[1]);
    Matrix12 kn = t.transpose() * k * t;
    kn.block<3, 3>(3, 3) += skew(f.segment<3>(0)) * skew(s.arm[0]);
    kn.block<3, 3>(9, 9) += skew(f.segment<3>(6)) * skew(s.arm[1]);
    return kn;
  }
  return k;
}

void CorotationalCrdTransf::print(std::ostream& os) const {
  os << context() << ": vecxz " << format(vecxz_);
  if (offset_[0].norm() > 0.0 || offset_[1].norm() > 0.0)
    os << ", jntOffset I " << format(offset_[0]) << " J " << format(offset_[1]);
  if (node_[0]) os << ", L0 " << initialLength_ << ", deformed length " << trial_.length;
  os << '\n';
}

std::unique_ptr<CrdTransf2d> CorotationalCrdTransf::planar() const {
  return std::make_unique<CorotationalCrdTransf2d>(tag(), offset_[0].head<2>(), offset_[1].head<2>());
}

namespace {

std::unique_ptr<CrdTransf> buildCorotationalCrdTransf(CommandArgs& args, Domain& domain) {
  if (domain.spaceDim() != 3 && domain.spaceDim() != 2)
    args.fail("the Corotational transformation needs a 2D or 3D model, this one has -ndm " +
              std::to_string(domain.spaceDim()));
  // In 2D: no vecxz (Z), and elements take the planar() form.
  const auto d = LinearCrdTransf::parse(args, "Corotational", domain.spaceDim());
  return std::make_unique<CorotationalCrdTransf>(d.tag, d.vecxz, d.jointOffsetI, d.jointOffsetJ);
}

void registerCorotationalCrdTransf(Registry& r) { r.geomTransfs.add("Corotational", &buildCorotationalCrdTransf); }

}  // namespace

BEAMSOLID_REGISTER(registerCorotationalCrdTransf);

}  // namespace beamsolid
