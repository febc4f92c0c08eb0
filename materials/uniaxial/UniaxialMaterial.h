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
  virtual void print(std::ostream& os) const;

 private:
  int tag_;
};

}  // namespace beamsolid
