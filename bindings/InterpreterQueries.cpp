// Query commands of the Interpreter: nodal and element results, tags, printModel.
#include <fstream>
#include <iostream>
#include <sstream>

#include "bindings/Interpreter.h"
#include "analysis/Analysis.h"
#include "analysis/CondensedSolver.h"
#include "core/OpenSeesClassName.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

using Result = Interpreter::Result;

namespace {
std::vector<double> toList(const Eigen::Ref<const Vector>& v) { return std::vector<double>(v.data(), v.data() + v.size()); }
}  // namespace

Result Interpreter::nodeVectorQuery(CommandArgs& a, const char* what, const Vector& (Node::*get)() const) {
  const int tag = a.nextInt("nodeTag");
  a.setContext(std::string(what) + " " + std::to_string(tag));
  const Node& n = domain_->node(tag, a.context());
  const Vector& v = (n.*get)();
  if (a.done()) return toList(v);
  const int dof = a.nextInt("dof");
  a.expectEnd();
  if (dof < 1 || dof > v.size())
    a.fail("dof " + std::to_string(dof) + " is out of range 1.." + std::to_string(v.size()));
  return v[dof - 1];
}

Result Interpreter::nodeDisp(CommandArgs& a) { return nodeVectorQuery(a, "nodeDisp", &Node::trialDisp); }
Result Interpreter::nodeVel(CommandArgs& a) { return nodeVectorQuery(a, "nodeVel", &Node::trialVel); }
Result Interpreter::nodeAccel(CommandArgs& a) { return nodeVectorQuery(a, "nodeAccel", &Node::trialAccel); }
Result Interpreter::nodeReaction(CommandArgs& a) { return nodeVectorQuery(a, "nodeReaction", &Node::reaction); }
Result Interpreter::nodeUnbalance(CommandArgs& a) { return nodeVectorQuery(a, "nodeUnbalance", &Node::unbalancedLoad); }
Result Interpreter::nodeMass(CommandArgs& a) { return nodeVectorQuery(a, "nodeMass", &Node::mass); }

Result Interpreter::nodeCoord(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  a.setContext("nodeCoord " + std::to_string(tag));
  const Node& n = domain_->node(tag, a.context());
  if (a.done()) return toList(n.coordinates());
  // dim as 1..ndm or as 'X', 'Y', 'Z' (either case), as OpenSees takes it.
  int dim = 0;
  if (a.nextIsString()) {
    const std::string name = a.nextString("dim");
    if (name.size() == 1 && std::string("xyzXYZ").find(name[0]) != std::string::npos)
      dim = 1 + static_cast<int>(std::string("xyzXYZ").find(name[0]) % 3);
    else
      a.failAt(a.position() - 1, "dim", "1.." + std::to_string(n.ndm()) + " or one of X, Y, Z");
  } else {
    dim = a.nextInt("dim");
  }
  a.expectEnd();
  if (dim < 1 || dim > n.ndm())
    a.fail("dim " + std::to_string(dim) + " is out of range 1.." + std::to_string(n.ndm()));
  return n.crd()[dim - 1];
}

Result Interpreter::nodeEigenvector(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  a.setContext("nodeEigenvector " + std::to_string(tag));
  const int mode = a.nextInt("eigenvector");
  const Node& n = domain_->node(tag, a.context());
  const Matrix& phi = n.eigenvectors();
  if (mode < 1 || mode > phi.cols())
    a.fail("mode " + std::to_string(mode) + " is not available (" + std::to_string(phi.cols()) +
           " modes computed; call eigen first)");
  if (a.done()) return toList(phi.col(mode - 1));
  const int dof = a.nextInt("dof");
  a.expectEnd();
  if (dof < 1 || dof > n.ndf()) a.fail("dof " + std::to_string(dof) + " is out of range 1.." + std::to_string(n.ndf()));
  return phi(dof - 1, mode - 1);
}

Result Interpreter::nodeDOFs(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  a.setContext("nodeDOFs " + std::to_string(tag));
  a.expectEnd();
  const Node& n = domain_->node(tag, a.context());
  std::vector<int> eqs(n.ndf(), -1);
  if (analysis_ && components_.handler && components_.numberer && components_.solver) {
    AnalysisModel& m = analysis_->model();
    m.setup(*components_.handler, *components_.numberer, *components_.solver);
    const int start = m.dofMap().fullStartOfNode(tag);
    for (int d = 0; d < n.ndf(); ++d) {
      auto* b = m.dofMap().fullTermsBegin(start + d);
      if (m.dofMap().fullTermsEnd(start + d) - b == 1 && b->coefficient == 1.0) eqs[d] = b->equation;
    }
  }
  return eqs;
}

