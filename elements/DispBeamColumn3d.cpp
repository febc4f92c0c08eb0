#include "elements/DispBeamColumn3d.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"
#include "elements/DispBeamColumn2d.h"

namespace beamsolid {

DispBeamColumn3d::DispBeamColumn3d(int tag, Definition&& definition)
    : SectionBeamColumn3d(tag, std::move(definition)) {}

Eigen::Matrix<double, 4, 6> DispBeamColumn3d::strainDisplacement(double xi, double L) {
  Eigen::Matrix<double, 4, 6> B = Eigen::Matrix<double, 4, 6>::Zero();
  B(0, 0) = 1.0 / L;
  B(1, 1) = B(2, 3) = (6.0 * xi - 4.0) / L;
  B(1, 2) = B(2, 4) = (6.0 * xi - 2.0) / L;
  B(3, 5) = 1.0 / L;
  return B;
}

void DispBeamColumn3d::initializeState() {
  initialBasicStiffness_.setZero();
  for (int i = 0; i < numSections(); ++i) {
    const Eigen::Matrix<double, 4, 6> B = strainDisplacement(xi_[i], length_);
    initialBasicStiffness_ += weights_[i] * length_ * B.transpose() * sections_[i]->initialTangent() * B;
  }
  assemble();
}

void DispBeamColumn3d::assemble() {
  sectionForce_.setZero();
  kb_.setZero();
  for (int i = 0; i < numSections(); ++i) {
    const Eigen::Matrix<double, 4, 6> B = strainDisplacement(xi_[i], length_);
    const double wL = weights_[i] * length_;
    sectionForce_.noalias() += wL * B.transpose() * sections_[i]->force();
    kb_.noalias() += wL * B.transpose() * sections_[i]->tangent() * B;
  }
}

void DispBeamColumn3d::update() {
  transf_->update();
  const Vector6 v = transf_->basicTrialDisp();
  for (int i = 0; i < numSections(); ++i)
    sections_[i]->setTrialDeformation(strainDisplacement(xi_[i], length_) * v);
  assemble();
}

void DispBeamColumn3d::commitState() {
  transf_->commitState();
  for (auto& s : sections_) s->commitState();
}

void DispBeamColumn3d::revertToLastCommit() {
  transf_->revertToLastCommit();
  for (auto& s : sections_) s->revertToLastCommit();
  assemble();
}

void DispBeamColumn3d::revertToStart() {
  transf_->revertToStart();
  for (auto& s : sections_) s->revertToStart();
  assemble();
}

void DispBeamColumn3d::zeroLoad() {
  q0_.setZero();
  zeroLoadReactions();
}

void DispBeamColumn3d::addLoad(const ElementLoad& load, double factor) {
  const BeamLoad l = readLoad(load, factor);
  addLoadReactions(l);
  const double L = length_;
  // Consistent loads of the Hermite and linear fields, which are the
  // fixed-end forces of a prismatic elastic member.
  if (l.uniform) {
    q0_[0] -= 0.5 * l.wx * L;
    const double mz = l.wy * L * L / 12.0;
    const double my = l.wz * L * L / 12.0;
    q0_[1] -= mz;
    q0_[2] += mz;
    q0_[3] += my;
    q0_[4] -= my;
  } else {
    const double a = l.a, b = L - l.a;
    q0_[0] -= l.px * a / L;
    const double atI = a * b * b / (L * L);
    const double atJ = a * a * b / (L * L);
    q0_[1] -= l.py * atI;
    q0_[2] += l.py * atJ;
    q0_[3] += l.pz * atI;
    q0_[4] -= l.pz * atJ;
  }
}

namespace {

std::unique_ptr<Element> buildDispBeamColumn3d(CommandArgs& args, Domain& domain) {
  if (domain.spaceDim() == 2) return DispBeamColumn2d::build(args, domain);
  auto d = SectionBeamColumn3d::parse(args, domain, "dispBeamColumn", BeamIntegration::Rule::Legendre, false);
  const int tag = d.tag;
  return std::make_unique<DispBeamColumn3d>(tag, std::move(d));
}

void registerDispBeamColumn3d(Registry& r) { r.elements.add("dispBeamColumn", &buildDispBeamColumn3d); }

}  // namespace

BEAMSOLID_REGISTER(registerDispBeamColumn3d);

}  // namespace beamsolid
