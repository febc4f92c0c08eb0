#pragma once
#include <array>
#include <memory>
#include <vector>

#include "materials/uniaxial/UniaxialMaterial.h"
#include "sections/SectionCode.h"
#include "sections/SectionForceDeformation.h"

namespace beamsolid {

// section('Aggregator', tag, matTag1, code1, ..., <'-section', secTag>) in a
// 3D model. The 3D section order is fixed ([P, Mz, My, T]), so a material
// takes over its component: with '-section' the section answers the others
// (the common use: 'T' giving a fiber section its torsion in place of its
// GJ); without it the materials must give all of P, Mz, My and T. OpenSees
// appends the materials instead, which differs only when a code repeats one
// of the section's (its torsion then acts in series in a force-based
// element). Vy and Vz (each at most once) are appended after [P, Mz, My, T]
// in the order given, as OpenSees reports them: shear components for a
// forceBeamColumn (see SectionForceDeformation::numShear). A '-section'
// that is itself shear-deformable is refused.
class SectionAggregator3d : public SectionForceDeformation {
 public:
  SectionAggregator3d(int tag, std::unique_ptr<SectionForceDeformation> section,
                      std::array<std::unique_ptr<UniaxialMaterial>, 4> materials);
  SectionAggregator3d(const SectionAggregator3d& other);
  SectionAggregator3d& operator=(const SectionAggregator3d&) = delete;

  // Index of a code in the 3D order [P, Mz, My, T]; -1 for shear.
  static int componentOf(SectionCode code);

  std::string className() const override { return "Aggregator"; }
  std::unique_ptr<SectionForceDeformation> clone() const override;

  void setTrialDeformation(const Vector4& e) override;
  const Vector4& deformation() const override { return deformation_; }
  const Vector4& force() const override { return force_; }
  const Matrix4& tangent() const override { return tangent_; }
  const Matrix4& initialTangent() const override { return initialTangent_; }

  int numShear() const override { return static_cast<int>(shear_.size()); }
  SectionCode shearCode(int k) const override;
  void setTrialShear(const ShearVector& gamma) override;
  ShearVector shearDeformation() const override;
  ShearVector shearForce() const override;
  ShearVector shearTangent() const override;
  ShearVector shearInitialTangent() const override;

  // Adds a material for Vy or Vz after the others (the command's order).
  void addShear(SectionCode code, std::unique_ptr<UniaxialMaterial> material);

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

 private:
  void assemble(bool initial);

  std::unique_ptr<SectionForceDeformation> section_;
  // One optional material per component P, Mz, My, T.
  std::array<std::unique_ptr<UniaxialMaterial>, 4> materials_;
  Vector4 deformation_ = Vector4::Zero(), committedDeformation_ = Vector4::Zero(), force_ = Vector4::Zero();
  Matrix4 tangent_ = Matrix4::Zero(), initialTangent_ = Matrix4::Zero();
  struct ShearMaterial {
    SectionCode code;
    std::unique_ptr<UniaxialMaterial> material;
  };
  std::vector<ShearMaterial> shear_;
};

}  // namespace beamsolid
