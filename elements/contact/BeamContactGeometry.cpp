#include "elements/contact/BeamContactGeometry.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/contact/ContactSupport.h"

namespace beamsolid {

namespace {

// The rotation taking unit vector a to unit vector c about a x c (no drilling)
// applied to v:  (a.c) v + k x v + (k.v) k / (1 + a.c),  k = a x c.
Vector3 transport(const Vector3& a, const Vector3& c, const Vector3& v) {
  const double cosine = a.dot(c);
  const Vector3 k = a.cross(c);
  return cosine * v + k.cross(v) + (k.dot(v) / (1.0 + cosine)) * k;
}

std::string format(const Vector3& v) {
  std::ostringstream os;
  os.precision(10);
  os << '(' << v.x() << ", " << v.y() << ", " << v.z() << ')';
  return os.str();
}

Vector3 position(const Node& n) { return n.crd() + n.trialDisp().head<3>(); }
Vector3 rotation(const Node& n) { return n.trialDisp().segment<3>(3); }

}  // namespace

void BeamContactGeometry::hermite(double xi, double h[4], double dh[4], double ddh[4]) {
  const double x2 = xi * xi, x3 = x2 * xi;
  h[0] = 1.0 - 3.0 * x2 + 2.0 * x3;
  h[1] = xi - 2.0 * x2 + x3;
  h[2] = 3.0 * x2 - 2.0 * x3;
  h[3] = -x2 + x3;
  dh[0] = -6.0 * xi + 6.0 * x2;
  dh[1] = 1.0 - 4.0 * xi + 3.0 * x2;
  dh[2] = 6.0 * xi - 6.0 * x2;
  dh[3] = -2.0 * xi + 3.0 * x2;
  ddh[0] = -6.0 + 12.0 * xi;
  ddh[1] = -4.0 + 6.0 * xi;
  ddh[2] = 6.0 - 12.0 * xi;
  ddh[3] = -2.0 + 6.0 * xi;
}

Vector3 BeamContactGeometry::centerline(double xi) const {
  double h[4], dh[4], ddh[4];
  hermite(xi, h, dh, ddh);
  return h[0] * xa_ + h[1] * length_ * frameA_.col(0) + h[2] * xb_ + h[3] * length_ * frameB_.col(0);
}

Vector3 BeamContactGeometry::centerlineTangent(double xi) const {
  double h[4], dh[4], ddh[4];
  hermite(xi, h, dh, ddh);
  return dh[0] * xa_ + dh[1] * length_ * frameA_.col(0) + dh[2] * xb_ + dh[3] * length_ * frameB_.col(0);
}

Vector3 BeamContactGeometry::centerlineCurvature(double xi) const {
  double h[4], dh[4], ddh[4];
  hermite(xi, h, dh, ddh);
  return ddh[0] * xa_ + ddh[1] * length_ * frameA_.col(0) + ddh[2] * xb_ + ddh[3] * length_ * frameB_.col(0);
}

void BeamContactGeometry::setLength(const Node& a, const Node& b) {
  length_ = (b.crd() - a.crd()).norm();
  if (!(length_ > 0.0))
    throw OpenSeesError("the beam nodes " + std::to_string(a.tag()) + " and " + std::to_string(b.tag()) +
                        " coincide at " + format(a.crd()));
}

void BeamContactGeometry::initialize(const Node& a, const Node& b, const Node& s, const Matrix3& frameA,
                                     const Matrix3& frameB, double radius, double xiStart) {
  radius_ = radius;
  setLength(a, b);
  setFrames(a, b, frameA, frameB);
  if (std::isfinite(xiStart)) {
    xi_ = xiStart;
  } else {
    const Vector3 chord = xb_ - xa_;
    xi_ = std::clamp(chord.dot(position(s) - xa_) / chord.squaredNorm(), 0.0, 1.0);
  }
  setProjectionData(s);
  update(a, b, s);
}

void BeamContactGeometry::setFrames(const Node& a, const Node& b, const Matrix3& frameA, const Matrix3& frameB) {
  frameA_ = frameA;
  frameB_ = frameB;
  thetaA_ = rotation(a);
  thetaB_ = rotation(b);
  xa_ = position(a);
  xb_ = position(b);
  computeTwist();
}

void BeamContactGeometry::initialize(const Node& a, const Node& b, const Node& s, const Matrix3& localAxes,
                                     double radius) {
  radius_ = radius;
  setLength(a, b);
  // Reference frames: columns = local x (along the beam), y, z (C1 start).
  frameA_ = localAxes.transpose();
  frameB_ = frameA_;
  thetaA_.setZero();
  thetaB_.setZero();
  updateFrames(a, b);
  // Start the projection from the chord projection.
  const Vector3 chord = xb_ - xa_;
  xi_ = std::clamp(chord.dot(position(s) - xa_) / chord.squaredNorm(), 0.0, 1.0);
  setProjectionData(s);
  update(a, b, s);
}

void BeamContactGeometry::updateFrames(const Node& a, const Node& b) {
  // C1: rotate by the exponential map of the increment since the last update.
  const Vector3 thetaA = rotation(a), thetaB = rotation(b);
  frameA_ = rotationExp(thetaA - thetaA_) * frameA_;
  frameB_ = rotationExp(thetaB - thetaB_) * frameB_;
  thetaA_ = thetaA;
  thetaB_ = thetaB;
  xa_ = position(a);
  xb_ = position(b);
  computeTwist();
}

void BeamContactGeometry::computeTwist() {
  // Twist of Q_b relative to Q_a transported (without drilling) to b1 (C6).
  const Vector3 a1 = frameA_.col(0), b1 = frameB_.col(0);
  if (1.0 + a1.dot(b1) <= 1e-8)
    throw OpenSeesError("the beam's end tangents point in opposite directions; the segment has folded back");
  const Vector3 a2 = transport(a1, b1, frameA_.col(1));
  const Vector3 a3 = transport(a1, b1, frameA_.col(2));
  const Vector3 b2 = frameB_.col(1);
  twist_ = std::atan2(b2.dot(a3), b2.dot(a2));
}

void BeamContactGeometry::frameAt(double xi, Matrix3& frame, Matrix3* derivative) const {
  double h[4], dh[4], ddh[4];
  hermite(xi, h, dh, ddh);
  const Vector3 a1 = frameA_.col(0), a2 = frameA_.col(1), a3 = frameA_.col(2);
  const Vector3 t = dh[0] * xa_ + dh[1] * length_ * a1 + dh[2] * xb_ + dh[3] * length_ * frameB_.col(0);
  const double tNorm = t.norm();
  if (!(tNorm > 0.0)) throw OpenSeesError("the centerline tangent vanishes at xi = " + std::to_string(xi));
  const Vector3 c1 = t / tNorm;
  const double cosine = a1.dot(c1);
  const double denom = 1.0 + cosine;
  if (denom <= 1e-8)
    throw OpenSeesError("the centerline turns back on itself at xi = " + std::to_string(xi));
  const Vector3 k = a1.cross(c1);
  const Vector3 c20 = cosine * a2 + k.cross(a2) + (k.dot(a2) / denom) * k;
  const Vector3 c30 = cosine * a3 + k.cross(a3) + (k.dot(a3) / denom) * k;
  const double angle = xi * twist_;
  const double cs = std::cos(angle), sn = std::sin(angle);
  const Vector3 c2 = cs * c20 + sn * c30;
  const Vector3 c3 = -sn * c20 + cs * c30;
  frame.col(0) = c1;
  frame.col(1) = c2;
  frame.col(2) = c3;
  if (!derivative) return;

  // xi-derivative: centerline curvature through the transport (c1' enters
  // cosine and k) plus the linear twist rate about c1.
  const Vector3 tt = ddh[0] * xa_ + ddh[1] * length_ * a1 + ddh[2] * xb_ + ddh[3] * length_ * frameB_.col(0);
  const Vector3 dc1 = (tt - c1 * c1.dot(tt)) / tNorm;
  const double dcosine = a1.dot(dc1);
  const Vector3 dk = a1.cross(dc1);
  auto dtransport = [&](const Vector3& v) -> Vector3 {
    return dcosine * v + dk.cross(v) + ((dk.dot(v) * k + k.dot(v) * dk) / denom) -
           (k.dot(v) * dcosine / (denom * denom)) * k;
  };
  const Vector3 dc20 = dtransport(a2), dc30 = dtransport(a3);
  derivative->col(0) = dc1;
  derivative->col(1) = twist_ * c3 + cs * dc20 + sn * dc30;
  derivative->col(2) = -twist_ * c2 - sn * dc20 + cs * dc30;
}

double BeamContactGeometry::project(const Vector3& x, double xiStart) const {
  projectionFallback_ = false;
  projectionIterations_ = 0;
  if (!x.allFinite() || !xa_.allFinite() || !xb_.allFinite())
    throw OpenSeesError("projection onto the centerline failed: non-finite coordinates");
  const double L = length_;
  // R(xi) = (x - phi) . phi' and R' = (x - phi) . phi'' - phi' . phi'  (C4).
  auto residual = [&](double xi, double& R, double& dR) {
    double h[4], dh[4], ddh[4];
    hermite(xi, h, dh, ddh);
    const Vector3 a1 = L * frameA_.col(0), b1 = L * frameB_.col(0);
    const Vector3 d = x - (h[0] * xa_ + h[1] * a1 + h[2] * xb_ + h[3] * b1);
    const Vector3 t = dh[0] * xa_ + dh[1] * a1 + dh[2] * xb_ + dh[3] * b1;
    const Vector3 tt = ddh[0] * xa_ + ddh[1] * a1 + ddh[2] * xb_ + ddh[3] * b1;
    R = d.dot(t);
    dR = d.dot(tt) - t.dot(t);
  };
  const double tolerance = 1e-13 * L * L;

  // Newton from the previous projection: the usual path, a few iterations.
  double xi = std::isfinite(xiStart) ? xiStart : 0.5;
  bool converged = false;
  for (int it = 0; it < 25 && !converged; ++it) {
    double R, dR;
    residual(xi, R, dR);
    projectionIterations_ = it + 1;
    if (!std::isfinite(R) || !std::isfinite(dR) || dR >= 0.0) break;  // not heading for a minimum
    if (std::abs(R) <= tolerance) {
      converged = true;
      break;
    }
    const double step = std::clamp(-R / dR, -0.25, 0.25);
    xi += step;
    if (std::abs(step) <= 1e-13) converged = true;
    if (xi < -1.0 || xi > 2.0) break;
  }
  if (converged && xi >= 0.0 && xi <= 1.0) return xi;

  // Fallback, and the check of a Newton result beyond the segment (the
  // extrapolated cubic can have spurious minima there): the smallest sampled
  // distance on an extended range, then a bracketed Newton-bisection on R
  // (D = |x - phi|^2 has D' = -2R).
  projectionFallback_ = true;
  constexpr int samples = 80;
  constexpr double lo0 = -0.5, hi0 = 1.5;
  int best = 0;
  double bestDistance = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const double s = lo0 + (hi0 - lo0) * k / samples;
    const double dist = (x - centerline(s)).squaredNorm();
    if (k == 0 || dist < bestDistance) {
      best = k;
      bestDistance = dist;
    }
  }
  if (converged && (x - centerline(xi)).squaredNorm() <= bestDistance) return xi;
  // The closest point lies beyond the sampled range: certainly out of bounds.
  if (best == 0) return lo0;
  if (best == samples) return hi0;
  double lo = lo0 + (hi0 - lo0) * (best - 1) / samples;
  double hi = lo0 + (hi0 - lo0) * (best + 1) / samples;
  double Rlo, Rhi, dR;
  residual(lo, Rlo, dR);
  residual(hi, Rhi, dR);
  if (!(Rlo >= 0.0 && Rhi <= 0.0)) {
    // No sign change over the bracket: shrink it on the distance (golden section).
    const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int it = 0; it < 200 && hi - lo > 1e-12; ++it) {
      const double m1 = hi - ratio * (hi - lo), m2 = lo + ratio * (hi - lo);
      if ((x - centerline(m1)).squaredNorm() <= (x - centerline(m2)).squaredNorm()) hi = m2;
      else lo = m1;
    }
    xi = 0.5 * (lo + hi);
    double R;
    residual(xi, R, dR);
    if (std::abs(R) <= 1e3 * tolerance || hi - lo <= 1e-12) return xi;
    std::ostringstream os;
    os << "projection of " << format(x) << " onto the centerline did not converge (residual " << R << ")";
    throw OpenSeesError(os.str());
  }
  xi = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    double R;
    residual(xi, R, dR);
    ++projectionIterations_;
    if (std::abs(R) <= tolerance) return xi;
    if (R > 0.0) lo = xi;
    else hi = xi;
    double next = (dR < 0.0) ? xi - R / dR : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (std::abs(next - xi) <= 1e-15 || hi - lo <= 1e-15) return next;
    xi = next;
  }
  std::ostringstream os;
  os << "projection of " << format(x) << " onto the centerline did not converge in the bracket [" << lo << ", "
     << hi << "]";
  throw OpenSeesError(os.str());
}

