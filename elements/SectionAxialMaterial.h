#pragma once
#include <memory>
#include <string>

#include "materials/uniaxial/UniaxialMaterial.h"
#include "sections/BeamSection.h"
#include "sections/SectionForceDeformation.h"
#include "sections/SectionForceDeformation2d.h"

namespace beamsolid {

// A beam section seen through its axial component alone, as the uniaxial
// "material" of a section truss: the strain sets the section's axial strain
// (every other deformation stays zero), the stress is the section's axial
// force P and the tangent d P / d eps. A fiber section is referred to its
// centroid, so an eccentric one still carries P without bending.
class SectionAxialMaterial : public UniaxialMaterial {
 public:
  // An OpenSeesError naming `context` when the section has no axial (P) component.
  SectionAxialMaterial(const BeamSection& section, const std::string& context);
  SectionAxialMaterial(const SectionAxialMaterial& other);

  std::string className() const override { return "sectionAxial"; }
  std::unique_ptr<UniaxialMaterial> clone() const override {
    return std::make_unique<SectionAxialMaterial>(*this);
  }

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return strain_; }
  double stress() const override;
  double tangent() const override;
  double initialTangent() const override;

  void commitState() override {
    section_->commitState();
    committedStrain_ = strain_;
  }
  void revertToLastCommit() override;
  void revertToStart() override;

  // The section's own responses ('force', 'deformation', 'stiffness', 'fiber' ...).
  Response setResponse(const std::vector<std::string>& args) override { return section_->setResponse(args); }
  bool setParameter(const std::vector<std::string>& args, double value) override;

  const BeamSection& section() const { return *section_; }

 private:
  void bind();

  std::unique_ptr<BeamSection> section_;
  SectionForceDeformation* section3d_ = nullptr;    // section_ as 3D, or null
  SectionForceDeformation2d* section2d_ = nullptr;  // section_ as 2D, or null
  int axialIndex_ = 0;                              // where P is in the 2D section's order
  double strain_ = 0.0;
  double committedStrain_ = 0.0;
};

}  // namespace beamsolid
