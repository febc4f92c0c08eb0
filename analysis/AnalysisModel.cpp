#include "analysis/AnalysisModel.h"

#include <map>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>

#include "analysis/CondensedSolver.h"
#include "analysis/ConstraintHandler.h"
#include "analysis/Numberer.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

AnalysisModel::AnalysisModel(Domain& domain) : domain_(domain) {}
AnalysisModel::~AnalysisModel() = default;

namespace {

// BEAMSOLID_CONDENSE=on|off overrides the automatic choice (scripts unchanged).
LinearSolver::Condensation condensationMode(const LinearSolver& solver) {
  if (solver.condensation() != LinearSolver::Condensation::Auto) return solver.condensation();
  const char* env = std::getenv("BEAMSOLID_CONDENSE");
  if (env && (!std::strcmp(env, "on") || !std::strcmp(env, "1"))) return LinearSolver::Condensation::On;
  if (env && (!std::strcmp(env, "off") || !std::strcmp(env, "0"))) return LinearSolver::Condensation::Off;
  return LinearSolver::Condensation::Auto;
}

// BEAMSOLID_INTERFACE_REUSE=off: factor the interface afresh every time
// instead of GMRES with an earlier factorization (CondensedSolver); =always:
// reuse on interfaces of any size (tests: small models take that path too).
CondensedSolver::Reuse interfaceReuse() {
  const char* env = std::getenv("BEAMSOLID_INTERFACE_REUSE");
  if (env && (!std::strcmp(env, "off") || !std::strcmp(env, "0"))) return CondensedSolver::Reuse::Off;
  if (env && !std::strcmp(env, "always")) return CondensedSolver::Reuse::Always;
  return CondensedSolver::Reuse::Auto;
}

}  // namespace

void AnalysisModel::chooseSolver(LinearSolver& solver) {
  outer_ = &solver;
  const int n = map_.numEquations();
  const auto mode = condensationMode(solver);
  bool use = false;
  std::vector<char> interior;
  condensationNote_ = mode == LinearSolver::Condensation::Off ? "no condensation (switched off)"
                      : n == 0                                 ? "no condensation (no equations)"
                                                               : "no condensation (it failed on this model)";
  if (mode != LinearSolver::Condensation::Off && n > 0 && condensationRefusedStamp_ != builtStamp_) {
    // Interior: equations that constant-tangent elements touch and no other
    // (or only through a constant, uncoupled dof such as a multiplier's inert ones).
    interior.assign(n, 0);
    std::vector<char> variable(n, 0);
    const auto& elements = map_.elements();
    for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
      const bool constant = elements[e]->hasConstantTangent();
      for (int i = 0; i < map_.elementMaps()[e].numDOF; ++i) {
        const bool fixedRow = constant || elements[e]->hasConstantUncoupledDof(i);
        for (auto* t = map_.elementTermsBegin(e, i); t != map_.elementTermsEnd(e, i); ++t)
          (fixedRow ? interior : variable)[t->equation] = 1;
      }
    }
    int nI = 0;
    for (int eq = 0; eq < n; ++eq) {
      if (variable[eq]) interior[eq] = 0;
      nI += interior[eq];
    }
    const int nB = n - nI;
    // The dense interface costs nB^3/3 per factorization: worth it when the
    // interior is large and the interface small (measured in
    // benchmarks/condensation.py).
    // (lateral pile: 2.0x faster per iteration at 3,241 equations, interface
    // 937; 2.9x at 9,037, interface 1,837).
    // With the interface factorization reused across iterations (GMRES,
    // CondensedSolver) the dense interface pays up to about 12,000 equations
    // (two dense n_B^2 matrices: 2.3 GB there).
    const bool pays = n >= 2000 && nB <= 12000 && nI >= nB;
    use = nI > 0 && nB <= 20000 && (mode == LinearSolver::Condensation::On || pays);
    if (!use) condensationNote_ = "no condensation (" + std::to_string(nI) + " of " + std::to_string(n) + " equations condensable)";
  }
  if (!use) {
    condensedActive_ = false;
    system_.setSolver(&solver);
    return;
  }
  const auto reuse = solver.requiresSPD() ? CondensedSolver::Reuse::Off : interfaceReuse();
  if (!condensed_ || condensed_->interior() != interior || condensed_->requestedName() != solver.requestedName() ||
      condensed_->requiresSPD() != solver.requiresSPD() || condensed_->reuses() != reuse) {
    condensed_ = std::make_unique<CondensedSolver>(solver.requestedName(), solver.backend(), solver.requiresSPD(),
                                                   std::move(interior), reuse);
    system_.resetSolverState();
    condensationNote_ = "condensing " + std::to_string(condensed_->numInteriorEquations()) + " of " +
                        std::to_string(n) + " equations (constant-tangent elements only), interface of " +
                        std::to_string(n - condensed_->numInteriorEquations());
    std::cerr << "system " << solver.requestedName() << ": " << condensationNote_ << "\n";
  } else {
    // The same partition as before (a new analysis of the same model): say so again.
    condensationNote_ = "condensing " + std::to_string(condensed_->numInteriorEquations()) + " of " +
                        std::to_string(n) + " equations (constant-tangent elements only), interface of " +
                        std::to_string(n - condensed_->numInteriorEquations());
  }
  condensedActive_ = true;
  system_.setSolver(condensed_.get());
}

