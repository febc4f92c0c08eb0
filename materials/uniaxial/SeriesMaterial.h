#pragma once
#include <vector>

#include "materials/uniaxial/OwnedMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Series', tag, *matTags, <'-iter', maxIter, tol>):
// the materials carry the same stress and their strains add up. The state
// is found as in a force-based element: from the last trial, the strain
// increment is turned into a stress increment with the series tangent
// (flexibilities add), each material's strain moves by its flexibility times
// its stress misfit, and the stress is corrected by the remaining strain
// misfit. maxIter (default 1, as OpenSees) such passes are made per trial,
// fewer once the misfit is below tol (default 1e-10); with one pass the
// misfit left is carried into the next trial, as in OpenSees.
class SeriesMaterial : public UniaxialMaterial {
 public:
  SeriesMaterial(int tag, const std::vector<const UniaxialMaterial*>& materials, int maxIter, double tol);

  std::string className() const override { return "Series"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return 1.0 / trial_.flexibility; }
  double initialTangent() const override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

 private:
  // maxIter > 1: the converged series state at `strain`; false if none was
  // found in maxIter passes (a softening component), the state then undefined.
  bool solveSeries(double strain);
  // One incremental pass; returns the strain misfit it leaves.
  double onePass(double strain);
  // Sets material i's trial strain so that it carries `stress`; returns it.
  double strainAtStress(std::size_t i, double stress);

  struct State {
    double strain = 0.0, stress = 0.0, flexibility = 0.0;
    std::vector<double> strains;  // of each material
  };
  std::vector<OwnedMaterial> materials_;
  int maxIter_;
  double tol_;
  State trial_, committed_;
};

}  // namespace beamsolid
