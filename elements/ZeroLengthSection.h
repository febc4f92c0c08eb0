#pragma once
#include <memory>
#include <vector>

#include "elements/Element.h"
#include "sections/SectionForceDeformation.h"
#include "sections/SectionForceDeformation2d.h"

namespace beamsolid {

// element('zeroLengthSection', tag, iNode, jNode, secTag,
//         <'-orient', x1, x2, x3, yp1, yp2, yp3>, <'-doRayleigh', r>):
// a section between two nodes at the same place, driven by their relative
// displacement in local axes (x from -orient, z = x cross yp, y = z cross x;
// global by default). Each section component takes its deformation from
// one relative dof of node J against node I:
//   P: translation along x   Vy: along y   Vz: along z
//   T: rotation about x      My: about y   Mz: about z
// so a moment-curvature analysis is a rotation of node J with unit "length".
// A 2D section (order [P, Mz] or with Vy) needs a 2D model and nodes with
// ndf 3, a 3D section ([P, Mz, My, T]) a 3D model and ndf 6.
class ZeroLengthSection : public Element {
 public:
  ZeroLengthSection(int tag, int iNode, int jNode, const BeamSection& section, const Matrix3& localAxes,
                    bool doRayleigh);

  std::string className() const override { return "zeroLengthSection"; }
  bool supportsSpace(int ndm) const override { return ndm == 2 || ndm == 3; }

  void update() override;
  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // 'force'/'forces' (global end forces, numDOF), 'basicForce'/'localForce'
  // (the section's resultants), 'deformation'/'deformations'/
  // 'basicDeformation' (its deformations), 'section', *args (forwarded),
  // 'xaxis'/'yaxis'/'zaxis'.
  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

  const BeamSection& section() const { return *section_; }
  const std::vector<SectionCode>& codes() const { return codes_; }
  // The section's current deformations and resultants (in codes() order).
  Vector sectionDeformation() const;
  Vector sectionForce() const;

 protected:
  void setDomain(Domain& domain) override;

 private:
  Matrix sectionTangent(bool initial) const;

  std::unique_ptr<BeamSection> section_;
  SectionForceDeformation* section3d_ = nullptr;    // section_ as 3D, or null
  SectionForceDeformation2d* section2d_ = nullptr;  // section_ as 2D, or null
  std::vector<SectionCode> codes_;
  Matrix3 localAxes_;
  bool doRayleigh_;

  // Section deformations = gradient * element displacements.
  Matrix gradient_;
  Vector displacement_, force_;
  Matrix stiffness_, initialStiffness_;
};

}  // namespace beamsolid
