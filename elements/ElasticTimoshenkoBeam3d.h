#pragma once
#include <memory>

#include "elements/ElasticBeam3d.h"

namespace beamsolid {

class CommandArgs;

// Linear elastic 3D beam with shear deformation:
//   element('ElasticTimoshenkoBeam', tag, iNode, jNode, E, G, A, Jx, Iy, Iz, Avy, Avz, transfTag,
//           <'-mass', massPerLength>, <'-cMass'>)
// ElasticBeam3d's basic stiffness with phi = 12 E Iz / (G Avy L^2) for
// bending about z and 12 E Iy / (G Avz L^2) about y. Geometrically linear
// whatever the geomTransf, as OpenSees' element; its lumped mass has no
// torsional inertia; -beamUniform loads only.
class ElasticTimoshenkoBeam3d : public ElasticBeam3d {
 public:
  using ElasticBeam3d::ElasticBeam3d;

  static std::unique_ptr<Element> build(CommandArgs& args, Domain& domain, int tag, int nodeI, int nodeJ);

  std::string className() const override { return "ElasticTimoshenkoBeam"; }
  bool hasConstantTangent() const override { return true; }
  bool acceptsLoad(ElementLoad::Type type) const override { return type == ElementLoad::Type::BeamUniform; }
};

}  // namespace beamsolid
