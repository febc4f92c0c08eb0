#pragma once
#include "elements/Truss.h"

namespace beamsolid {

class BeamSection;
class CommandArgs;
class Domain;

// element('TrussSection', tag, i, j, secTag, <'-rho', rho>, <'-cMass', 1>, <'-doRayleigh', 1>),
// also element('Truss', tag, i, j, secTag, ...) (no area before the tag):
// the truss with a section instead of an area and a uniaxial material. The
// bar's strain is the section's axial strain (curvatures held at zero) and
// its axial force the section's P, so N = P(eps) and the axial stiffness
// is dP/deps / L. Mass as the truss: rho per unit length, lumped or consistent.
class TrussSection : public Truss {
 public:
  TrussSection(int tag, int iNode, int jNode, const BeamSection& section, double rho, bool consistentMass,
               bool doRayleigh, const std::string& context);

  std::string className() const override { return "trussSection"; }
  // No area to change: 'A' is refused; 'rho' and the section's parameters are taken.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void print(std::ostream& os) const override;

  // The section form of the truss command: after the nodes, a single
  // integer (the section tag), alone or before the options.
  static bool isSectionForm(const CommandArgs& args);
  static std::unique_ptr<Element> build(CommandArgs& args, Domain& domain, int tag, int iNode, int jNode);
};

}  // namespace beamsolid
