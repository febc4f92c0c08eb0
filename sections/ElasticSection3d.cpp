#include "sections/ElasticSection3d.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"
#include "sections/ElasticSection2d.h"

namespace beamsolid {

ElasticSection3d::ElasticSection3d(int tag, const Properties& p) : SectionForceDeformation(tag), properties_(p) {
  stiffness_.diagonal() << p.E * p.A, p.E * p.Iz, p.E * p.Iy, p.G * p.J;
  if (p.shear) shearStiffness_ << p.alphaY * p.G * p.A, p.alphaZ * p.G * p.A;
}

std::unique_ptr<SectionForceDeformation> ElasticSection3d::clone() const {
  return std::make_unique<ElasticSection3d>(*this);
}

void ElasticSection3d::setTrialDeformation(const Vector4& e) {
  deformation_ = e;
  force_ = stiffness_.diagonal().cwiseProduct(e);
}

SectionCode ElasticSection3d::shearCode(int k) const {
  if (k < 0 || k >= numShear()) return SectionForceDeformation::shearCode(k);
  return k == 0 ? SectionCode::Vy : SectionCode::Vz;
}

void ElasticSection3d::setTrialShear(const ShearVector& gamma) {
  if (gamma.size() != numShear()) SectionForceDeformation::setTrialShear(gamma);
  if (numShear() > 0) shearDeformation_ = gamma;
}

std::vector<SectionCode> ElasticSection3d::responseCodes() const {
  if (!properties_.shear) return SectionForceDeformation::responseCodes();
  return {SectionCode::P, SectionCode::Mz, SectionCode::Vy, SectionCode::My, SectionCode::Vz, SectionCode::T};
}

void ElasticSection3d::commitState() {
  committedDeformation_ = deformation_;
  committedShear_ = shearDeformation_;
}

void ElasticSection3d::revertToLastCommit() {
  setTrialDeformation(committedDeformation_);
  shearDeformation_ = committedShear_;
}

void ElasticSection3d::revertToStart() {
  committedDeformation_.setZero();
  committedShear_.setZero();
  shearDeformation_.setZero();
  setTrialDeformation(committedDeformation_);
}

void ElasticSection3d::print(std::ostream& os) const {
  const Properties& p = properties_;
  os << "Section " << tag() << " type Elastic E " << p.E << " A " << p.A << " Iz " << p.Iz << " Iy " << p.Iy
     << " G " << p.G << " J " << p.J;
  if (p.shear) os << " alphaY " << p.alphaY << " alphaZ " << p.alphaZ;
  os << '\n';
}

namespace {

std::unique_ptr<BeamSection> buildElasticSection3d(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("secTag");
  args.setContext("section Elastic " + std::to_string(tag));
  const std::size_t numbers = args.remaining();
  if (domain.spaceDim() == 2) return ElasticSection2d::build(args, tag);
  if (numbers == 3)
    args.fail("the 2D form (E, A, Iz) needs a 2D model (-ndm 2); in 3D give E, A, Iz, Iy, G, J");
  if (numbers != 6 && numbers != 8)
    args.fail("expected E, A, Iz, Iy, G, J (6 numbers) or E, A, Iz, Iy, G, J, alphaY, alphaZ (8) after the tag, got " +
              std::to_string(numbers));
  ElasticSection3d::Properties p;
  struct Positive {
    double* value;
    const char* name;
  };
  for (const Positive& item : {Positive{&p.E, "E"}, Positive{&p.A, "A"}, Positive{&p.Iz, "Iz"},
                               Positive{&p.Iy, "Iy"}, Positive{&p.G, "G"}, Positive{&p.J, "J"}}) {
    const std::size_t at = args.position();
    *item.value = args.nextDouble(item.name);
    if (!(*item.value > 0.0)) args.failAt(at, item.name, "a positive number");
  }
  if (numbers == 8) {
    p.shear = true;
    for (const Positive& item : {Positive{&p.alphaY, "alphaY"}, Positive{&p.alphaZ, "alphaZ"}}) {
      const std::size_t at = args.position();
      *item.value = args.nextDouble(item.name);
      if (!(*item.value > 0.0)) args.failAt(at, item.name, "a positive number (shear area factor)");
    }
  }
  args.expectEnd();
  return std::make_unique<ElasticSection3d>(tag, p);
}

void registerElasticSection3d(Registry& r) { r.sections.add("Elastic", &buildElasticSection3d); }

}  // namespace

BEAMSOLID_REGISTER(registerElasticSection3d);

}  // namespace beamsolid