void BeamContactGeometry::addCenterlineGradient(Vector15& B, const Vector3& e, const double h[4],
                                                double sign) const {
  // e . (h0 x_a + h1 L a1 + h2 x_b + h3 L b1) with a1 = a1n + dth_a x a1n (C2):
  // d/dth_a of e . (dth_a x a1n) is a1n x e.
  B.segment<3>(0) += (sign * h[0]) * e;
  B.segment<3>(3) += (sign * h[1] * length_) * frameA_.col(0).cross(e);
  B.segment<3>(6) += (sign * h[2]) * e;
  B.segment<3>(9) += (sign * h[3] * length_) * frameB_.col(0).cross(e);
}

void BeamContactGeometry::setProjectionData(const Node& s) {
  const Vector3 xs = position(s);
  xi_ = project(xs, xi_);
  double ddh[4];
  hermite(xi_, h_, dh_, ddh);
  centerlinePoint_ = centerline(xi_);
  tangent_ = centerlineTangent(xi_);
  tangentNorm_ = tangent_.norm();

  Matrix3 dframe;
  frameAt(xi_, frame_, &dframe);
  const Vector3 c1 = frame_.col(0), c2 = frame_.col(1), c3 = frame_.col(2);

  // Outward normal (C5), kept exactly normal to the centerline.
  const Vector3 d = xs - centerlinePoint_;
  const Vector3 dPerp = d - c1 * c1.dot(d);
  const double distance = dPerp.norm();
  if (!(distance > 1e-12 * std::max(length_, radius_)))
    throw OpenSeesError("the secondary node " + std::to_string(s.tag()) + " at " + format(xs) +
                        " lies on the beam centerline; the contact normal is undefined");
  normal_ = dPerp / distance;
  committedGap_ = normal_.dot(d) - radius_;

  // Surface point and tangent plane (C7, C8), metric and duals (C9).
  rho2_ = radius_ * normal_.dot(c2);
  rho3_ = radius_ * normal_.dot(c3);
  radial_ = rho2_ * c2 + rho3_ * c3;
  covariantBase_[0] = tangent_ + rho2_ * dframe.col(1) + rho3_ * dframe.col(2);
  covariantBase_[1] = -rho3_ * c2 + rho2_ * c3;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) metric_(i, j) = covariantBase_[i].dot(covariantBase_[j]);
  const Matrix2 inverse = metric_.inverse();
  for (int i = 0; i < 2; ++i)
    contravariantBase_[i] = inverse(i, 0) * covariantBase_[0] + inverse(i, 1) * covariantBase_[1];
  offsetN_ = d - radial_;

  // C12: B_n = -dg/dq with g = n . (x_s - x_c) - R.
  gapGradient_.setZero();
  gapGradient_.segment<3>(12) = -normal_;
  addCenterlineGradient(gapGradient_, normal_, h_, 1.0);

  // C12: s^alpha = g^alpha . (x_s - x_c - r - w x r), with the section
  // rotation increment w = twist c1 + c1 x (phi' - phi'_n)/|phi'_n|, twist =
  // c1 . ((1 - xi) dth_a + xi dth_b), so that
  // ds^alpha/dw = g^alpha x r.
  slipGradient_.setZero();
  for (int alpha = 0; alpha < 2; ++alpha) {
    Vector15 B = Vector15::Zero();
    const Vector3& gUp = contravariantBase_[alpha];
    B.segment<3>(12) = gUp;
    addCenterlineGradient(B, gUp, h_, -1.0);
    const Vector3 v = gUp.cross(radial_);
    const Vector3 p = v.cross(c1) / tangentNorm_;
    addCenterlineGradient(B, p, dh_, 1.0);
    const double vTwist = v.dot(c1);
    B.segment<3>(3) += (vTwist * (1.0 - xi_)) * c1;
    B.segment<3>(9) += (vTwist * xi_) * c1;
    slipGradient_.col(alpha) = B;
  }
}