bool AnalysisModel::setup(const ConstraintHandler& handler, const Numberer& numberer, LinearSolver& solver) {
  // Compare what the handler and numberer are, not where they live: a new
  // object may reuse a freed address.
  const std::string configuration = handler.name() + "/" + std::to_string(handler.alphaS()) + "/" +
                                    std::to_string(handler.alphaM()) + "/" + numberer.name();
  const bool rebuild = builtStamp_ != domain_.modelStamp() || builtConfiguration_ != configuration;
  if (solver.requiresSPD() && domain_.needsGeneralSolver()) {
    std::string who;
    for (const auto& [tag, e] : domain_.elements())
      if (e->needsGeneralSolver()) {
        who = e->className() + " " + std::to_string(tag);
        break;
      }
    throw OpenSeesError("system " + solver.requestedName() + ": element " + who +
                        " makes the system unsymmetric or indefinite (contact multipliers, sliding friction); "
                        "the SPD-only solver CHOLMOD cannot factor it: use system('UmfPack')");
  }
  if (rebuild) {
    map_.build(domain_, handler, numberer);
    system_.setPattern(map_);
    builtStamp_ = domain_.modelStamp();
    builtConfiguration_ = configuration;
    imposedValues_.assign(map_.imposedFullDofs().size(), 0.0);
  }
  penaltyAlphaS_ = handler.alphaS();
  penaltyAlphaM_ = handler.alphaM();
  chooseSolver(solver);
  return rebuild;
}

void AnalysisModel::scatterElementMatrix(std::vector<double>& values, int e, const double* k) const {
  const DofMap::ElementMap& m = map_.elementMaps()[e];
  if (m.simple) {
    const int* pos = map_.scatterPositions(e);
    const int nn = m.numDOF * m.numDOF;
    for (int i = 0; i < nn; ++i)
      if (pos[i] >= 0) values[pos[i]] += k[i];
  } else {
    for (auto* s = map_.generalScatterBegin(e); s != map_.generalScatterEnd(e); ++s)
      values[s->position] += s->coefficient * k[s->local];
  }
}

void AnalysisModel::formTangent(Stiffness which) {
  system_.zeroA();
  system_.invalidateFactor();
  auto& values = system_.values();
  const auto& elements = map_.elements();
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
    MatrixView k = which == Stiffness::Initial ? elements[e]->initialStiff() : elements[e]->tangentStiff();
    scatterElementMatrix(values, e, k.data());
  }
  addPenaltyTangent(values, 1.0);
  factoredKind_ = int(which);
}

