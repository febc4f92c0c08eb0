#pragma once
#include <vector>

#include "materials/uniaxial/OwnedMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Parallel', tag, *matTags, <'-factors', *factors>):
// the materials share the strain; stress and tangent are the sums of the
// materials' ones, each times its factor (default 1; negative subtracts).
// Responses beyond the base ones: 'material' k ... forwards to material k
// (1-based).
class ParallelMaterial : public UniaxialMaterial {
 public:
  ParallelMaterial(int tag, const std::vector<const UniaxialMaterial*>& materials, std::vector<double> factors);

  std::string className() const override { return "Parallel"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return strain_; }
  double stress() const override;
  double tangent() const override;
  double initialTangent() const override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  Response setResponse(const std::vector<std::string>& args) override;
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void print(std::ostream& os) const override;

 private:
  std::vector<OwnedMaterial> materials_;
  std::vector<double> factors_;
  double strain_ = 0.0, committedStrain_ = 0.0;
};

}  // namespace beamsolid
