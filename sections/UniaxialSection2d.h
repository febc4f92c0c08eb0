#pragma once
#include <memory>

#include "sections/SectionAggregator2d.h"

namespace beamsolid {

// section('Uniaxial', tag, matTag, quantity) in a 2D model: one uniaxial
// material as a section of order 1 whose only component is quantity (P, Mz
// or Vy), e.g. a moment-rotation spring in a zeroLengthSection. It is an
// Aggregator of that one material without a base section.
class UniaxialSection2d : public SectionAggregator2d {
 public:
  UniaxialSection2d(int tag, std::unique_ptr<UniaxialMaterial> material, SectionCode code);
  std::string className() const override { return "Uniaxial"; }
  std::unique_ptr<SectionForceDeformation2d> clone() const override;
};

}  // namespace beamsolid