// Penalty springs (only present with the Penalty handler).
void AnalysisModel::addPenaltyTangent(std::vector<double>& values, double factor) const {
  for (const auto& sp : map_.penaltySPs()) values[sp.diagPosition] += factor * penaltyAlphaS_;
  for (const auto& mp : map_.penaltyMPs()) {
    int k = 0;
    for (const auto& b : mp.row)
      for (const auto& a : mp.row)
        values[mp.positions[k++]] += factor * penaltyAlphaM_ * a.coefficient * b.coefficient;
  }
}

void AnalysisModel::formDynamicTangent(Stiffness which, double cK, double cC, double cM) {
  system_.zeroA();
  system_.invalidateFactor();
  auto& values = system_.values();
  const bool damped = domain_.anyRayleigh();
  const auto& elements = map_.elements();
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
    Element& el = *elements[e];
    const RayleighFactors& r = el.rayleighFactors(domain_.rayleigh());
    const Matrix current = Matrix(el.tangentStiff());
    Matrix a = cK * (which == Stiffness::Initial ? Matrix(el.initialStiff()) : current);
    if (cC != 0.0 && damped && r.any()) a += cC * el.rayleighMatrix(r, current);
    if (cC != 0.0 && el.hasDampingTangent()) a += cC * el.dampingTangent();
    if (cM != 0.0) a += cM * Matrix(el.massMatrix());
    scatterElementMatrix(values, e, a.data());
  }
  for (int f = 0; f < map_.numFullDofs(); ++f) {
    const Node* node = map_.nodeOfFull(f);
    const double m = node->mass()[map_.dofOfFull(f)];
    const double nodal = cM + cC * node->alphaM(domain_.rayleigh().alphaM);
    if (m == 0.0 || nodal == 0.0) continue;
    for (auto* a = map_.fullTermsBegin(f); a != map_.fullTermsEnd(f); ++a)
      for (auto* b = map_.fullTermsBegin(f); b != map_.fullTermsEnd(f); ++b)
        values[map_.position(a->equation, b->equation)] += nodal * m * a->coefficient * b->coefficient;
  }
  addPenaltyTangent(values, cK);
  factoredKind_ = int(which);
}

void AnalysisModel::subtractInertiaAndDamping() {
  Vector& b = system_.b();
  const RayleighFactors& r = domain_.rayleigh();
  const bool damped = domain_.anyRayleigh();
  const auto& elements = map_.elements();
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
    Vector force = elements[e]->inertiaForce();
    if (damped) force += elements[e]->rayleighForce(elements[e]->rayleighFactors(r));
    const int n = map_.elementMaps()[e].numDOF;
    for (int i = 0; i < n; ++i)
      for (auto* t = map_.elementTermsBegin(e, i); t != map_.elementTermsEnd(e, i); ++t)
        b[t->equation] -= t->coefficient * force[i];
  }
  for (int f = 0; f < map_.numFullDofs(); ++f) {
    const Node* node = map_.nodeOfFull(f);
    const int d = map_.dofOfFull(f);
    const double m = node->mass()[d];
    if (m == 0.0) continue;
    const double p = m * (node->trialAccel()[d] + node->alphaM(r.alphaM) * node->trialVel()[d]);
    for (auto* t = map_.fullTermsBegin(f); t != map_.fullTermsEnd(f); ++t) b[t->equation] -= t->coefficient * p;
  }
  if (const ModalDamping* modal = domain_.modalDamping()) {
    const std::map<int, Vector> forces = modal->forces(domain_);
    for (int f = 0; f < map_.numFullDofs(); ++f) {
      auto it = forces.find(map_.nodeOfFull(f)->tag());
      if (it == forces.end()) continue;
      const double p = it->second[map_.dofOfFull(f)];
      for (auto* t = map_.fullTermsBegin(f); t != map_.fullTermsEnd(f); ++t) b[t->equation] -= t->coefficient * p;
    }
  }
}

void AnalysisModel::assembleMass(std::vector<double>& values) const {
  values.assign(map_.rowIndex().size(), 0.0);
  const auto& elements = map_.elements();
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
    MatrixView m = elements[e]->massMatrix();
    scatterElementMatrix(values, e, m.data());
  }
  for (int f = 0; f < map_.numFullDofs(); ++f) {
    const double m = map_.nodeOfFull(f)->mass()[map_.dofOfFull(f)];
    if (m == 0.0) continue;
    for (auto* a = map_.fullTermsBegin(f); a != map_.fullTermsEnd(f); ++a)
      for (auto* b = map_.fullTermsBegin(f); b != map_.fullTermsEnd(f); ++b)
        values[map_.position(a->equation, b->equation)] += m * a->coefficient * b->coefficient;
  }
}

