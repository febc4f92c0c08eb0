#include "elements/TrussSection.h"

#include <variant>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"
#include "elements/SectionAxialMaterial.h"
#include "sections/BeamSection.h"

namespace beamsolid {

TrussSection::TrussSection(int tag, int iNode, int jNode, const BeamSection& section, double rho,
                           bool consistentMass, bool doRayleigh, const std::string& context)
    // Unit area: the axial "stress" of the section material is the force P itself.
    : Truss(tag, iNode, jNode, 1.0, SectionAxialMaterial(section, context), rho, consistentMass, doRayleigh) {}

bool TrussSection::setParameter(const std::vector<std::string>& args, double value) {
  if (!args.empty() && args[0] == "A") return false;
  return Truss::setParameter(args, value);
}

void TrussSection::print(std::ostream& os) const {
  os << "Element " << tag() << " type " << className() << " nodes " << nodeTags()[0] << ' ' << nodeTags()[1]
     << " section " << material().tag() << '\n';
}

bool TrussSection::isSectionForm(const CommandArgs& args) {
  // truss: A, matTag, options; section truss: secTag, options. The area form
  // has a number where the section form has the end or an option flag, and
  // a tag is an integer (truss(..., 1.0) is an area with its material missing).
  const std::size_t at = args.position();
  return at < args.size() && std::holds_alternative<long long>(args.at(at)) &&
         (at + 1 >= args.size() || std::holds_alternative<std::string>(args.at(at + 1)));
}

std::unique_ptr<Element> TrussSection::build(CommandArgs& args, Domain& domain, int tag, int iNode, int jNode) {
  const int secTag = args.nextInt("secTag");
  double rho = 0.0;
  bool consistentMass = false, doRayleigh = false;
  while (!args.done()) {
    if (args.nextFlag("-rho")) rho = args.nextDouble("rho");
    else if (args.nextFlag("-cMass")) consistentMass = args.nextInt("cFlag") != 0;
    else if (args.nextFlag("-doRayleigh")) doRayleigh = args.nextInt("rFlag") != 0;
    else args.failAt(args.position(), "option", "'-rho', '-cMass' or '-doRayleigh'");
  }
  const BeamSection& section = domain.sections.get(secTag, args.context());
  return std::make_unique<TrussSection>(tag, iNode, jNode, section, rho, consistentMass, doRayleigh, args.context());
}

namespace {

std::unique_ptr<Element> buildTrussSection(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element TrussSection " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  return TrussSection::build(args, domain, tag, iNode, jNode);
}

void registerTrussSection(Registry& r) {
  r.elements.add("TrussSection", &buildTrussSection);
  r.elements.add("trussSection", &buildTrussSection);
}

}  // namespace

BEAMSOLID_REGISTER(registerTrussSection);

}  // namespace beamsolid
