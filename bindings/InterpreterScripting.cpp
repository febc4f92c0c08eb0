// Queries and small commands that OpenSeesPy scripts and post-processing tools
// (opsvis, vfo) call: model sizes and tags, loads per pattern, class tags and
// names, MP constraint dofs, parameters, reset, counters. Return values and
// types are OpenSeesPy 3.7.1's, found by running it.
#include <cmath>
#include <iostream>
#include <map>
#include <thread>

#include "bindings/Interpreter.h"
#include "core/LoadPattern.h"
#include "core/OpenSeesClassName.h"
#include "core/OpenSeesError.h"
#include "elements/Element.h"
#include "sections/BeamSection.h"

namespace beamsolid {

using Result = Interpreter::Result;

namespace {

// OpenSees' class tags (classTags.h numbers, read back with getEleClassTags).
int elementClassTag(const std::string& openSeesName) {
  static const std::map<std::string, int> tags = {
      {"ElasticBeam2d", 3},      {"ElasticBeam3d", 5},       {"Truss", 12},
      {"TrussSection", 13},      {"CorotTruss", 14},         {"CorotTrussSection", 15},
      {"ZeroLength", 19},        {"ZeroLengthSection", 20},  {"ZeroLengthContact3D", 23},
      {"FourNodeQuad", 31},      {"Brick", 56},              {"BbarBrick", 57},
      {"DispBeamColumn2d", 62},  {"DispBeamColumn3d", 64},   {"ForceBeamColumn2d", 73},
      {"ForceBeamColumn3d", 74}, {"BeamContact3D", 115},     {"BeamEndContact3D", 118},
      {"BeamContact3Dp", 124},   {"BeamEndContact3Dp", 125}, {"ElasticTimoshenkoBeam2d", 145},
      {"Tri31", 33},             {"TwoNodeLink", 86},        {"FourNodeTetrahedron", 179},
      {"ShellMITC4", 53},        {"ElasticTimoshenkoBeam3d", 146}, {"SSPquad", 119},
      {"ConstantPressureVolumeQuad", 60}, {"SSPbrick", 121},
  };
  const auto it = tags.find(openSeesName);
  return it == tags.end() ? -1 : it->second;
}

// OpenSees' class names of the uniaxial materials BeamSolid has.
std::string uniaxialClassName(const std::string& name) {
  static const std::map<std::string, std::string> names = {
      {"Elastic", "ElasticMaterial"},     {"ElasticPP", "ElasticPPMaterial"}, {"Hardening", "HardeningMaterial"},
      {"Hysteretic", "HystereticMaterial"}, {"Parallel", "ParallelMaterial"}, {"Series", "SeriesMaterial"},
      {"MinMax", "MinMaxMaterial"},       {"ENT", "ENTMaterial"},             {"Viscous", "ViscousMaterial"},
      {"ElasticPPGap", "EPPGapMaterial"},
  };
  const auto it = names.find(name);
  return it == names.end() ? name : it->second;
}

std::string sectionClassName(const std::string& name, int ndm) {
  const std::string dim = ndm == 2 ? "2d" : "3d";
  if (name == "Elastic") return "ElasticSection" + dim;
  if (name == "Fiber" || name == "WFSection2d" || name == "RCSection2d") return "FiberSection" + dim;
  if (name == "Aggregator" || name == "Uniaxial") return "SectionAggregator";  // OpenSees builds Uniaxial as one
  return name;
}

}  // namespace

// getNDM(<nodeTag>): [ndm] of the model, or of the node (its coordinates).
Result Interpreter::getNDM(CommandArgs& a) {
  if (a.done()) return std::vector<int>{domain_->ndm()};
  const int tag = a.nextInt("nodeTag");
  a.setContext("getNDM " + std::to_string(tag));
  a.expectEnd();
  return std::vector<int>{static_cast<int>(domain_->node(tag, a.context()).coordinates().size())};
}

Result Interpreter::getNumElements(CommandArgs& a) {
  a.expectEnd();
  return std::vector<int>{static_cast<int>(domain_->elements().size())};
}

Result Interpreter::getCrdTransfTags(CommandArgs& a) {
  a.expectEnd();
  std::vector<int> tags;
  for (const auto& [tag, t] : domain_->geomTransfs) tags.push_back(tag);
  return tags;
}

Result Interpreter::getPatterns(CommandArgs& a) {
  a.expectEnd();
  std::vector<int> tags;
  for (const auto& [tag, p] : domain_->patterns()) tags.push_back(tag);
  return tags;
}

// The patterns a load query covers: one (by tag) or all, in tag order.
std::vector<const LoadPattern*> Interpreter::loadPatterns(CommandArgs& a, const char* command) {
  std::vector<const LoadPattern*> patterns;
  if (a.done()) {
    for (const auto& [tag, p] : domain_->patterns()) patterns.push_back(p.get());
    return patterns;
  }
  const int tag = a.nextInt("patternTag");
  a.setContext(std::string(command) + " " + std::to_string(tag));
  a.expectEnd();
  patterns.push_back(&domain_->pattern(tag, a.context()));
  return patterns;
}

Result Interpreter::getNodeLoadTags(CommandArgs& a) {
  std::vector<int> tags;
  for (const LoadPattern* p : loadPatterns(a, "getNodeLoadTags"))
    for (const auto& l : p->nodalLoads()) tags.push_back(l.nodeTag);
  return tags;
}

Result Interpreter::getNodeLoadData(CommandArgs& a) {
  std::vector<double> data;
  for (const LoadPattern* p : loadPatterns(a, "getNodeLoadData"))
    for (const auto& l : p->nodalLoads()) data.insert(data.end(), l.load.data(), l.load.data() + l.load.size());
  return data;
}

Result Interpreter::getEleLoadTags(CommandArgs& a) {
  std::vector<int> tags;
  for (const LoadPattern* p : loadPatterns(a, "getEleLoadTags"))
    for (const auto& l : p->elementLoads()) tags.push_back(l.elementTag);
  return tags;
}

// OpenSees' load class tags: Beam2dUniformLoad 3, Beam2dPointLoad 4,
// Beam3dUniformLoad 5, Beam3dPointLoad 6, SelfWeight 10.
Result Interpreter::getEleLoadClassTags(CommandArgs& a) {
  const bool planar = domain_->ndm() == 2;
  std::vector<int> tags;
  for (const LoadPattern* p : loadPatterns(a, "getEleLoadClassTags"))
    for (const auto& l : p->elementLoads()) {
      switch (l.load.type) {
        case ElementLoad::Type::BeamUniform: tags.push_back(planar ? 3 : 5); break;
        case ElementLoad::Type::BeamPoint: tags.push_back(planar ? 4 : 6); break;
        case ElementLoad::Type::SelfWeight: tags.push_back(10); break;
      }
    }
  return tags;
}

// Each load's data as OpenSees orders it: 2D uniform (wy, wx), point (Py, Px, xL);
// 3D uniform (wy, wz, wx), point (Py, Pz, Px, xL); self weight (bx, by, bz).
Result Interpreter::getEleLoadData(CommandArgs& a) {
  const bool planar = domain_->ndm() == 2;
  std::vector<double> data;
  for (const LoadPattern* p : loadPatterns(a, "getEleLoadData"))
    for (const auto& l : p->elementLoads()) {
      const std::vector<double>& v = l.load.values;
      switch (l.load.type) {
        case ElementLoad::Type::BeamUniform:
          if (planar) data.insert(data.end(), {v[0], v[2]});
          else data.insert(data.end(), {v[0], v[1], v[2]});
          break;
        case ElementLoad::Type::BeamPoint:
          if (planar) data.insert(data.end(), {v[0], v[3], v[2]});
          else data.insert(data.end(), {v[0], v[1], v[3], v[2]});
          break;
        case ElementLoad::Type::SelfWeight: data.insert(data.end(), v.begin(), v.end()); break;
      }
    }
  return data;
}

// getEleClassTags(<eleTag>): OpenSees' class tag of each element (or of one).
Result Interpreter::getEleClassTags(CommandArgs& a) {
  std::vector<const Element*> elements;
  if (a.done()) {
    for (const auto& [tag, e] : domain_->elements()) elements.push_back(e.get());
  } else {
    const int tag = a.nextInt("eleTag");
    a.setContext("getEleClassTags " + std::to_string(tag));
    a.expectEnd();
    elements.push_back(&domain_->element(tag, a.context()));
  }
  std::vector<int> tags;
  for (const Element* e : elements) {
    const int t = elementClassTag(openSeesClassName(*e));
    if (t < 0) a.fail("element " + std::to_string(e->tag()) + " (" + e->className() + ") has no OpenSees class tag");
    tags.push_back(t);
  }
  return tags;
}

// classType(type, tag): OpenSees' class name of a uniaxialMaterial or a
// section; other types give None with a warning, as OpenSees.
Result Interpreter::classType(CommandArgs& a) {
  const std::string type = a.nextString("type");
  const int tag = a.nextInt("tag");
  a.setContext("classType " + type + " " + std::to_string(tag));
  a.expectEnd();
  if (type == "uniaxialMaterial") return uniaxialClassName(domain_->uniaxialMaterials.get(tag, a.context()).className());
  if (type == "section") return sectionClassName(domain_->sections.get(tag, a.context()).className(), domain_->ndm());
  if (type == "element" || type == "nDMaterial" || type == "timeSeries" || type == "geomTransf" ||
      type == "pattern" || type == "beamIntegration") {
    std::cerr << "WARNING classType - " << type << " not yet supported\n";
    return {};
  }
  a.fail("unknown type '" + type + "' (expected uniaxialMaterial or section)");
}

// getConstrainedDOFs(cNode, <rNode>, <rDOF>) and getRetainedDOFs(rNode, <cNode>, <cDOF>):
// 1-based dofs of the MP constraints on that node, optionally of one pair and one dof.
Result Interpreter::mpDofs(CommandArgs& a, const char* command, bool constrained) {
  const int node = a.nextInt(constrained ? "cNode" : "rNode");
  a.setContext(std::string(command) + " " + std::to_string(node));
  const int other = a.done() ? 0 : a.nextInt(constrained ? "rNode" : "cNode");
  const int otherDof = a.done() ? 0 : a.nextInt(constrained ? "rDOF" : "cDOF");
  a.expectEnd();
  domain_->node(node, a.context());
  std::vector<int> dofs;
  for (const MPConstraint& mp : domain_->mps()) {
    if ((constrained ? mp.constrainedNode : mp.retainedNode) != node) continue;
    if (other && (constrained ? mp.retainedNode : mp.constrainedNode) != other) continue;
    const std::vector<int>& mine = constrained ? mp.constrainedDofs : mp.retainedDofs;
    const std::vector<int>& theirs = constrained ? mp.retainedDofs : mp.constrainedDofs;
    for (std::size_t i = 0; i < mine.size(); ++i)
      if (!otherDof || (i < theirs.size() && theirs[i] == otherDof - 1)) dofs.push_back(mine[i] + 1);
  }
  return dofs;
}

Result Interpreter::getConstrainedDOFs(CommandArgs& a) { return mpDofs(a, "getConstrainedDOFs", true); }
Result Interpreter::getRetainedDOFs(CommandArgs& a) { return mpDofs(a, "getRetainedDOFs", false); }

// setPrecision(n): digits of printed numbers in OpenSees; BeamSolid's reports
// keep their own formats, so only the argument is checked.
Result Interpreter::setPrecision(CommandArgs& a) {
  const int digits = a.nextInt("precision");
  a.expectEnd();
  if (digits < 1) a.fail("precision must be positive, got " + std::to_string(digits));
  return {};
}

// setStartNodeTag(tag): the first tag OpenSees' mesh command gives its nodes.
// BeamSolid has no mesh command (block2D/block3D take their tags), so only the
// argument is checked.
Result Interpreter::setStartNodeTag(CommandArgs& a) {
  a.nextInt("nodeTag");
  a.expectEnd();
  return {};
}

Result Interpreter::setNumThreads(CommandArgs& a) {
  const int n = a.nextInt("numThreads");
  a.expectEnd();
  if (n < 1) a.fail("numThreads must be at least 1, got " + std::to_string(n));
  numThreads_ = n;
  return {};
}

Result Interpreter::getNumThreads(CommandArgs& a) {
  a.expectEnd();
  if (numThreads_ > 0) return static_cast<long long>(numThreads_);
  return static_cast<long long>(std::max(1u, std::thread::hardware_concurrency()));
}

// numFact, totalCPU, solveCPU, accelCPU: OpenSees' algorithm counters, floats.
// OpenSees 3.7.1 reports 0.0 from Newton and Linear; BeamSolid reports what it
// measured: factorizations, and the seconds spent in the linear solver.
Result Interpreter::algorithmCounter(CommandArgs& a, const char* command) {
  a.expectEnd();
  if (!components_.algorithm && !analysis_) a.fail("no algorithm is set: call algorithm(...) first");
  const SolverInfo info = solverInfo();
  const std::string c = command;
  if (c == "numFact") return static_cast<double>(info.factorizations);
  if (c == "accelCPU") return 0.0;  // no accelerator (Krylov, Broyden) time is kept apart
  return info.solverSeconds;
}

Result Interpreter::numFact(CommandArgs& a) { return algorithmCounter(a, "numFact"); }
Result Interpreter::totalCPU(CommandArgs& a) { return algorithmCounter(a, "totalCPU"); }
Result Interpreter::solveCPU(CommandArgs& a) { return algorithmCounter(a, "solveCPU"); }
Result Interpreter::accelCPU(CommandArgs& a) { return algorithmCounter(a, "accelCPU"); }

// reset(): every node and element back to its initial state, time zero.
Result Interpreter::reset(CommandArgs& a) {
  a.expectEnd();
  domain_->revertToStart();
  return {};
}

// parameter(tag, <'element', eleTag, *args | 'node', nodeTag, 'coord', dim>)
// and addToParameter(tag, ...): a named value mapped onto objects' arguments
// (as setParameter reaches them); updateParameter(tag, value) sets it.
Result Interpreter::parameterCommand(CommandArgs& a, const char* command, bool add) {
  const int tag = a.nextInt("paramTag");
  a.setContext(std::string(command) + " " + std::to_string(tag));
  auto it = parameters_.find(tag);
  if (add && it == parameters_.end()) a.fail("parameter " + std::to_string(tag) + " does not exist");
  if (!add && it != parameters_.end()) a.fail("parameter " + std::to_string(tag) + " already exists");
  if (a.done()) {
    parameters_[tag];
    return static_cast<long long>(tag);
  }
  // The target is checked whole before the parameter exists.
  Parameter::Target target;
  double value = 0.0;
  target.kind = a.nextString("object type ('element' or 'node')");
  if (target.kind == "element") {
    target.tag = a.nextInt("eleTag");
    domain_->element(target.tag, a.context());
    target.args = a.restAsStrings();
    if (target.args.empty()) a.fail("missing the element's parameter name (e.g. 'E')");
  } else if (target.kind == "node") {
    target.tag = a.nextInt("nodeTag");
    const Node& n = domain_->node(target.tag, a.context());
    if (a.nextString("node parameter ('coord')") != "coord") a.fail("node parameters: 'coord', dim");
    const int dim = a.nextInt("dim");
    a.expectEnd();
    if (dim < 1 || dim > static_cast<int>(n.coordinates().size()))
      a.fail("dim " + std::to_string(dim) + " is out of range 1.." + std::to_string(n.coordinates().size()));
    target.args = {std::to_string(dim)};
    value = n.coordinates()[dim - 1];
  } else {
    a.fail("unknown object type '" + target.kind + "' (expected 'element' or 'node')");
  }
  Parameter& p = parameters_[tag];
  if (p.targets.empty()) p.value = value;
  p.targets.push_back(std::move(target));
  return static_cast<long long>(tag);
}

Result Interpreter::parameter(CommandArgs& a) { return parameterCommand(a, "parameter", false); }
Result Interpreter::addToParameter(CommandArgs& a) { return parameterCommand(a, "addToParameter", true); }

Result Interpreter::updateParameter(CommandArgs& a) {
  const int tag = a.nextInt("paramTag");
  a.setContext("updateParameter " + std::to_string(tag));
  const double value = a.nextDouble("value");
  a.expectEnd();
  auto it = parameters_.find(tag);
  if (it == parameters_.end()) a.fail("parameter " + std::to_string(tag) + " does not exist");
  for (const Parameter::Target& t : it->second.targets) {
    if (t.kind == "element") {
      Element& e = domain_->element(t.tag, a.context());
      if (!e.setParameter(t.args, value)) {
        std::string name;
        for (const auto& s : t.args) name += (name.empty() ? "" : " ") + s;
        a.fail("element " + std::to_string(t.tag) + " (" + e.className() + ") has no parameter '" + name + "'");
      }
      domain_->touch();
    } else {
      Node& n = domain_->node(t.tag, a.context());
      n.setCoordinate(std::stoi(t.args[0]) - 1, value);
      domain_->nodeMoved(t.tag, a.context());
    }
  }
  it->second.value = value;
  return static_cast<long long>(tag);
}

Result Interpreter::getParamTags(CommandArgs& a) {
  a.expectEnd();
  std::vector<int> tags;
  for (const auto& [tag, p] : parameters_) tags.push_back(tag);
  return tags;
}

// The value last given to updateParameter; before that, a node coordinate's
// value, else 0 (OpenSees reads an element argument's current value there).
Result Interpreter::getParamValue(CommandArgs& a) {
  const int tag = a.nextInt("paramTag");
  a.setContext("getParamValue " + std::to_string(tag));
  a.expectEnd();
  auto it = parameters_.find(tag);
  if (it == parameters_.end()) a.fail("parameter " + std::to_string(tag) + " does not exist");
  return it->second.value;
}

// sensitivityAlgorithm(<'-computeAtEachStep' | '-computeByCommand'>): the
// direct differentiation method after every converged step of the analysis
// (SensitivityAlgorithm). Either option computes at every step, since the
// sensitivity of a path-dependent history needs every step.
Result Interpreter::sensitivityAlgorithm(CommandArgs& a) {
  a.setContext("sensitivityAlgorithm");
  if (!a.done()) {
    const std::size_t at = a.position();
    const std::string option = a.nextString("option");
    if (option != "-computeAtEachStep" && option != "-computeByCommand")
      a.failAt(at, "option", "'-computeAtEachStep' or '-computeByCommand'");
  }
  a.expectEnd();
  components_.sensitivity = std::make_unique<SensitivityAlgorithm>(parameters_, sensitivityResults_);
  return {};
}

// computeGradients(): the gradients of the last converged step are current
// already (computed with it); 0 when a sensitivity algorithm is defined.
Result Interpreter::computeGradients(CommandArgs& a) {
  a.expectEnd();
  if (!components_.sensitivity) a.fail("no sensitivity algorithm: call sensitivityAlgorithm(...) first");
  return 0LL;
}

// sensNodeDisp(nodeTag, dof, paramTag): d u / d theta of the last converged
// step (0 before any).
Result Interpreter::sensNodeDisp(CommandArgs& a) {
  const int nodeTag = a.nextInt("nodeTag");
  a.setContext("sensNodeDisp " + std::to_string(nodeTag));
  const std::size_t dofAt = a.position();
  const int dof = a.nextInt("dof");
  const int paramTag = a.nextInt("paramTag");
  a.expectEnd();
  const Node& node = domain_->node(nodeTag, a.context());
  if (dof < 1 || dof > node.ndf()) a.failAt(dofAt, "dof", "a dof in 1.." + std::to_string(node.ndf()));
  if (parameters_.find(paramTag) == parameters_.end()) a.fail("parameter " + std::to_string(paramTag) + " does not exist");
  const int k = sensitivityResults_.gradientOf(paramTag);
  auto it = sensitivityResults_.nodeDisp.find(nodeTag);
  if (k < 0 || it == sensitivityResults_.nodeDisp.end()) return 0.0;
  return it->second(dof - 1, k);
}

// sensLambda(patternTag, paramTag): d lambda / d theta of the pattern's load
// factor at the last converged step: 0 under load control; under
// displacement control the time's sensitivity times the pattern's slope.
Result Interpreter::sensLambda(CommandArgs& a) {
  const int patternTag = a.nextInt("patternTag");
  a.setContext("sensLambda " + std::to_string(patternTag));
  const int paramTag = a.nextInt("paramTag");
  a.expectEnd();
  const LoadPattern* pattern = domain_->findPattern(patternTag);
  if (!pattern) a.fail("load pattern " + std::to_string(patternTag) + " does not exist");
  if (parameters_.find(paramTag) == parameters_.end()) a.fail("parameter " + std::to_string(paramTag) + " does not exist");
  const int k = sensitivityResults_.gradientOf(paramTag);
  if (k < 0 || k >= static_cast<int>(sensitivityResults_.lambda.size())) return 0.0;
  return sensitivityResults_.lambda[k] * pattern->factorSlope(domain_->currentTime());
}

// setElementRayleighDampingFactors(eleTag, alphaM, betaK, betaK0, betaKc):
// this element's own factors, as region(... '-ele', tag, '-rayleigh', ...).
Result Interpreter::setElementRayleighDampingFactors(CommandArgs& a) {
  const int tag = a.nextInt("eleTag");
  a.setContext("setElementRayleighDampingFactors " + std::to_string(tag));
  RayleighFactors f;
  f.alphaM = a.nextDouble("alphaM");
  f.betaK = a.nextDouble("betaK");
  f.betaKinit = a.nextDouble("betaK0");
  f.betaKcomm = a.nextDouble("betaKc");
  a.expectEnd();
  domain_->element(tag, a.context()).setRegionRayleigh(f);
  domain_->noteRegionRayleigh();
  return {};
}

}  // namespace beamsolid