void AnalysisModel::formUnbalance() {
  Vector& b = system_.b();
  b.setZero();
  for (int f = 0; f < map_.numFullDofs(); ++f) {
    const double p = map_.nodeOfFull(f)->unbalancedLoad()[map_.dofOfFull(f)];
    if (p == 0.0) continue;
    for (auto* t = map_.fullTermsBegin(f); t != map_.fullTermsEnd(f); ++t) b[t->equation] += t->coefficient * p;
  }
  const auto& elements = map_.elements();
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
    VectorView force = elements[e]->resistingForce();
    const int n = map_.elementMaps()[e].numDOF;
    for (int i = 0; i < n; ++i)
      for (auto* t = map_.elementTermsBegin(e, i); t != map_.elementTermsEnd(e, i); ++t)
        b[t->equation] -= t->coefficient * force[i];
  }
  if (!map_.penaltySPs().empty()) {
    const auto imposed = domain_.imposedValues(domain_.currentTime());
    for (std::size_t i = 0; i < map_.penaltySPs().size(); ++i) {
      const auto& sp = map_.penaltySPs()[i];
      const double u = map_.nodeOfFull(sp.full)->trialDisp()[map_.dofOfFull(sp.full)];
      b[sp.equation] += penaltyAlphaS_ * (imposed[i].value - u);
    }
  }
  for (const auto& mp : map_.penaltyMPs()) {
    double g = 0.0;
    for (const auto& a : mp.row) g += a.coefficient * map_.nodeOfFull(a.full)->trialDisp()[map_.dofOfFull(a.full)];
    for (const auto& a : mp.row) b[a.equation] -= penaltyAlphaM_ * a.coefficient * g;
  }
}

void AnalysisModel::formReferenceLoad(Vector& out) const {
  out = Vector::Zero(numEquations());
  const double t = domain_.currentTime();
  std::map<int, std::vector<std::pair<const ElementLoad*, double>>> loaded;  // element tag -> (load, slope)
  for (const auto& [tag, pattern] : domain_.patterns()) {
    const double slope = pattern->factorSlope(t);
    if (slope == 0.0) continue;
    for (const auto& nl : pattern->nodalLoads()) {
      const int start = map_.fullStartOfNode(nl.nodeTag);
      if (start < 0) continue;
      for (int d = 0; d < nl.load.size(); ++d)
        for (auto* term = map_.fullTermsBegin(start + d); term != map_.fullTermsEnd(start + d); ++term)
          out[term->equation] += slope * term->coefficient * nl.load[d];
    }
    for (const auto& el : pattern->elementLoads()) loaded[el.elementTag].push_back({&el.load, slope});
  }
  if (loaded.empty()) return;
  // The element loads of those patterns belong in -dR/dlambda too (OpenSees' reference load carries
  // their nodal equivalents; without them a path-following step converges only linearly when the
  // pushed pattern has element loads). Each loaded element's force is taken without its loads and
  // with them at the patterns' slopes, then its loads of the current time are put back. An element
  // whose loads act only through its state determination (forceBeamColumn) shows no difference here.
  const auto& elements = map_.elements();
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
    const auto it = loaded.find(elements[e]->tag());
    if (it == loaded.end()) continue;
    Element& element = *elements[e];
    element.zeroLoad();
    const Vector without = element.resistingForce();
    for (const auto& [load, slope] : it->second) element.addLoad(*load, slope);
    const Vector with = element.resistingForce();
    element.zeroLoad();
    for (const auto& [tag, pattern] : domain_.patterns()) {
      double factor = 0.0;
      bool any = false;
      for (const auto& el : pattern->elementLoads())
        if (el.elementTag == element.tag()) {
          if (!any) factor = pattern->factor(t), any = true;
          element.addLoad(el.load, factor);
        }
    }
    const int n = map_.elementMaps()[e].numDOF;
    for (int i = 0; i < n; ++i)
      for (auto* term = map_.elementTermsBegin(e, i); term != map_.elementTermsEnd(e, i); ++term)
        out[term->equation] += term->coefficient * (without[i] - with[i]);
  }
}

