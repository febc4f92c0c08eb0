#pragma once
#include <memory>

#include "sections/SectionAggregator3d.h"
#include "sections/SectionCode.h"

namespace beamsolid {

// section('Uniaxial', tag, matTag, quantity) in a 3D model: one uniaxial
// material for one of P, Mz, My, T. The 3D section order here is fixed
// ([P, Mz, My, T]), so the other three components have zero force and
// stiffness (as in OpenSees, where they are absent); the section's own
// responses ('force', 'deformation', 'stiffness', ...) hold its one
// component, as OpenSees'. Vy and Vz need a shear-deformable 3D section and
// are refused. Alone in a forceBeamColumn, its missing components get the
// element's regularization of a section without stiffness (a tiny fraction
// of the initial one, ForceBeamCompatibility::invert), where OpenSees fails
// to invert the flexibility; in an Aggregator ('-section') the materials give them.
class UniaxialSection3d : public SectionAggregator3d {
 public:
  UniaxialSection3d(int tag, std::unique_ptr<UniaxialMaterial> material, SectionCode code);
  std::string className() const override { return "Uniaxial"; }
  std::unique_ptr<SectionForceDeformation> clone() const override;
  Response setResponse(const std::vector<std::string>& args) override;
  SectionCode code() const { return code_; }

 private:
  SectionCode code_;
  int component_;  // index in [P, Mz, My, T]
};

}  // namespace beamsolid
