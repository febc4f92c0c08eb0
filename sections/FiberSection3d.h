#pragma once
#include <memory>
#include <vector>

#include "materials/uniaxial/UniaxialMaterial.h"
#include "sections/SectionForceDeformation.h"

namespace beamsolid {

// section('Fiber', tag, '-GJ', GJ) or section('Fiber', tag, '-torsion', matTag):
// fibers are copies of uniaxial materials at (y, z) with an area, filled by
// the patch, layer and fiber commands; torsion is uncoupled, elastic GJ or a
// uniaxial material of twist rate -> torque. The reference axis is y = z = 0
// of the fiber coordinates (see SectionForceDeformation.h for the signs).
class FiberSection3d : public SectionForceDeformation {
 public:
  struct Fiber {
    std::unique_ptr<UniaxialMaterial> material;
    double y = 0.0, z = 0.0, area = 0.0;
  };

  FiberSection3d(int tag, double torsionalStiffness);
  FiberSection3d(int tag, std::unique_ptr<UniaxialMaterial> torsion);
  FiberSection3d(const FiberSection3d& other);
  FiberSection3d& operator=(const FiberSection3d&) = delete;

  std::string className() const override { return "Fiber"; }
  std::unique_ptr<SectionForceDeformation> clone() const override;

  // A fiber with its own copy of `material`; throws for area <= 0.
  void addFiber(const UniaxialMaterial& material, double y, double z, double area);
  std::size_t numFibers() const { return fibers_.size(); }
  const Fiber& fiber(std::size_t i) const { return fibers_.at(i); }
  // The fiber nearest to (y, z), optionally of one material; -1 if none.
  int nearestFiber(double y, double z, int materialTag = -1) const;

  void setTrialDeformation(const Vector4& e) override;
  const Vector4& deformation() const override { return deformation_; }
  const Vector4& force() const override { return force_; }
  const Matrix4& tangent() const override { return tangent_; }
  const Matrix4& initialTangent() const override { return initialTangent_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // Besides the base responses: 'fiber', y, z, <matTag>, *materialArgs (the
  // nearest fiber), 'fiber', index, *materialArgs (0-based, creation order),
  // 'fiberData' (y, z, area, stress, strain of every fiber), 'numFibers'.
  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

 private:
  // Resultants and tangent from the fibers' current stresses and tangents.
  void sumFibers();
  void formInitialTangent();

  std::vector<Fiber> fibers_;
  double torsionalStiffness_ = 0.0;
  std::unique_ptr<UniaxialMaterial> torsion_;

  Vector4 deformation_ = Vector4::Zero();
  Vector4 committedDeformation_ = Vector4::Zero();
  Vector4 force_ = Vector4::Zero();
  Matrix4 tangent_ = Matrix4::Zero();
  Matrix4 initialTangent_ = Matrix4::Zero();
};

}  // namespace beamsolid
