// Analysis commands of the Interpreter.
#include <algorithm>
#include <iostream>
#include <optional>
#include <set>

#include "analysis/EigenAnalysis.h"
#include "bindings/Interpreter.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

using Result = Interpreter::Result;

namespace {
template <class Product, class Table>
std::unique_ptr<Product> buildDefault(const Table& table, Domain& domain, const std::string& type,
                                      std::vector<CommandArgs::Value> args) {
  CommandArgs a("default", std::move(args));
  return table.get(type)(a, domain);
}
}  // namespace

Result Interpreter::constraints(CommandArgs& a) {
  components_.handler = Registry::global().constraintHandlers.build(a, *domain_);
  // A new handler may reuse the address of one freed earlier, so the model's
  // pointer comparison cannot be trusted to notice the change: renumber.
  if (analysis_) analysis_->model().invalidate();
  return {};
}

Result Interpreter::numberer(CommandArgs& a) {
  components_.numberer = Registry::global().numberers.build(a, *domain_);
  if (analysis_) analysis_->model().invalidate();  // as for constraints()
  return {};
}

Result Interpreter::system(CommandArgs& a) {
  components_.solver = Registry::global().systems.build(a, *domain_);
  if (analysis_) analysis_->model().invalidate();
  return {};
}

Result Interpreter::test(CommandArgs& a) {
  components_.test = Registry::global().tests.build(a, *domain_);
  return {};
}

Result Interpreter::algorithm(CommandArgs& a) {
  components_.algorithm = Registry::global().algorithms.build(a, *domain_);
  return {};
}

Result Interpreter::integrator(CommandArgs& a) {
  components_.integrator = Registry::global().integrators.build(a, *domain_);
  if (analysis_) analysis_->model().invalidate();
  return {};
}

// OpenSees' defaults for whatever the script did not choose.
void Interpreter::ensureAnalysisDefaults() {
  Registry& r = Registry::global();
  if (!components_.handler) components_.handler = buildDefault<ConstraintHandler>(r.constraintHandlers, *domain_, "Plain", {});
  if (!components_.numberer) components_.numberer = buildDefault<Numberer>(r.numberers, *domain_, "RCM", {});
  if (!components_.solver)
    components_.solver = buildDefault<LinearSolver>(r.systems, *domain_,
                                                    domain_->needsGeneralSolver() ? "UmfPack" : "ProfileSPD", {});
  if (!components_.test)
    components_.test = buildDefault<ConvergenceTest>(r.tests, *domain_, "NormUnbalance", {1e-6, 25LL});
  if (!components_.algorithm) components_.algorithm = buildDefault<Algorithm>(r.algorithms, *domain_, "Newton", {});
  if (!components_.integrator)
    components_.integrator = buildDefault<Integrator>(r.integrators, *domain_, "LoadControl", {1.0});
}

Result Interpreter::analysis(CommandArgs& a) {
  const std::string type = a.nextString("type");
  a.setContext("analysis " + type);
  while (!a.done()) a.restAsStrings();
  const bool transient = type == "Transient" || type == "VariableTransient";
  if (!transient && type != "Static")
    a.fail("analysis type '" + type + "' is unknown (expected 'Static', 'Transient' or 'VariableTransient')");
  // OpenSees' default integrator is LoadControl for Static, Newmark(0.5, 0.25) for Transient.
  if (transient && !components_.integrator)
    components_.integrator = buildDefault<Integrator>(Registry::global().integrators, *domain_, "Newmark",
                                                      {0.5, 0.25});
  ensureAnalysisDefaults();
  if (transient == components_.integrator->isStatic())
    a.fail("integrator " + components_.integrator->name() + " is " + (transient ? "static" : "transient") +
           ": choose a " + (transient ? "transient one (Newmark, HHT, CentralDifference)" : "static one") +
           " before analysis('" + type + "')");
  if (transient)
    analysis_ = std::make_unique<TransientAnalysis>(*domain_, components_, type == "VariableTransient");
  else
    analysis_ = std::make_unique<StaticAnalysis>(*domain_, components_);
  return {};
}

Result Interpreter::analyze(CommandArgs& a) {
  const int n = a.nextInt("numIncr");
  if (!analysis_) a.fail("no analysis: call analysis('Static') or analysis('Transient') first");
  if (n < 0) a.fail("numIncr must be non-negative");
  int code = 0;
  if (auto* transient = dynamic_cast<TransientAnalysis*>(analysis_.get())) {
    if (components_.integrator->isStatic())
      a.fail("integrator " + components_.integrator->name() + " is static; the analysis is transient");
    const double dt = a.nextDouble("dt");
    if (!(dt > 0.0)) a.fail("dt must be positive");
    if (transient->variable() && !a.done() && !a.nextIsString()) {
      const double dtMin = a.nextDouble("dtMin");
      const double dtMax = a.nextDouble("dtMax");
      const int jd = a.nextInt("Jd");
      if (!(dtMin > 0.0) || dtMax < dtMin) a.fail("need 0 < dtMin <= dtMax");
      if (jd < 1) a.fail("Jd must be at least 1");
      while (!a.done()) a.restAsStrings();  // '-noFlush'
      code = transient->analyze(n, dt, dtMin, dtMax, jd);
    } else {
      while (!a.done()) a.restAsStrings();
      code = transient->analyze(n, dt);
    }
  } else {
    while (!a.done()) a.restAsStrings();  // '-noFlush'; OpenSees ignores a dt in statics
    if (!components_.integrator->isStatic())
      a.fail("integrator " + components_.integrator->name() + " is not static");
    // analyze never throws once it runs (Analysis): a failure is a negative
    // code, its reason kept for last_error().
    code = static_cast<StaticAnalysis&>(*analysis_).analyze(n);
  }
  lastError_ = analysis_->lastError();
  // Recorded data reaches the disk after every analyze, success or not.
  domain_->flushRecorders();
  return static_cast<long long>(code);
}