Result Interpreter::getNDF(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  a.setContext("getNDF " + std::to_string(tag));
  a.expectEnd();
  return std::vector<int>{domain_->node(tag, a.context()).ndf()};
}

Result Interpreter::eleResponse(CommandArgs& a) {
  const int tag = a.nextInt("eleTag");
  a.setContext("eleResponse " + std::to_string(tag));
  Element& e = domain_->element(tag, a.context());
  const auto args = a.restAsStrings();
  if (args.empty()) a.fail("missing response name (e.g. 'force')");
  Response r = e.setResponse(args);
  if (!r) {
    std::string joined;
    for (const auto& s : args) joined += (joined.empty() ? "" : " ") + s;
    a.fail("element " + e.className() + " " + std::to_string(tag) + " has no response '" + joined + "'");
  }
  return toList(r.value());
}

namespace {
// The whole force vector, or its entry (dof) when one more argument is given.
Interpreter::Result forceOrEntry(CommandArgs& a, const Vector& f) {
  if (a.done()) return toList(f);
  const int dof = a.nextInt("dof");
  a.expectEnd();
  if (dof < 1 || dof > f.size()) a.fail("dof " + std::to_string(dof) + " is out of range 1.." + std::to_string(f.size()));
  return f[dof - 1];
}
}  // namespace

Result Interpreter::eleForce(CommandArgs& a) {
  const int tag = a.nextInt("eleTag");
  a.setContext("eleForce " + std::to_string(tag));
  Element& e = domain_->element(tag, a.context());
  return forceOrEntry(a, e.resistingForce());
}

// As OpenSees: the resisting force with the element's inertia and Rayleigh
// damping forces (what balances the applied loads in a transient analysis).
Result Interpreter::eleDynamicalForce(CommandArgs& a) {
  const int tag = a.nextInt("eleTag");
  a.setContext("eleDynamicalForce " + std::to_string(tag));
  Element& e = domain_->element(tag, a.context());
  Vector f = e.resistingForce();
  f += e.inertiaForce();
  f += e.rayleighForce(e.rayleighFactors(domain_->rayleigh()));
  Result r = forceOrEntry(a, f);
  // OpenSeesPy gives one dof's entry as a list of one value here.
  if (const double* value = std::get_if<double>(&r)) return std::vector<double>{*value};
  return r;
}

Result Interpreter::eleNodes(CommandArgs& a) {
  const int tag = a.nextInt("eleTag");
  a.setContext("eleNodes " + std::to_string(tag));
  a.expectEnd();
  return domain_->element(tag, a.context()).nodeTags();
}

// eleType answers OpenSees' C++ class names, not the command names.
Result Interpreter::eleType(CommandArgs& a) {
  const int tag = a.nextInt("eleTag");
  a.setContext("eleType " + std::to_string(tag));
  a.expectEnd();
  return openSeesClassName(domain_->element(tag, a.context()));
}

Result Interpreter::getNodeTags(CommandArgs& a) {
  a.expectEnd();
  std::vector<int> tags;
  for (const auto& [tag, n] : domain_->nodes()) tags.push_back(tag);
  return tags;
}

Result Interpreter::getEleTags(CommandArgs& a) {
  a.expectEnd();
  std::vector<int> tags;
  for (const auto& [tag, e] : domain_->elements()) tags.push_back(tag);
  return tags;
}

Result Interpreter::getLoadFactor(CommandArgs& a) {
  const int tag = a.nextInt("patternTag");
  a.setContext("getLoadFactor " + std::to_string(tag));
  a.expectEnd();
  return domain_->pattern(tag, a.context()).factor(domain_->currentTime());
}

namespace {
void printVectorJSON(std::ostream& os, const Eigen::Ref<const Vector>& v) {
  os << '[';
  for (int i = 0; i < v.size(); ++i) os << (i ? ", " : "") << v[i];
  os << ']';
}
}  // namespace

Interpreter::SolverInfo Interpreter::solverInfo() const {
  SolverInfo info;
  if (!analysis_) return info;
  AnalysisModel& model = analysis_->model();
  const LinearSolver* solver = model.system().solver();
  if (!solver) return info;
  info.system = solver->requestedName();
  info.backend = solver->backend();
  info.note = model.condensationNote();
  info.equations = model.numEquations();
  info.factorizations = solver->numFactorize();
  info.analyses = solver->numAnalyze();
  info.solverSeconds = model.system().solverSeconds();
  if (const CondensedSolver* c = model.condensedSolver()) {
    info.condensed = true;
    info.interior = c->numInterior();
    info.interface = c->numInterface();
    info.condensations = c->numCondensations();
    info.condensationsReused = c->numCondensationsReused();
    info.interfaceFactorizations = c->numInterfaceFactorizations();
    info.krylovIterations = c->numKrylovIterations();
    info.condenseSeconds = c->condenseSeconds();
    info.interfaceFactorSeconds = c->interfaceFactorSeconds();
    info.interfaceSolveSeconds = c->interfaceSolveSeconds();
  }
  return info;
}

