#include "elements/transforms/PDeltaCrdTransf.h"

#include "core/Domain.h"
#include "core/Registry.h"
#include "elements/transforms/PDeltaCrdTransf2d.h"

namespace beamsolid {

std::unique_ptr<CrdTransf> PDeltaCrdTransf::clone() const {
  return std::make_unique<PDeltaCrdTransf>(tag(), vecxz(), jointOffsetI(), jointOffsetJ());
}

std::unique_ptr<CrdTransf2d> PDeltaCrdTransf::planar() const {
  return std::make_unique<PDeltaCrdTransf2d>(tag(), jointOffsetI().head<2>(), jointOffsetJ().head<2>());
}

PDeltaCrdTransf::Vector12 PDeltaCrdTransf::chordShear(double axialForce) const {
  const Vector12& u = localTrialDisp();
  const double factor = axialForce / initialLength();
  const double shearY = factor * (u[7] - u[1]);
  const double shearZ = factor * (u[8] - u[2]);
  Vector12 p = Vector12::Zero();
  p[1] = -shearY;
  p[7] = shearY;
  p[2] = -shearZ;
  p[8] = shearZ;
  return p;
}

PDeltaCrdTransf::Vector12 PDeltaCrdTransf::localResistingForce(const Vector6& q, const Vector12& p0) const {
  return basicToLocal(q, p0) + chordShear(q[0]);
}

PDeltaCrdTransf::Vector12 PDeltaCrdTransf::globalResistingForce(const Vector6& q, const Vector12& p0) const {
  return localFromGlobal().transpose() * localResistingForce(q, p0);
}

PDeltaCrdTransf::Matrix12 PDeltaCrdTransf::globalStiffMatrix(const Matrix6& kb, const Vector6& q) const {
  // Geometric stiffness N/L (e_j - e_i)(e_j - e_i)^T for v and w, mapped to
  // global dofs through the rows of the local-from-global matrix.
  const Matrix12& t = localFromGlobal();
  const Vector12 dv = (t.row(7) - t.row(1)).transpose();
  const Vector12 dw = (t.row(8) - t.row(2)).transpose();
  const double factor = q[0] / initialLength();
  Matrix12 k = initialGlobalStiffMatrix(kb);
  k.noalias() += factor * (dv * dv.transpose() + dw * dw.transpose());
  return k;
}

namespace {

std::unique_ptr<CrdTransf> buildPDeltaCrdTransf(CommandArgs& args, Domain& domain) {
  const auto d = LinearCrdTransf::parse(args, "PDelta", domain.spaceDim());
  return std::make_unique<PDeltaCrdTransf>(d.tag, d.vecxz, d.jointOffsetI, d.jointOffsetJ);
}

void registerPDeltaCrdTransf(Registry& r) { r.geomTransfs.add("PDelta", &buildPDeltaCrdTransf); }

}  // namespace

BEAMSOLID_REGISTER(registerPDeltaCrdTransf);

}  // namespace beamsolid
