#pragma once
#include <memory>

#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// A uniaxial material owned by a wrapper material (Parallel, Series, MinMax,
// ...): copying the wrapper copies the state of the wrapped one (clone()),
// so each fiber or spring has its own.
class OwnedMaterial {
 public:
  explicit OwnedMaterial(const UniaxialMaterial& m) : material_(m.clone()) {}
  OwnedMaterial(const OwnedMaterial& other) : material_(other.material_->clone()) {}
  OwnedMaterial& operator=(const OwnedMaterial& other) {
    if (this != &other) material_ = other.material_->clone();
    return *this;
  }
  OwnedMaterial(OwnedMaterial&&) noexcept = default;
  OwnedMaterial& operator=(OwnedMaterial&&) noexcept = default;

  UniaxialMaterial* operator->() const { return material_.get(); }
  UniaxialMaterial& operator*() const { return *material_; }

 private:
  std::unique_ptr<UniaxialMaterial> material_;
};

}  // namespace beamsolid