Result Interpreter::wipeAnalysis(CommandArgs& a) {
  a.expectEnd();
  analysis_.reset();
  components_ = AnalysisComponents{};
  return {};
}

Result Interpreter::eigen(CommandArgs& a) {
  bool dense = false, standard = false;
  int numModes = 0;
  while (!a.done()) {
    if (a.nextIsString()) {
      const std::string opt = a.nextString("solver");
      if (opt == "-fullGenLapack") dense = true;
      else if (opt == "-standard") standard = true;  // K phi = lambda phi, as OpenSees
      else if (opt == "-genBandArpack" || opt == "-symmBandLapack" || opt == "-generalized") {}
      else {
        // OpenSees prints "unknown option" and solves with its default solver
        // (OpenSeesPy's own test_EigenFrameExtra passes -UmfPack, -SuperLU,
        // -ProfileSPD); the solver changes no eigenvalue, so do the same.
        std::cerr << "WARNING eigen - unknown option '" << opt
                  << "' ignored (known: -genBandArpack, -fullGenLapack, -symmBandLapack, -standard, "
                     "-generalized); the default solver runs\n";
      }
    } else {
      numModes = a.nextInt("numEigenvalues");
    }
  }
  if (numModes < 1) a.fail("the number of eigenvalues must be at least 1");
  // Eigen runs on the model's own numbering; it needs a handler and a
  // numberer, which it borrows from the analysis or creates by default.
  Registry& r = Registry::global();
  if (!components_.handler)
    components_.handler = buildDefault<ConstraintHandler>(r.constraintHandlers, *domain_, "Transformation", {});
  if (!components_.numberer) components_.numberer = buildDefault<Numberer>(r.numberers, *domain_, "RCM", {});
  auto solver = buildDefault<LinearSolver>(r.systems, *domain_, "UmfPack", {});
  AnalysisModel model(*domain_);
  model.setup(*components_.handler, *components_.numberer, *solver);
  if (numModes > model.numEquations())
    a.fail("asked for " + std::to_string(numModes) + " eigenvalues but the model has only " +
           std::to_string(model.numEquations()) + " equations");
  eigenvalues_ = EigenAnalysis::solve(model, numModes, dense, standard);
  haveModalProperties_ = false;
  domain_->setEigenvalues(eigenvalues_);
  return eigenvalues_;
}

Result Interpreter::getEigenvalues(CommandArgs& a) {
  a.expectEnd();
  return eigenvalues_;
}

Result Interpreter::testIter(CommandArgs& a) {
  a.expectEnd();
  if (!components_.test) a.fail("no convergence test: call test(...) or analysis(...) first");
  return static_cast<long long>(components_.test->reportedIterations());
}

// As OpenSees: one value per allowed iteration (maxIter), the norms of the
// last step's iterations followed by zeros.
Result Interpreter::testNorm(CommandArgs& a) {
  a.expectEnd();
  if (!components_.test) a.fail("no convergence test: call test(...) or analysis(...) first");
  // OpenSees pads the list with zeros to maxIter entries; a huge maxIter
  // (e.g. 2^31 - 1, "never give up") must not allocate gigabytes for it.
  constexpr int maxPadded = 100000;
  return components_.test->reportedNorms(maxPadded);
}

// As OpenSees: the size of the system as the last analyze built it (0 before
// the first one), not of the model as it stands.
Result Interpreter::systemSize(CommandArgs& a) {
  a.expectEnd();
  if (!analysis_) return 0LL;
  return static_cast<long long>(analysis_->model().numEquations());
}

Result Interpreter::reactions(CommandArgs& a) {
  Domain::ReactionKind kind = Domain::ReactionKind::Static;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-dynamic") kind = Domain::ReactionKind::Dynamic;
    else if (opt == "-rayleigh") kind = Domain::ReactionKind::Rayleigh;
    else a.fail("unknown option '" + opt + "' (expected -dynamic or -rayleigh)");
  }
  domain_->calculateReactions(kind);
  return {};
}

// rayleigh(alphaM, betaK, betaKinit, betaKcomm): global Rayleigh damping.
Result Interpreter::rayleigh(CommandArgs& a) {
  RayleighFactors f;
  f.alphaM = a.nextDouble("alphaM");
  f.betaK = a.nextDouble("betaK");
  f.betaKinit = a.nextDouble("betaKinit");
  f.betaKcomm = a.nextDouble("betaKcomm");
  a.expectEnd();
  domain_->setRayleigh(f);
  return {};
}

