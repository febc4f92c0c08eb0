#include "elements/contact/ZeroLengthContact3D.h"

#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/contact/ContactSupport.h"

namespace beamsolid {

namespace {

// ContactMaterial3D needs G > 0; with Kt = 0 the element never asks it.
double frictionStiffness(double Kt) { return Kt > 0.0 ? Kt : 1.0; }

}  // namespace

ZeroLengthContact3D::ZeroLengthContact3D(int tag, int cNode, int rNode, double Kn, double Kt, double mu, double c,
                                         int direction, const Vector2& origin)
    : Element(tag, {cNode, rNode}),
      Kn_(Kn),
      Kt_(Kt),
      mu_(mu),
      c_(c),
      direction_(direction),
      origin_(origin),
      friction_(0, std::isfinite(mu) && mu >= 0.0 ? mu : 0.0, frictionStiffness(Kt),
                std::isfinite(c) && c >= 0.0 ? c : 0.0, 0.0) {
  auto require = [this](bool ok, const char* what, const char* expected, double value) {
    if (!ok)
      throw OpenSeesError(context() + ": " + what + " must be " + expected + ", got " + std::to_string(value));
  };
  require(Kn > 0.0 && std::isfinite(Kn), "Kn", "positive", Kn);
  require(Kt >= 0.0 && std::isfinite(Kt), "Kt", "a number >= 0", Kt);
  require(mu >= 0.0 && std::isfinite(mu), "mu", "a number >= 0", mu);
  require(c >= 0.0 && std::isfinite(c), "c", "a number >= 0", c);
  if (direction < 0 || direction > 3)
    throw OpenSeesError(context() + ": dir must be 0 (radial from originX originY), 1, 2 or 3 (normal +X, +Y, +Z), got " +
                        std::to_string(direction));
}

void ZeroLengthContact3D::setDomain(Domain&) {
  requireNodeDofs(*nodes()[0], 3, "constrained node", context());
  requireNodeDofs(*nodes()[1], 3, "retained node", context());
  const Vector3& Xc = nodes()[0]->crd();
  const Vector3& Xr = nodes()[1]->crd();
  if (direction_ > 0) {
    const int a = direction_ - 1;
    normal_ = Vector3::Unit(a);
    tangents_.row(0) = Vector3::Unit((a + 1) % 3).transpose();
    tangents_.row(1) = Vector3::Unit((a + 2) % 3).transpose();
    gap0_ = normal_.dot(Xc - Xr);
  } else {
    const Eigen::Vector2d rr = Xr.head<2>() - origin_;
    const Eigen::Vector2d rc = Xc.head<2>() - origin_;
    const double Rr = rr.norm();
    if (!(Rr > 1e-12 * (1.0 + origin_.norm())))
      throw OpenSeesError(context() + ": dir 0 (radial) needs the retained node " + std::to_string(nodes()[1]->tag()) +
                          " off the axis through originX, originY = " + std::to_string(origin_(0)) + ", " +
                          std::to_string(origin_(1)));
    const Eigen::Vector2d er = rr / Rr;
    normal_ = Vector3(-er(0), -er(1), 0.0);  // the retained surface faces the axis
    tangents_.row(0) = Vector3(-er(1), er(0), 0.0).transpose();
    tangents_.row(1) = Vector3::UnitZ().transpose();
    gap0_ = Rr - rc.norm();
  }
  formInitialStiffness();
  revertToStart();
}

void ZeroLengthContact3D::formInitialStiffness() {
  const Matrix3 k = Kn_ * normal_ * normal_.transpose() + Kt_ * tangents_.transpose() * tangents_;
  initialStiffness_ << k, -k, -k, k;
}

void ZeroLengthContact3D::update() {
  const Vector3 du = nodes()[0]->trialDisp().head<3>() - nodes()[1]->trialDisp().head<3>();
  gap_ = gap0_ + normal_.dot(du);
  normalForce_ = gap_ < 0.0 ? -Kn_ * gap_ : 0.0;
  slip_ = tangents_ * du;

  Vector3 f = -normalForce_ * normal_;  // resisting force at the constrained node
  Matrix3 k = Matrix3::Zero();
  if (normalForce_ > 0.0) k += Kn_ * normal_ * normal_.transpose();
  if (Kt_ > 0.0) {
    friction_.setIterate(gap_, slip_ - committedSlip_, normalForce_, Eigen::Matrix2d::Identity());
    f += tangents_.transpose() * friction_.traction();
    k += tangents_.transpose() * friction_.tangentSlip() * tangents_;
    // dF_t/dN dN/d(du) with dN/d(du) = -Kn n^T in contact.
    if (normalForce_ > 0.0) k -= Kn_ * tangents_.transpose() * friction_.tangentNormal() * normal_.transpose();
  }
  force_ << f, -f;
  stiffness_ << k, -k, -k, k;
}

void ZeroLengthContact3D::commitState() {
  friction_.commitState();
  committedSlip_ = slip_;
}

void ZeroLengthContact3D::revertToLastCommit() {
  // The Domain updates the elements afterwards from the reverted displacements.
  friction_.revertToLastCommit();
}

void ZeroLengthContact3D::revertToStart() {
  friction_.revertToStart();
  committedSlip_.setZero();
  update();
}

ZeroLengthContact3D::Vector2 ZeroLengthContact3D::frictionComponents() const {
  return Kt_ > 0.0 ? friction_.traction() : Vector2::Zero();
}

ZeroLengthContact3D::Status ZeroLengthContact3D::status() const {
  if (!(normalForce_ > 0.0)) return Status::Open;
  return Kt_ > 0.0 && friction_.sliding() ? Status::Slide : Status::Stick;
}

Response ZeroLengthContact3D::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string what = lowerCase(args[0]);
  if (what == "force" || what == "forces" || what == "globalforce" || what == "globalforces")
    return Response::named({"P1_1", "P1_2", "P1_3", "P2_1", "P2_2", "P2_3"},
                           [this] { return withoutNegativeZeros(Vector(force_)); });
  if (what == "gap") return Response::named({"gap"}, [this] { return vectorOf({gap_}); });
  if (what == "status")
    return Response::named({"status"}, [this] { return vectorOf({double(static_cast<int>(status()))}); });
  if (what == "normalforce") return Response::named({"N"}, [this] { return vectorOf({normalForce_}); });
  if (what == "frictionforce")
    return Response::named({"Fx", "Fy", "Fz"}, [this] {
      return withoutNegativeZeros(Vector(tangents_.transpose() * frictionComponents()));
    });
  if (what == "contactforce")
    return Response::named({"Fx", "Fy", "Fz"}, [this] { return withoutNegativeZeros(Vector(force_.head<3>())); });
  if (what == "forcescalar")
    return Response::named({"N", "T1", "T2"}, [this] {
      const Vector2 t = frictionComponents();
      return withoutNegativeZeros(vectorOf({normalForce_, t(0), t(1)}));
    });
  if (what == "normal") return Response::named({"nx", "ny", "nz"}, [this] { return withoutNegativeZeros(normal_); });
  if (what == "deformation" || what == "deformations")
    return Response::named({"gap", "s1", "s2"},
                           [this] { return withoutNegativeZeros(vectorOf({gap_, slip_(0), slip_(1)})); });
  if (what == "slip") return Response::named({"s1", "s2"}, [this] { return withoutNegativeZeros(Vector(slip_)); });
  return {};
}

