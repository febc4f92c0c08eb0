#pragma once
#include <memory>
#include <vector>

#include "materials/nd/NDMaterial.h"
#include "sections/PlateSection.h"

namespace beamsolid {

// Plate sections integrated through the thickness from plate fiber
// materials (nDMaterial('PlateFiber', ...)):
//   section('PlateFiber', tag, matTag, h): one material at five Gauss-Lobatto
//     points (both faces among them: found against OpenSeesPy, where the
//     faces yield first), the transverse shear taken at 5/6 (strain and
//     stress each scaled by sqrt(5/6));
//   section('LayeredShell', tag, nLayers, mat1, t1, mat2, t2, ...): one point
//     at the middle of each layer (weight its thickness), layer 1 at the
//     bottom (z = -h/2), at least three layers (as OpenSees), the transverse
//     shear of the full layers.
// A fiber at height z strains [e11 + z k11, e22 + z k22, g12 + z k12, g23,
// g13] and the section sums p = int s dz, m = int s z dz, q = int tau dz.
// Checked against OpenSeesPy 3.7.1 (oracle script layered_shells).
class LayeredPlateSection : public PlateSection {
 public:
  struct Layer {
    std::unique_ptr<NDMaterial> material;  // a plate fiber material
    double z = 0.0, weight = 0.0;
  };

  LayeredPlateSection(int tag, std::string className, std::vector<Layer> layers, double shearFactor);
  LayeredPlateSection(const LayeredPlateSection& other);

  std::string className() const override { return className_; }
  std::unique_ptr<PlateSection> clone() const override;

  void setTrialDeformation(const Vector8& e) override;
  const Vector8& deformation() const override { return deformation_; }
  const Vector8& force() const override { return force_; }
  const Matrix8& tangent() const override { return tangent_; }
  const Matrix8& initialTangent() const override { return initialTangent_; }
  double areaDensity() const override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void print(std::ostream& os) const override;

 private:
  using Matrix58 = Eigen::Matrix<double, 5, 8>;
  Matrix58 strainMap(double z) const;
  void integrate(bool initial);

  std::string className_;
  std::vector<Layer> layers_;
  double shearRoot_;  // sqrt of the shear factor, on the fiber's shear strain and stress
  Vector8 deformation_ = Vector8::Zero(), committedDeformation_ = Vector8::Zero(), force_ = Vector8::Zero();
  Matrix8 tangent_ = Matrix8::Zero(), initialTangent_ = Matrix8::Zero();
};

}  // namespace beamsolid
