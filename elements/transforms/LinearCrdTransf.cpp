#include "elements/transforms/LinearCrdTransf.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/transforms/LinearCrdTransf2d.h"

namespace beamsolid {

namespace {

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

}  // namespace

LinearCrdTransf::LinearCrdTransf(int tag, const Vector3& vecxz, const Vector3& jointOffsetI,
                                 const Vector3& jointOffsetJ)
    : CrdTransf(tag), vecxz_(vecxz), offsetI_(jointOffsetI), offsetJ_(jointOffsetJ) {}

std::unique_ptr<CrdTransf> LinearCrdTransf::clone() const {
  return std::make_unique<LinearCrdTransf>(tag(), vecxz_, offsetI_, offsetJ_);
}

std::string LinearCrdTransf::context() const { return "geomTransf " + className() + " " + std::to_string(tag()); }

void LinearCrdTransf::initialize(const Node& nodeI, const Node& nodeJ) {
  for (const Node* n : {&nodeI, &nodeJ})
    if (n->ndf() != 6)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs, a 3D beam needs 6");
  nodeI_ = &nodeI;
  nodeJ_ = &nodeJ;

  const Vector3 endI = nodeI.crd() + offsetI_;
  const Vector3 endJ = nodeJ.crd() + offsetJ_;
  const Vector3 chord = endJ - endI;
  length_ = chord.norm();
  const bool offsets = offsetI_.norm() > 0.0 || offsetJ_.norm() > 0.0;
  // Relative to the coordinates' size, so a tiny but real element in a model
  // far from the origin is still accepted.
  if (length_ == 0.0 || length_ <= 1e-12 * std::max(endI.norm(), endJ.norm()))
    throw OpenSeesError(context() + ": element has zero length: the ends at node " + std::to_string(nodeI.tag()) +
                        " " + format(endI) + " and node " + std::to_string(nodeJ.tag()) + " " + format(endJ) +
                        " coincide" + (offsets ? " (after joint offsets)" : ""));

  const Vector3 x = chord / length_;
  Vector3 y = vecxz_.cross(x);
  // vecxz only fixes a plane when it is not along the axis.
  if (y.norm() <= 1e-10 * vecxz_.norm())
    throw OpenSeesError(context() + ": vecxz " + format(vecxz_) + " is parallel to the element axis " + format(x) +
                        " from node " + std::to_string(nodeI.tag()) + " to node " + std::to_string(nodeJ.tag()) +
                        "; choose a vecxz that is not parallel to the element");
  y.normalize();
  const Vector3 z = x.cross(y);
  axes_.row(0) = x.transpose();
  axes_.row(1) = y.transpose();
  axes_.row(2) = z.transpose();

  // Local end displacement = R (u + theta x offset), local rotation = R theta.
  localFromGlobal_.setZero();
  for (int k = 0; k < 4; ++k) localFromGlobal_.block<3, 3>(3 * k, 3 * k) = axes_;
  localFromGlobal_.block<3, 3>(0, 3) = -axes_ * skew(offsetI_);
  localFromGlobal_.block<3, 3>(6, 9) = -axes_ * skew(offsetJ_);

  // Basic deformations from local end displacements (see CrdTransf.h).
  Eigen::Matrix<double, 6, 12> a = Eigen::Matrix<double, 6, 12>::Zero();
  const double invL = 1.0 / length_;
  a(0, 0) = -1.0;
  a(0, 6) = 1.0;
  a(1, 5) = 1.0;
  a(1, 1) = invL;
  a(1, 7) = -invL;
  a(2, 11) = 1.0;
  a(2, 1) = invL;
  a(2, 7) = -invL;
  a(3, 4) = 1.0;
  a(3, 2) = -invL;
  a(3, 8) = invL;
  a(4, 10) = 1.0;
  a(4, 2) = -invL;
  a(4, 8) = invL;
  a(5, 3) = -1.0;
  a(5, 9) = 1.0;
  basicFromGlobal_ = a * localFromGlobal_;

  update();
  basicIncrDelta_.setZero();
}

LinearCrdTransf::Vector12 LinearCrdTransf::globalTrialDisp() const {
  Vector12 u;
  u.head<6>() = nodeI_->trialDisp();
  u.tail<6>() = nodeJ_->trialDisp();
  return u;
}

LinearCrdTransf::Vector12 LinearCrdTransf::globalCommittedDisp() const {
  Vector12 u;
  u.head<6>() = nodeI_->committedDisp();
  u.tail<6>() = nodeJ_->committedDisp();
  return u;
}

void LinearCrdTransf::update() {
  if (!nodeI_) throw OpenSeesError(context() + ": update() before initialize()");
  const Vector12 u = globalTrialDisp();
  localTrial_ = localFromGlobal_ * u;
  const Vector6 basic = basicFromGlobal_ * u;
  basicIncrDelta_ = basic - basicTrial_;
  basicTrial_ = basic;
  basicIncr_ = basicFromGlobal_ * (u - globalCommittedDisp());
}

void LinearCrdTransf::revertToStart() {
  localTrial_.setZero();
  basicTrial_.setZero();
  basicIncr_.setZero();
  basicIncrDelta_.setZero();
}

LinearCrdTransf::Vector12 LinearCrdTransf::basicToLocal(const Vector6& q, const Vector12& p0) const {
  return CrdTransf::basicToLocal(q, p0, length_);
}

LinearCrdTransf::Vector12 LinearCrdTransf::localResistingForce(const Vector6& q, const Vector12& p0) const {
  return basicToLocal(q, p0);
}

LinearCrdTransf::Vector12 LinearCrdTransf::globalResistingForce(const Vector6& q, const Vector12& p0) const {
  return localFromGlobal_.transpose() * basicToLocal(q, p0);
}

LinearCrdTransf::Matrix12 LinearCrdTransf::globalStiffMatrix(const Matrix6& kb, const Vector6&) const {
  return initialGlobalStiffMatrix(kb);
}

LinearCrdTransf::Matrix12 LinearCrdTransf::initialGlobalStiffMatrix(const Matrix6& kb) const {
  const Eigen::Matrix<double, 6, 12> kbA = kb * basicFromGlobal_;
  return basicFromGlobal_.transpose() * kbA;
}

void LinearCrdTransf::print(std::ostream& os) const {
  os << context() << ": vecxz " << format(vecxz_);
  if (offsetI_.norm() > 0.0 || offsetJ_.norm() > 0.0)
    os << ", jntOffset I " << format(offsetI_) << " J " << format(offsetJ_);
  if (nodeI_)
    os << ", L " << length_ << ", local x " << format(axes_.row(0).transpose()) << " y "
       << format(axes_.row(1).transpose()) << " z " << format(axes_.row(2).transpose());
  os << '\n';
}

std::unique_ptr<CrdTransf2d> CrdTransf::planar() const { return nullptr; }

std::unique_ptr<CrdTransf2d> LinearCrdTransf::planar() const {
  return std::make_unique<LinearCrdTransf2d>(tag(), offsetI_.head<2>(), offsetJ_.head<2>());
}

LinearCrdTransf::Definition LinearCrdTransf::parse(CommandArgs& args, const std::string& type, int ndm) {
  Definition d;
  d.tag = args.nextInt("transfTag");
  args.setContext("geomTransf " + type + " " + std::to_string(d.tag));
  if (ndm == 2) {
    // The plane is x-y: local z is global Z, so vecxz = Z.
    d.vecxz = Vector3::UnitZ();
    if (args.nextIsNumber())
      args.fail("vecxz is for 3D models; in a 2D model (-ndm 2) give geomTransf('" + type +
                "', tag, <'-jntOffset', dXi, dYi, dXj, dYj>)");
    while (!args.done()) {
      if (args.nextFlag("-jntOffset")) {
        const std::vector<double> off = args.nextDoubles("jntOffset");
        if (off.size() != 4)
          args.fail("-jntOffset needs 4 numbers in 2D (dXi, dYi, dXj, dYj), got " + std::to_string(off.size()));
        d.jointOffsetI = Vector3(off[0], off[1], 0.0);
        d.jointOffsetJ = Vector3(off[2], off[3], 0.0);
      } else if (args.nextIsString()) {
        args.fail("unknown option '" + *args.peekString() + "' (expected '-jntOffset')");
      } else {
        args.expectEnd();
      }
    }
    return d;
  }
  if (ndm != 3) args.fail("beam transformations need a 2D or 3D model, this one has -ndm " + std::to_string(ndm));
  const char* names[3] = {"vecxzX", "vecxzY", "vecxzZ"};
  for (int k = 0; k < 3; ++k) {
    if (!args.nextIsNumber())
      args.failAt(args.position(), names[k], "a number (3D beams need vecxz = vecxzX, vecxzY, vecxzZ after the tag)");
    d.vecxz[k] = args.nextDouble(names[k]);
  }
  if (d.vecxz.norm() == 0.0) args.fail("vecxz is the zero vector; it must span the local x-z plane with the axis");
  while (!args.done()) {
    if (args.nextFlag("-jntOffset")) {
      const std::vector<double> off = args.nextDoubles("jntOffset");
      if (off.size() != 6)
        args.fail("-jntOffset needs 6 numbers (dXi, dYi, dZi, dXj, dYj, dZj), got " + std::to_string(off.size()));
      d.jointOffsetI = Vector3(off[0], off[1], off[2]);
      d.jointOffsetJ = Vector3(off[3], off[4], off[5]);
    } else if (args.nextIsString()) {
      args.fail("unknown option '" + *args.peekString() + "' (expected '-jntOffset')");
    } else {
      args.expectEnd();
    }
  }
  return d;
}

namespace {

std::unique_ptr<CrdTransf> buildLinearCrdTransf(CommandArgs& args, Domain& domain) {
  const auto d = LinearCrdTransf::parse(args, "Linear", domain.spaceDim());
  return std::make_unique<LinearCrdTransf>(d.tag, d.vecxz, d.jointOffsetI, d.jointOffsetJ);
}

void registerLinearCrdTransf(Registry& r) { r.geomTransfs.add("Linear", &buildLinearCrdTransf); }

}  // namespace

BEAMSOLID_REGISTER(registerLinearCrdTransf);

}  // namespace beamsolid
