#include "bindings/Interpreter.h"

#include <exception>

#include "analysis/DofMap.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

Interpreter::Interpreter() : domain_(std::make_unique<Domain>()) { DofMap::resetWarnings(); }

Interpreter::~Interpreter() = default;

const std::map<std::string, Interpreter::Command>& Interpreter::commands() {
  static const std::map<std::string, Command> table = {
      {"wipe", &Interpreter::wipe},
      {"model", &Interpreter::model},
      {"node", &Interpreter::node},
      {"fix", &Interpreter::fix},
      {"fixX", &Interpreter::fixX},
      {"fixY", &Interpreter::fixY},
      {"fixZ", &Interpreter::fixZ},
      {"equalDOF", &Interpreter::equalDOF},
      {"rigidLink", &Interpreter::rigidLink},
      {"mass", &Interpreter::mass},
      {"uniaxialMaterial", &Interpreter::uniaxialMaterial},
      {"nDMaterial", &Interpreter::nDMaterial},
      {"geomTransf", &Interpreter::geomTransf},
      {"element", &Interpreter::element},
      {"block2D", &Interpreter::block2D},
      {"block3D", &Interpreter::block3D},
      {"timeSeries", &Interpreter::timeSeries},
      {"pattern", &Interpreter::pattern},
      {"groundMotion", &Interpreter::groundMotion},
      {"imposedMotion", &Interpreter::imposedMotion},
      {"load", &Interpreter::load},
      {"sp", &Interpreter::sp},
      {"eleLoad", &Interpreter::eleLoad},
      {"loadConst", &Interpreter::loadConst},
      {"setTime", &Interpreter::setTime},
      {"getTime", &Interpreter::getTime},
      {"remove", &Interpreter::remove},
      {"recorder", &Interpreter::recorder},
      {"record", &Interpreter::record},
      {"loadPlugin", &Interpreter::loadPlugin},
      {"setParameter", &Interpreter::setParameter},
      {"updateMaterialStage", &Interpreter::updateMaterialStage},
      {"InitialStateAnalysis", &Interpreter::initialStateAnalysis},
      {"section", &Interpreter::section},
      {"patch", &Interpreter::patch},
      {"layer", &Interpreter::layer},
      {"fiber", &Interpreter::fiber},
      {"beamIntegration", &Interpreter::beamIntegration},
      {"constraints", &Interpreter::constraints},
      {"numberer", &Interpreter::numberer},
      {"system", &Interpreter::system},
      {"test", &Interpreter::test},
      {"algorithm", &Interpreter::algorithm},
      {"integrator", &Interpreter::integrator},
      {"analysis", &Interpreter::analysis},
      {"analyze", &Interpreter::analyze},
      {"wipeAnalysis", &Interpreter::wipeAnalysis},
      {"eigen", &Interpreter::eigen},
      {"modalProperties", &Interpreter::modalProperties},
      {"responseSpectrumAnalysis", &Interpreter::responseSpectrumAnalysis},
      {"printA", &Interpreter::printA},
      {"printB", &Interpreter::printB},
      {"testIter", &Interpreter::testIter},
      {"testNorm", &Interpreter::testNorm},
      {"testNorms", &Interpreter::testNorm},
      {"systemSize", &Interpreter::systemSize},
      {"reactions", &Interpreter::reactions},
      {"rayleigh", &Interpreter::rayleigh},
      {"region", &Interpreter::region},
      {"modalDamping", &Interpreter::modalDamping},
      {"modalDampingQ", &Interpreter::modalDamping},
      {"nodeDisp", &Interpreter::nodeDisp},
      {"nodeVel", &Interpreter::nodeVel},
      {"nodeAccel", &Interpreter::nodeAccel},
      {"nodeCoord", &Interpreter::nodeCoord},
      {"nodeReaction", &Interpreter::nodeReaction},
      {"nodeUnbalance", &Interpreter::nodeUnbalance},
      {"nodeMass", &Interpreter::nodeMass},
      {"nodeEigenvector", &Interpreter::nodeEigenvector},
      {"nodeDOFs", &Interpreter::nodeDOFs},
      {"getNDF", &Interpreter::getNDF},
      {"eleResponse", &Interpreter::eleResponse},
      {"eleForce", &Interpreter::eleForce},
      {"eleDynamicalForce", &Interpreter::eleDynamicalForce},
      {"updateElementDomain", &Interpreter::updateElementDomain},
      {"eleNodes", &Interpreter::eleNodes},
      {"eleType", &Interpreter::eleType},
      {"getNodeTags", &Interpreter::getNodeTags},
      {"getEleTags", &Interpreter::getEleTags},
      {"getLoadFactor", &Interpreter::getLoadFactor},
      {"printModel", &Interpreter::printModel},
      {"getEigenvalues", &Interpreter::getEigenvalues},
      {"testUniaxialMaterial", &Interpreter::testUniaxialMaterial},
      {"setStrain", &Interpreter::setStrain},
      {"getStrain", &Interpreter::getStrain},
      {"getStress", &Interpreter::getStress},
      {"getTangent", &Interpreter::getTangent},
      {"version", &Interpreter::version},
      {"getNP", &Interpreter::getNP},
      {"getPID", &Interpreter::getPID},
      {"barrier", &Interpreter::barrier},
      {"start", &Interpreter::start},
      {"stop", &Interpreter::stop},
      {"logFile", &Interpreter::logFile},
      {"defaultUnits", &Interpreter::defaultUnits},
      {"nodeBounds", &Interpreter::nodeBounds},
      {"numIter", &Interpreter::numIter},
      {"basicForce", &Interpreter::basicForce},
      {"basicDeformation", &Interpreter::basicDeformation},
      {"basicStiffness", &Interpreter::basicStiffness},
      {"sectionForce", &Interpreter::sectionForce},
      {"sectionDeformation", &Interpreter::sectionDeformation},
      {"sectionStiffness", &Interpreter::sectionStiffness},
      {"sectionFlexibility", &Interpreter::sectionFlexibility},
      {"sectionLocation", &Interpreter::sectionLocation},
      {"sectionWeight", &Interpreter::sectionWeight},
      {"getFixedNodes", &Interpreter::getFixedNodes},
      {"getFixedDOFs", &Interpreter::getFixedDOFs},
      {"getConstrainedNodes", &Interpreter::getConstrainedNodes},
      {"getRetainedNodes", &Interpreter::getRetainedNodes},
      {"nodeResponse", &Interpreter::nodeResponse},
      {"setNodeCoord", &Interpreter::setNodeCoord},
      {"setNodeDisp", &Interpreter::setNodeDisp},
      {"setNodeVel", &Interpreter::setNodeVel},
      {"setNodeAccel", &Interpreter::setNodeAccel},
      {"domainChange", &Interpreter::domainChange},
      {"rigidDiaphragm", &Interpreter::rigidDiaphragm},
      {"getNDM", &Interpreter::getNDM},
      {"getNumElements", &Interpreter::getNumElements},
      {"getCrdTransfTags", &Interpreter::getCrdTransfTags},
      {"getPatterns", &Interpreter::getPatterns},
      {"getNodeLoadTags", &Interpreter::getNodeLoadTags},
      {"getNodeLoadData", &Interpreter::getNodeLoadData},
      {"getEleLoadTags", &Interpreter::getEleLoadTags},
      {"getEleLoadData", &Interpreter::getEleLoadData},
      {"getEleLoadClassTags", &Interpreter::getEleLoadClassTags},
      {"getEleClassTags", &Interpreter::getEleClassTags},
      {"classType", &Interpreter::classType},
      {"getConstrainedDOFs", &Interpreter::getConstrainedDOFs},
      {"getRetainedDOFs", &Interpreter::getRetainedDOFs},
      {"setPrecision", &Interpreter::setPrecision},
      {"setStartNodeTag", &Interpreter::setStartNodeTag},
      {"setNumThreads", &Interpreter::setNumThreads},
      {"getNumThreads", &Interpreter::getNumThreads},
      {"numFact", &Interpreter::numFact},
      {"totalCPU", &Interpreter::totalCPU},
      {"solveCPU", &Interpreter::solveCPU},
      {"accelCPU", &Interpreter::accelCPU},
      {"reset", &Interpreter::reset},
      {"parameter", &Interpreter::parameter},
      {"addToParameter", &Interpreter::addToParameter},
      {"updateParameter", &Interpreter::updateParameter},
      {"getParamTags", &Interpreter::getParamTags},
      {"getParamValue", &Interpreter::getParamValue},
      {"sensitivityAlgorithm", &Interpreter::sensitivityAlgorithm},
      {"computeGradients", &Interpreter::computeGradients},
      {"sensNodeDisp", &Interpreter::sensNodeDisp},
      {"sensLambda", &Interpreter::sensLambda},
      {"setElementRayleighDampingFactors", &Interpreter::setElementRayleighDampingFactors},
      {"imposedSupportMotion", &Interpreter::imposedMotion},
  };
  return table;
}