// modalDamping(factor) | modalDamping(f1, f2, ...): damping ratios of the
// modes of the last eigen (see core/ModalDamping.h).
Result Interpreter::modalDamping(CommandArgs& a) {
  std::vector<double> factors = a.nextDoubles("damping factor", 1);
  a.expectEnd();
  if (domain_->eigenvalues().empty()) a.fail("no eigen analysis: call eigen(n) before modalDamping");
  const std::size_t modes = domain_->eigenvalues().size();
  if (factors.size() > modes) {
    std::cerr << "WARNING modalDamping - more damping factors than modes were specified"
                 " - ignoring additional damping factors\n";
    factors.resize(modes);
  }
  domain_->setModalDamping(std::make_unique<ModalDamping>(std::move(factors)));
  return {};
}

// region(tag, '-ele' | '-eleOnly', *eles, '-eleRange' | '-eleOnlyRange', a, b,
// '-node' | '-nodeOnly', *nodes, '-nodeRange' | '-nodeOnlyRange', a, b,
// '-rayleigh', alphaM, betaK, betaKinit, betaKcomm). As OpenSees: a region of
// elements also holds their nodes (alphaM damps their nodal mass), one of
// nodes also the elements whose nodes all lie in it; given both, the elements
// win; ranges skip missing tags; the factors replace the global ones on the
// region's elements and nodes until the next rayleigh(). Unlike OpenSees, a
// listed tag that does not exist and a reused region tag are errors.
Result Interpreter::region(CommandArgs& a) {
  const int tag = a.nextInt("regTag");
  std::set<int> eles, nodes;
  bool eleOnly = false, nodeOnly = false, haveEles = false, haveNodes = false;
  std::optional<RayleighFactors> factors;
  auto range = [&](std::set<int>& into, const auto& existing) {
    const int first = a.nextInt("start tag"), last = a.nextInt("end tag");
    for (auto it = existing.lower_bound(first); it != existing.end() && it->first <= last; ++it) into.insert(it->first);
  };
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-ele" || opt == "-eleOnly") {
      for (int t : a.nextInts("element tags", 1)) {
        domain_->element(t, "region " + std::to_string(tag));
        eles.insert(t);
      }
      haveEles = true;
      eleOnly = opt == "-eleOnly";
    } else if (opt == "-eleRange" || opt == "-eleOnlyRange") {
      range(eles, domain_->elements());
      haveEles = true;
      eleOnly = opt == "-eleOnlyRange";
    } else if (opt == "-node" || opt == "-nodeOnly") {
      for (int t : a.nextInts("node tags", 1)) {
        domain_->node(t, "region " + std::to_string(tag));
        nodes.insert(t);
      }
      haveNodes = true;
      nodeOnly = opt == "-nodeOnly";
    } else if (opt == "-nodeRange" || opt == "-nodeOnlyRange") {
      range(nodes, domain_->nodes());
      haveNodes = true;
      nodeOnly = opt == "-nodeOnlyRange";
    } else if (opt == "-rayleigh") {
      RayleighFactors f;
      f.alphaM = a.nextDouble("alphaM");
      f.betaK = a.nextDouble("betaK");
      f.betaKinit = a.nextDouble("betaKinit");
      f.betaKcomm = a.nextDouble("betaKcomm");
      factors = f;
    } else {
      a.fail("unknown option '" + opt +
             "' (expected -ele, -eleOnly, -eleRange, -eleOnlyRange, -node, -nodeOnly, -nodeRange, "
             "-nodeOnlyRange or -rayleigh)");
    }
  }
  std::vector<Element*> regionEles;
  std::vector<Node*> regionNodes;
  if (haveEles) {
    for (int t : eles) regionEles.push_back(domain_->findElement(t));
    if (!eleOnly) {
      std::set<int> held;
      for (Element* e : regionEles) held.insert(e->nodeTags().begin(), e->nodeTags().end());
      for (int t : held) regionNodes.push_back(domain_->findNode(t));
    }
  } else if (haveNodes) {
    for (int t : nodes) regionNodes.push_back(domain_->findNode(t));
    if (!nodeOnly)
      for (const auto& [t, e] : domain_->elements())
        if (std::all_of(e->nodeTags().begin(), e->nodeTags().end(), [&](int n) { return nodes.count(n) > 0; }))
          regionEles.push_back(e.get());
  }
  Domain::Region held;
  for (const Node* n : regionNodes) held.nodes.push_back(n->tag());
  for (const Element* e : regionEles) held.elements.push_back(e->tag());
  if (!domain_->addRegion(tag, std::move(held))) a.fail("region with tag " + std::to_string(tag) + " already exists");
  if (factors) {
    for (Element* e : regionEles) e->setRegionRayleigh(*factors);
    for (Node* n : regionNodes) n->setRegionAlphaM(factors->alphaM);
    domain_->noteRegionRayleigh();
  }
  return {};
}

}  // namespace beamsolid
