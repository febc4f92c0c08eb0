#pragma once
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "core/Response.h"

namespace beamsolid {

// A one-dimensional constitutive model: strain in, stress and tangent out,
// with trial and committed state. Elements and fibers own copies (clone()).
class UniaxialMaterial {
 public:
  explicit UniaxialMaterial(int tag) : tag_(tag) {}
  virtual ~UniaxialMaterial() = default;

  int tag() const { return tag_; }
  virtual std::string className() const = 0;
  virtual std::unique_ptr<UniaxialMaterial> clone() const = 0;

  virtual void setTrialStrain(double strain, double strainRate = 0.0) = 0;
  virtual double strain() const = 0;
  virtual double stress() const = 0;
  virtual double tangent() const = 0;
  virtual double initialTangent() const = 0;
  // d stress / d strain rate, for the damping matrix of transient analysis.
  virtual double dampingTangent() const { return 0.0; }
  // True when the tangent is constant (linear elastic).
  virtual bool isLinear() const { return false; }

  virtual void commitState() = 0;
  virtual void revertToLastCommit() = 0;
  virtual void revertToStart() = 0;

  // 'stress', 'strain', 'tangent', 'stressStrain' by default.
  virtual Response setResponse(const std::vector<std::string>& args);
  virtual bool setParameter(const std::vector<std::string>&, double) { return false; }

  // Sensitivity (direct differentiation, sensitivityAlgorithm). The id (> 0)
  // of the argument named args[0], 0 if the material has none of that name.
  virtual int sensitivityParameter(const std::vector<std::string>&) { return 0; }
  // d stress / d theta at the trial strain: through theta itself
  // (parameterId, 0 when theta is not this material's) and through the
  // committed history's sensitivities of `gradient`. The default serves
  // linear materials theta does not reach; others throw.
  virtual double stressSensitivity(int gradient, int parameterId);
  // Keeps the trial history's sensitivities of `gradient`, given the
  // strain's (d strain / d theta); numGradients sizes the storage.
  virtual void commitSensitivity(double strainSensitivity, int gradient, int parameterId, int numGradients);
  virtual void print(std::ostream& os) const;

 private:
  int tag_;
};

}  // namespace beamsolid
