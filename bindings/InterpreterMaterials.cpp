// Driving one uniaxial material outside any element, as OpenSeesPy's
// testUniaxialMaterial / setStrain / getStrain / getStress / getTangent do.
#include "bindings/Interpreter.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

using Result = Interpreter::Result;

namespace {
UniaxialMaterial& materialUnderTest(const std::unique_ptr<UniaxialMaterial>& m, CommandArgs& a) {
  if (!m) a.fail("no material under test: call testUniaxialMaterial(matTag) first");
  return *m;
}
}  // namespace

Result Interpreter::testUniaxialMaterial(CommandArgs& a) {
  const int tag = a.nextInt("matTag");
  a.setContext("testUniaxialMaterial " + std::to_string(tag));
  a.expectEnd();
  // A fresh copy: the model's material (and its clones in elements) stay untouched.
  testMaterial_ = domain_->uniaxialMaterials.get(tag, a.context()).clone();
  testMaterial_->revertToStart();
  return {};
}

Result Interpreter::setStrain(CommandArgs& a) {
  a.setContext("setStrain");
  const double strain = a.nextDouble("strain");
  const double rate = a.done() ? 0.0 : a.nextDouble("strainRate");
  a.expectEnd();
  UniaxialMaterial& m = materialUnderTest(testMaterial_, a);
  // Each call is one converged step: trial state, then commit.
  m.setTrialStrain(strain, rate);
  m.commitState();
  return {};
}

Result Interpreter::getStrain(CommandArgs& a) {
  a.setContext("getStrain");
  a.expectEnd();
  return materialUnderTest(testMaterial_, a).strain();
}

Result Interpreter::getStress(CommandArgs& a) {
  a.setContext("getStress");
  a.expectEnd();
  return materialUnderTest(testMaterial_, a).stress();
}

Result Interpreter::getTangent(CommandArgs& a) {
  a.setContext("getTangent");
  a.expectEnd();
  return materialUnderTest(testMaterial_, a).tangent();
}

}  // namespace beamsolid
