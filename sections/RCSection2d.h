#pragma once
#include "sections/FiberSection2d.h"

namespace beamsolid {

// section('RCSection2d', tag, coreMatTag, coverMatTag, steelMatTag, d, b,
//         coverDepth, Atop, Abot, Aside, Nfcore, Nfcover, Nfs):
// a rectangular RC section of depth d and width b centred on y = 0, as
// fibers: the core (b - 2 c wide, d - 2 c deep) in Nfcore strips through
// the depth, the top and bottom covers (b wide, c deep) in Nfcover strips
// each, the side covers (c wide, beside the core) in Nfcore strips; Nfs bars
// of Atop at the top and of Abot at the bottom (y = +-(d/2 - c)) and Nfs - 2
// bars of Aside down each side, evenly between them. The concrete is the
// gross section (bars are not subtracted), as OpenSees (checked against its
// section stiffness).
class RCSection2d : public FiberSection2d {
 public:
  struct Definition {
    double d = 0.0, b = 0.0, cover = 0.0, areaTop = 0.0, areaBottom = 0.0, areaSide = 0.0;
    int coreFibers = 0, coverFibers = 0, bars = 0;
  };
  RCSection2d(int tag, const UniaxialMaterial& core, const UniaxialMaterial& cover, const UniaxialMaterial& steel,
              const Definition& definition);

  std::string className() const override { return "RCSection2d"; }
  std::unique_ptr<SectionForceDeformation2d> clone() const override;
  const Definition& definition() const { return definition_; }

 private:
  Definition definition_;
};

}  // namespace beamsolid