bool ZeroLengthContact3D::setParameter(const std::vector<std::string>& args, double value) {
  if (args.empty()) return false;
  const std::string& name = args[0];
  try {
    if (name == "friction" || name == "frictionalState") return friction_.setParameter({"friction"}, value);
    if (name == "mu" || name == "frictionCoefficient") {
      friction_.setParameter({"mu"}, value);
      mu_ = value;
      return true;
    }
    if (name == "c" || name == "cohesion") {
      friction_.setParameter({"c"}, value);
      c_ = value;
      return true;
    }
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
  if (name == "Kn" || name == "Kt") {
    const bool normal = name == "Kn";
    if (!std::isfinite(value) || (normal ? !(value > 0.0) : !(value >= 0.0)))
      throw OpenSeesError(context() + ": " + name + " must be " + (normal ? "positive" : "a number >= 0") + ", got " +
                          std::to_string(value));
    if (normal) {
      Kn_ = value;
    } else {
      if (value > 0.0) friction_.setParameter({"G"}, value);
      Kt_ = value;
    }
    formInitialStiffness();
    return true;
  }
  return false;
}

void ZeroLengthContact3D::print(std::ostream& os) const {
  os << context() << ": constrained node " << nodeTags()[0] << ", retained node " << nodeTags()[1] << ", Kn " << Kn_
     << ", Kt " << Kt_ << ", mu " << mu_ << ", c " << c_ << ", dir " << direction_;
  if (direction_ == 0) os << " (origin " << origin_(0) << ", " << origin_(1) << ')';
  os << ", normal (" << normal_.transpose() << "), gap " << gap_ << ", status " << static_cast<int>(status())
     << '\n';
}

namespace {

std::unique_ptr<Element> buildZeroLengthContact3D(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element zeroLengthContact3D " + std::to_string(tag));
  const int cNode = args.nextInt("cNode");
  const int rNode = args.nextInt("rNode");
  const double Kn = readPositive(args, "Kn");
  const double Kt = readNonNegative(args, "Kt");
  const double mu = readNonNegative(args, "mu");
  const double c = readNonNegative(args, "c");
  const std::size_t dirAt = args.position();
  const int dir = args.nextInt("dir");
  if (dir < 0 || dir > 3)
    args.failAt(dirAt, "dir", "0 (radial from originX originY), 1, 2 or 3 (normal +X, +Y, +Z)");
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  if (dir == 0 && !args.done()) {
    origin(0) = args.nextDouble("originX");
    origin(1) = args.nextDouble("originY");
  }
  if (!args.done())
    args.failAt(args.position(), "end of arguments",
                dir == 0 ? "nothing after originX originY" : "nothing after dir (originX originY only with dir 0)");
  return std::make_unique<ZeroLengthContact3D>(tag, cNode, rNode, Kn, Kt, mu, c, dir, origin);
}

void registerZeroLengthContact3D(Registry& r) { r.elements.add("zeroLengthContact3D", &buildZeroLengthContact3D); }

}  // namespace

BEAMSOLID_REGISTER(registerZeroLengthContact3D);

}  // namespace beamsolid
