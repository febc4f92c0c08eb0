#include "sections/ElasticMembranePlateSection.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

ElasticMembranePlateSection::ElasticMembranePlateSection(int tag, const Properties& p)
    : PlateSection(tag), properties_(p) {
  const double membrane = p.E * p.h / (1.0 - p.nu * p.nu);
  const double bending = membrane * p.h * p.h / 12.0;
  const double shear = 5.0 / 6.0 * p.E / (2.0 * (1.0 + p.nu)) * p.h;
  for (int block = 0; block < 2; ++block) {
    const int o = 3 * block;
    const double k = block == 0 ? membrane : bending;
    stiffness_(o, o) = stiffness_(o + 1, o + 1) = k;
    stiffness_(o, o + 1) = stiffness_(o + 1, o) = p.nu * k;
    stiffness_(o + 2, o + 2) = 0.5 * (1.0 - p.nu) * k;
  }
  stiffness_(6, 6) = stiffness_(7, 7) = shear;
}

std::unique_ptr<PlateSection> ElasticMembranePlateSection::clone() const {
  return std::make_unique<ElasticMembranePlateSection>(*this);
}

void ElasticMembranePlateSection::setTrialDeformation(const Vector8& e) {
  deformation_ = e;
  force_ = stiffness_ * e;
}

void ElasticMembranePlateSection::revertToStart() {
  committedDeformation_.setZero();
  setTrialDeformation(committedDeformation_);
}

void ElasticMembranePlateSection::print(std::ostream& os) const {
  const Properties& p = properties_;
  os << "Section " << tag() << " type ElasticMembranePlateSection E " << p.E << " nu " << p.nu << " h " << p.h
     << " rho " << p.rho << '\n';
}

namespace {

std::unique_ptr<BeamSection> buildElasticMembranePlateSection(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("secTag");
  args.setContext("section ElasticMembranePlateSection " + std::to_string(tag));
  if (domain.spaceDim() != 3) args.fail("a plate section is for shells in a 3D model (-ndm 3, -ndf 6)");
  ElasticMembranePlateSection::Properties p;
  std::size_t at = args.position();
  p.E = args.nextDouble("E");
  if (!(p.E > 0.0)) args.failAt(at, "E", "a positive number");
  at = args.position();
  p.nu = args.nextDouble("nu");
  if (!(p.nu > -1.0 && p.nu < 0.5)) args.failAt(at, "nu", "a Poisson's ratio in (-1, 0.5)");
  at = args.position();
  p.h = args.nextDouble("h");
  if (!(p.h > 0.0)) args.failAt(at, "h", "a positive thickness");
  if (!args.done()) {
    at = args.position();
    p.rho = args.nextDouble("rho");
    if (!(p.rho >= 0.0)) args.failAt(at, "rho", "a density >= 0");
  }
  args.expectEnd();
  return std::make_unique<ElasticMembranePlateSection>(tag, p);
}

void registerElasticMembranePlateSection(Registry& r) {
  r.sections.add("ElasticMembranePlateSection", &buildElasticMembranePlateSection);
}

}  // namespace

BEAMSOLID_REGISTER(registerElasticMembranePlateSection);

}  // namespace beamsolid