Result Interpreter::printModel(CommandArgs& a) {
  bool json = false;
  std::string file;
  std::vector<int> nodeTags, eleTags;
  bool onlyNodes = false, onlyEles = false;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-JSON") json = true;
    else if (opt == "-file") file = a.nextString("file");
    else if (opt == "-node") { onlyNodes = true; auto t = a.nextInts("nodeTag"); nodeTags.insert(nodeTags.end(), t.begin(), t.end()); }
    else if (opt == "-ele") { onlyEles = true; auto t = a.nextInts("eleTag"); eleTags.insert(eleTags.end(), t.begin(), t.end()); }
    else if (opt == "-flag") a.nextInt("flag");
    else a.fail("unknown option '" + opt + "' (expected -JSON, -file, -node, -ele)");
  }
  std::ostringstream os;
  os.precision(12);
  auto wantNode = [&](int t) { return !onlyEles && (nodeTags.empty() || std::find(nodeTags.begin(), nodeTags.end(), t) != nodeTags.end()); };
  auto wantEle = [&](int t) { return !onlyNodes && (eleTags.empty() || std::find(eleTags.begin(), eleTags.end(), t) != eleTags.end()); };
  if (json) {
    os << "{\"StructuralAnalysisModel\": {\n  \"properties\": {\"time\": " << domain_->currentTime()
       << ", \"ndm\": " << domain_->ndm() << "},\n  \"geometry\": {\n    \"nodes\": [";
    bool first = true;
    for (const auto& [tag, n] : domain_->nodes()) {
      if (!wantNode(tag)) continue;
      os << (first ? "\n      " : ",\n      ") << "{\"name\": " << tag << ", \"ndf\": " << n->ndf() << ", \"crd\": ";
      printVectorJSON(os, n->coordinates());
      os << ", \"disp\": ";
      printVectorJSON(os, n->trialDisp());
      os << '}';
      first = false;
    }
    os << "\n    ],\n    \"elements\": [";
    first = true;
    for (const auto& [tag, e] : domain_->elements()) {
      if (!wantEle(tag)) continue;
      os << (first ? "\n      " : ",\n      ");
      e->printJSON(os);
      first = false;
    }
    os << "\n    ],\n    \"constraints\": [";
    first = true;
    for (const auto& s : domain_->sps()) {
      os << (first ? "\n      " : ",\n      ") << "{\"node\": " << s.nodeTag << ", \"dof\": " << s.dof + 1
         << ", \"value\": " << s.value << '}';
      first = false;
    }
    for (const auto& m : domain_->mps()) {
      os << (first ? "\n      " : ",\n      ") << "{\"type\": \"" << m.kind << "\", \"retained\": " << m.retainedNode
         << ", \"constrained\": " << m.constrainedNode << '}';
      first = false;
    }
    os << "\n    ]\n  }\n}}\n";
  } else {
    os << "Domain: time " << domain_->currentTime() << ", " << domain_->nodes().size() << " nodes, "
       << domain_->elements().size() << " elements, " << domain_->sps().size() << " single-point and "
       << domain_->mps().size() << " multi-point constraints, " << domain_->patterns().size() << " load patterns\n";
    const SolverInfo solver = solverInfo();
    if (!solver.system.empty())
      os << "System " << solver.system << " (" << solver.backend << "), " << solver.equations << " equations: "
         << solver.note << '\n';
    for (const auto& [tag, n] : domain_->nodes()) {
      if (!wantNode(tag)) continue;
      os << "Node " << tag << ": ndf " << n->ndf() << ", coordinates " << n->coordinates().transpose()
         << ", displacements " << n->trialDisp().transpose() << '\n';
    }
    for (const auto& [tag, e] : domain_->elements())
      if (wantEle(tag)) e->print(os);
  }
  // The Python layer prints the returned text through sys.stdout.
  if (file.empty()) {
    return os.str();
  } else {
    std::ofstream out(file);
    if (!out) a.fail("cannot open '" + file + "' for writing");
    out << os.str();
  }
  return {};
}

}  // namespace beamsolid
