#pragma once
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "core/Response.h"
#include "core/Types.h"

namespace beamsolid {

// A multi-dimensional constitutive model. For solids ("ThreeDimensional")
// strain and stress are Voigt 6-vectors in OpenSees order
// [xx, yy, zz, xy, yz, zx] with engineering shear strains.
class NDMaterial {
 public:
  explicit NDMaterial(int tag) : tag_(tag) {}
  virtual ~NDMaterial() = default;

  int tag() const { return tag_; }
  virtual std::string className() const = 0;
  // A copy for one integration point of an element of the given kind
  // ("ThreeDimensional", "ContactMaterial3D", ...); nullptr when this
  // material cannot serve that kind.
  virtual std::unique_ptr<NDMaterial> clone(const std::string& kind) const = 0;

  virtual void setTrialStrain(const Eigen::Ref<const Vector>& strain) = 0;
  virtual VectorView strain() const = 0;
  virtual VectorView stress() const = 0;
  virtual MatrixView tangent() const = 0;
  virtual MatrixView initialTangent() const = 0;
  virtual double density() const { return 0.0; }
  // True when the tangent is constant (linear elastic).
  virtual bool isLinear() const { return false; }

  virtual void commitState() = 0;
  virtual void revertToLastCommit() = 0;
  virtual void revertToStart() = 0;

  // updateMaterialStage; materials without stages ignore it.
  virtual void updateStage(int) {}
  // InitialStateAnalysis('on' | 'off'); only InitialStateAnalysisWrapper
  // keeps its state through the 'off' that zeroes the displacements.
  virtual void initialStateAnalysis(bool) {}
  virtual bool setParameter(const std::vector<std::string>&, double) { return false; }

  // 'stress', 'strain', 'tangent' by default.
  virtual Response setResponse(const std::vector<std::string>& args);
  virtual void print(std::ostream& os) const;

 private:
  int tag_;
};

}  // namespace beamsolid
