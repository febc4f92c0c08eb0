#pragma once
#include "sections/FiberSection2d.h"

namespace beamsolid {

// section('WFSection2d', tag, matTag, d, tw, bf, tf, Nfw, Nff): a wide-flange
// (I) section of depth d, web thickness tw, flange width bf and thickness tf,
// centred on y = 0, as fibers of one material: Nfw equal strips over the web
// height d - 2 tf and Nff equal strips over each flange's thickness, each
// fiber at its strip's mid-height.
class WFSection2d : public FiberSection2d {
 public:
  struct Dimensions {
    double d = 0.0, tw = 0.0, bf = 0.0, tf = 0.0;
    int webFibers = 0, flangeFibers = 0;
  };
  WFSection2d(int tag, const UniaxialMaterial& material, const Dimensions& dimensions);

  std::string className() const override { return "WFSection2d"; }
  std::unique_ptr<SectionForceDeformation2d> clone() const override;
  const Dimensions& dimensions() const { return dimensions_; }

 protected:
  // 'd', 'tw', 'bf', 'tf' (ids 1-4): parameters that move the fibers.
  int geometryParameter(const std::vector<std::string>& args) const override;
  double geometryValue(int id) const override;
  void setGeometry(int id, double value) override;

 private:
  struct Strip {
    double y, area;
  };
  // The fibers' positions and areas, top flange first (see the class comment).
  static std::vector<Strip> layout(const Dimensions& w);

  Dimensions dimensions_;
};

}  // namespace beamsolid