void BeamContactGeometry::commit(const Node& a, const Node& b, const Node& s) {
  updateFrames(a, b);
  setProjectionData(s);
  update(a, b, s);
}

void BeamContactGeometry::commit(const Node& a, const Node& b, const Node& s, const Matrix3& frameA,
                                 const Matrix3& frameB) {
  setFrames(a, b, frameA, frameB);
  setProjectionData(s);
  update(a, b, s);
}

void BeamContactGeometry::update(const Node& a, const Node& b, const Node& s) {
  const Vector3 xa = position(a), xb = position(b), xs = position(s);
  const Vector3 dThetaA = rotation(a) - thetaA_, dThetaB = rotation(b) - thetaB_;
  const Vector3 a1n = frameA_.col(0), b1n = frameB_.col(0);
  // C2: linearized tangents inside the step.
  const Vector3 a1 = length_ * (a1n + dThetaA.cross(a1n));
  const Vector3 b1 = length_ * (b1n + dThetaB.cross(b1n));
  // C3 at the held xi_c.
  trialCenterlinePoint_ = h_[0] * xa + h_[1] * a1 + h_[2] * xb + h_[3] * b1;
  const Vector3 d = xs - trialCenterlinePoint_;
  gap_ = normal_.dot(d) - radius_;  // C10

  // C11: rotate the held section vectors by the trial rotation increment at
  // xi_c: linear twist plus the bending rotation of the centerline tangent.
  const Vector3 t = dh_[0] * xa + dh_[1] * a1 + dh_[2] * xb + dh_[3] * b1;
  const Vector3 c1 = frame_.col(0);
  // The twist is the c1 component of the linearly interpolated nodal rotation
  // increments, so a rigid rotation w of the whole element gives w here and
  // moves the surface point rigidly (no spurious slip).
  const double twist = c1.dot((1.0 - xi_) * dThetaA + xi_ * dThetaB);
  const Vector3 w = twist * c1 + c1.cross(t - tangent_) / tangentNorm_;
  // Relative to the commit's x_s - x_c - r (along n, so this only removes
  // the projection's round-off from the slip).
  const Vector3 dStar = d - radial_ - w.cross(radial_) - offsetN_;
  slip_(0) = contravariantBase_[0].dot(dStar);
  slip_(1) = contravariantBase_[1].dot(dStar);
}

}  // namespace beamsolid
