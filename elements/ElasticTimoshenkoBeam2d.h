#pragma once
#include <memory>

#include "elements/ElasticBeam2d.h"

namespace beamsolid {

class CommandArgs;

// Linear elastic 2D beam with shear deformation:
//   element('ElasticTimoshenkoBeam', tag, iNode, jNode, E, G, A, Iz, Avy, transfTag,
//           <'-mass', massPerLength>, <'-cMass'>)
// The basic stiffness of ElasticBeam2d with phi = 12 EI / (G Avy L^2). As
// OpenSees' element, it stays geometrically linear whatever the geomTransf
// (PDelta and Corotational act as Linear, joint offsets kept) and takes
// -beamUniform loads only (their fixed-end forces do not depend on phi).
class ElasticTimoshenkoBeam2d : public ElasticBeam2d {
 public:
  using ElasticBeam2d::ElasticBeam2d;

  static std::unique_ptr<Element> build(CommandArgs& args, Domain& domain, int tag, int nodeI, int nodeJ);

  std::string className() const override { return "ElasticTimoshenkoBeam"; }
  bool hasConstantTangent() const override { return true; }
  bool acceptsLoad(ElementLoad::Type type) const override { return type == ElementLoad::Type::BeamUniform; }
};

}  // namespace beamsolid