void AnalysisModel::applyIncrement(const Vector& dU) {
  for (int f = 0; f < map_.numFullDofs(); ++f) {
    double du = 0.0;
    for (auto* t = map_.fullTermsBegin(f); t != map_.fullTermsEnd(f); ++t) du += t->coefficient * dU[t->equation];
    if (du != 0.0) map_.nodeOfFull(f)->incrTrialDisp(map_.dofOfFull(f), du);
  }
  domain_.update();
}

void AnalysisModel::enforcePrescribed() {
  if (!map_.penaltySPs().empty()) return;  // penalty: values enter through the springs
  const auto imposed = domain_.imposedValues(domain_.currentTime());
  const auto& full = map_.imposedFullDofs();
  for (std::size_t i = 0; i < full.size() && i < imposed.size(); ++i)
    if (full[i] >= 0) map_.nodeOfFull(full[i])->setTrialDisp(map_.dofOfFull(full[i]), imposed[i].value);
  for (const auto& d : map_.dependents()) {
    double u = 0.0;
    for (const auto& [src, c] : d.sources) u += c * map_.nodeOfFull(src)->trialDisp()[map_.dofOfFull(src)];
    map_.nodeOfFull(d.full)->setTrialDisp(map_.dofOfFull(d.full), u);
  }
}

void AnalysisModel::trialDisplacement(Vector& out) const {
  out = Vector::Zero(numEquations());
  for (int f = 0; f < map_.numFullDofs(); ++f) {
    auto* t = map_.fullTermsBegin(f);
    if (map_.fullTermsEnd(f) - t == 1 && t->coefficient == 1.0)
      out[t->equation] = map_.nodeOfFull(f)->trialDisp()[map_.dofOfFull(f)];
  }
}

bool AnalysisModel::factor(Stiffness which) {
  (void)which;
  if (system_.factor()) return true;
  if (!condensedActive_) return false;
  // The interior block may be singular where the whole matrix is not (a
  // region held only through the interface): solve this pattern plainly.
  std::cerr << "system " << outer_->requestedName() << ": condensation failed (" << condensed_->lastError()
            << "); solving without it\n";
  condensationRefusedStamp_ = builtStamp_;
  condensationNote_ = "no condensation (it failed on this model: " + condensed_->lastError() + ")";
  condensedActive_ = false;
  system_.setSolver(outer_);
  return system_.factor();
}

std::string AnalysisModel::describeFactorFailure() const {
  std::ostringstream os;
  const LinearSolver* solver = system_.solver();
  os << (solver ? solver->lastError() : std::string("the matrix is singular"));
  // Equations with no stiffness at all are the usual cause: an unrestrained dof.
  const auto& values = system_.values();
  const auto& diag = map_.diagonalPosition();
  std::vector<int> zero;
  for (int eq = 0; eq < numEquations(); ++eq)
    if (values[diag[eq]] == 0.0) zero.push_back(eq);
  if (!zero.empty()) {
    os << "; no stiffness at";
    for (std::size_t i = 0; i < zero.size() && i < 5; ++i) {
      auto [node, dof] = map_.nodeDofOfEquation(zero[i]);
      os << (i ? ", " : " ") << "node " << node << " dof " << dof + 1;
    }
    if (zero.size() > 5) os << " and " << zero.size() - 5 << " more";
  } else if (solver && solver->failedEquation() >= 0 && solver->failedEquation() < numEquations()) {
    auto [node, dof] = map_.nodeDofOfEquation(solver->failedEquation());
    os << " (breakdown at node " << node << " dof " << dof + 1 << ")";
  }
  os << ": check the boundary conditions (fix) and connectivity, or the system type";
  return os.str();
}

}  // namespace beamsolid
