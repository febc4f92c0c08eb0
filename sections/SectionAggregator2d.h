#pragma once
#include <memory>
#include <vector>

#include "materials/uniaxial/UniaxialMaterial.h"
#include "sections/SectionForceDeformation2d.h"

namespace beamsolid {

class CommandArgs;
class Domain;

// section('Aggregator', tag, matTag1, code1, ..., <'-section', secTag>) in a
// 2D model: uncoupled uniaxial responses (each a copy of a material, driven
// by one section deformation) added to an optional 2D section. As OpenSees,
// the components are the section's first, then the materials' in the order
// given; codes are P, Mz and Vy, each at most once, at most 3 in all.
class SectionAggregator2d : public SectionForceDeformation2d {
 public:
  SectionAggregator2d(int tag, std::unique_ptr<SectionForceDeformation2d> section,
                      std::vector<std::unique_ptr<UniaxialMaterial>> materials, std::vector<SectionCode> materialCodes);
  SectionAggregator2d(const SectionAggregator2d& other);
  SectionAggregator2d& operator=(const SectionAggregator2d&) = delete;

  static std::unique_ptr<SectionAggregator2d> build(CommandArgs& args, Domain& domain, int tag);

  std::string className() const override { return "Aggregator"; }
  std::unique_ptr<SectionForceDeformation2d> clone() const override;
  const std::vector<SectionCode>& codes() const override { return codes_; }

  void setTrialDeformation(const Vector& e) override;
  const Vector& deformation() const override { return deformation_; }
  const Vector& force() const override { return force_; }
  const Matrix& tangent() const override { return tangent_; }
  const Matrix& initialTangent() const override { return initialTangent_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // Besides the base responses, anything else goes to the aggregated section.
  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

 private:
  int sectionOrder() const { return section_ ? section_->order() : 0; }
  void assemble(bool initial);

  std::unique_ptr<SectionForceDeformation2d> section_;
  std::vector<std::unique_ptr<UniaxialMaterial>> materials_;
  std::vector<SectionCode> codes_;
  Vector deformation_, committedDeformation_, force_;
  Matrix tangent_, initialTangent_;
};

}  // namespace beamsolid
