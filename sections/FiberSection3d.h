#pragma once
#include <memory>
#include <vector>

#include "materials/uniaxial/UniaxialMaterial.h"
#include "sections/FiberGeometry.h"
#include "sections/SectionForceDeformation.h"

namespace beamsolid {

// section('Fiber', tag, '-GJ', GJ) or section('Fiber', tag, '-torsion', matTag):
// fibers are copies of uniaxial materials at (y, z) with an area, filled by
// the patch, layer and fiber commands; torsion is uncoupled, elastic GJ or a
// uniaxial material of twist rate -> torque. As in OpenSees, the reference
// axis is the fibers' area centroid (yBar, zBar): a fiber strains by
// eps - (y - yBar) kappaZ + (z - zBar) kappaY (signs in SectionForceDeformation.h),
// so an axial force alone does not bend an unsymmetric section.
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
  // A patch's or layer's fibers at once: the centroid and sums are formed once.
  void addFibers(const UniaxialMaterial& material, const std::vector<FiberPoint>& points);
  std::size_t numFibers() const { return fibers_.size(); }
  const Fiber& fiber(std::size_t i) const { return fibers_.at(i); }
  // The fiber nearest to (y, z), optionally of one material; -1 if none.
  int nearestFiber(double y, double z, int materialTag = -1) const;
  double centroidY() const { return yBar_; }
  double centroidZ() const { return zBar_; }

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
  // Lever arms about the (new) centroid: initial tangent and current state.
  void refresh();
  bool deferred_ = false;
  void formInitialTangent();

  std::vector<Fiber> fibers_;
  double torsionalStiffness_ = 0.0;
  std::unique_ptr<UniaxialMaterial> torsion_;

  // Area sums for the centroid.
  double area_ = 0.0, areaY_ = 0.0, areaZ_ = 0.0;
  double yBar_ = 0.0, zBar_ = 0.0;

  Vector4 deformation_ = Vector4::Zero();
  Vector4 committedDeformation_ = Vector4::Zero();
  Vector4 force_ = Vector4::Zero();
  Matrix4 tangent_ = Matrix4::Zero();
  Matrix4 initialTangent_ = Matrix4::Zero();
};

}  // namespace beamsolid
