#pragma once
#include "elements/Truss.h"

namespace beamsolid {

// element('corotTruss', tag, i, j, A, matTag, <'-rho', rho>, <'-cMass', 1>, <'-doRayleigh', 1>):
// the truss in large displacement. The strain is the engineering strain of
// the current length, (Ln - L0)/L0, so rigid rotations cause no force; the
// force acts along the current axis e and the tangent adds the geometric
// stiffness N/Ln (I - e e^T).
class CorotTruss : public Truss {
 public:
  using Truss::Truss;
  std::string className() const override { return "corotTruss"; }
  bool hasConstantTangent() const override { return false; }

 protected:
  bool largeDisplacement() const override { return true; }
};

}  // namespace beamsolid