std::vector<std::string> Interpreter::commandNames() {
  std::vector<std::string> names;
  for (const auto& kv : commands()) names.push_back(kv.first);
  return names;
}

const Interpreter::Command* Interpreter::find(const std::string& name) {
  auto it = commands().find(name);
  return it == commands().end() ? nullptr : &it->second;
}

Interpreter::Result Interpreter::call(const std::string& name, std::vector<CommandArgs::Value> values) {
  const Command* command = find(name);
  if (!command) throw OpenSeesError("unknown command '" + name + "'");
  return call(*command, name, std::move(values));
}

Interpreter::Result Interpreter::call(const Command& command, const std::string& name,
                                      std::vector<CommandArgs::Value> values) {
  CommandArgs args(name, std::move(values));
  try {
    return (this->*command)(args);
  } catch (const OpenSeesError&) {
    throw;
  } catch (const std::exception& e) {
    // Anything else is our bug; it still must not take the interpreter down.
    throw OpenSeesError(name + ": internal error: " + e.what());
  }
}

void Interpreter::requireModel(CommandArgs& a) const {
  if (domain_->ndm() == 0) a.fail("no model: call model('basic', '-ndm', ndm, '-ndf', ndf) first");
}

LoadPattern& Interpreter::currentPattern(CommandArgs& a) const {
  LoadPattern* p = domain_->findPattern(currentPatternTag_);
  if (!p) a.fail("no load pattern: call pattern('Plain', tag, tsTag) first");
  return *p;
}

}  // namespace beamsolid
