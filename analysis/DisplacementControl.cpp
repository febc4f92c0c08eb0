#include "analysis/DisplacementControl.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

DisplacementControl::DisplacementControl(int nodeTag, int dof, double increment, int desiredIterations,
                                         double minIncrement, double maxIncrement)
    : nodeTag_(nodeTag),
      dof_(dof),
      increment_(increment),
      desiredIterations_(desiredIterations),
      minIncrement_(minIncrement),
      maxIncrement_(maxIncrement) {}

void DisplacementControl::resolve(AnalysisModel& model) {
  const std::string where = "integrator DisplacementControl";
  const Node* node = model.domain().findNode(nodeTag_);
  if (!node) throw OpenSeesError(where + ": node " + std::to_string(nodeTag_) + " does not exist");
  if (dof_ < 0 || dof_ >= node->ndf())
    throw OpenSeesError(where + ": dof " + std::to_string(dof_ + 1) + " is out of range for node " +
                        std::to_string(nodeTag_) + " (ndf " + std::to_string(node->ndf()) + ")");
  const DofMap& map = model.dofMap();
  const int f = map.fullStartOfNode(nodeTag_) + dof_;
  control_.assign(map.fullTermsBegin(f), map.fullTermsEnd(f));
  if (control_.empty())
    throw OpenSeesError(where + ": node " + std::to_string(nodeTag_) + " dof " + std::to_string(dof_ + 1) +
                        " is fixed (fix or sp): the controlled dof must be free");
}

double DisplacementControl::controlled(const Vector& v) const {
  double c = 0.0;
  for (const auto& t : control_) c += t.coefficient * v[t.equation];
  return c;
}

void DisplacementControl::domainChanged(AnalysisModel& model) { resolve(model); }

bool DisplacementControl::movesControlledDof(AnalysisModel& model) {
  referenceDisplacement(model);  // only the controlled component has to be usable here
  const double ep = controlled(referenceDisp_);
  return std::isfinite(ep) && ep != 0.0;
}

int DisplacementControl::newStep(AnalysisModel& model) {
  lastError_.clear();
  resolve(model);
  if (lastIterations_ > 0 && desiredIterations_ > 0) {
    const double lo = std::min(std::fabs(minIncrement_), std::fabs(maxIncrement_));
    const double hi = std::max(std::fabs(minIncrement_), std::fabs(maxIncrement_));
    const double size = std::clamp(std::fabs(increment_) * desiredIterations_ / lastIterations_, lo, hi);
    increment_ = std::copysign(size, increment_);
  }
  model.formReferenceLoad(referenceLoad_);
  if (referenceLoad_.lpNorm<Eigen::Infinity>() == 0.0)
    throw OpenSeesError("integrator DisplacementControl: the reference load is zero at time " +
                        std::to_string(model.domain().currentTime()) +
                        ": define a load pattern with nodal loads whose time series grows with time (e.g. Linear)");
  model.formTangent(AnalysisModel::Stiffness::Current);
  if (!model.factor(AnalysisModel::Stiffness::Current))
    return fail("the tangent is singular at the start of the step: " + model.describeFactorFailure());
  if (!movesControlledDof(model))
    return fail("the reference load does not move node " + std::to_string(nodeTag_) + " dof " +
                std::to_string(dof_ + 1));
  const Node& node = model.domain().node(nodeTag_, "integrator DisplacementControl");
  target_ = node.committedDisp()[dof_] + increment_;
  // Predictor: the tangent step that reaches the target.
  const double dLambda = (target_ - node.trialDisp()[dof_]) / controlled(referenceDisp_);
  applyLoadIncrement(model, dLambda, dLambda * referenceDisp_);
  return 0;
}

int DisplacementControl::update(AnalysisModel& model, const Vector& dU) {
  LinearSystem& system = model.system();
  if (!system.isFactored()) return fail("update without a factored tangent");
  const Vector residualDisp = dU;  // dU may alias system.x(), rewritten below
  if (!movesControlledDof(model))
    return fail("the reference load no longer moves node " + std::to_string(nodeTag_) + " dof " +
                std::to_string(dof_ + 1) + " (singular constraint)");
  const Node& node = model.domain().node(nodeTag_, "integrator DisplacementControl");
  // Aim at the target itself, not at a zero change: drift cannot accumulate.
  const double dLambda =
      (target_ - node.trialDisp()[dof_] - controlled(residualDisp)) / controlled(referenceDisp_);
  system.x() = residualDisp + dLambda * referenceDisp_;
  applyLoadIncrement(model, dLambda, system.x());
  return 0;
}

void DisplacementControl::commit(AnalysisModel&, int iterations) { lastIterations_ = iterations; }

void DisplacementControl::revert(AnalysisModel&) {
  // The Domain is back at its last commit (time = lambda included); nothing
  // of the failed step is kept here but the error message.
  target_ = 0.0;
}

namespace {
std::unique_ptr<Integrator> buildDisplacementControl(CommandArgs& args, Domain&) {
  const int nodeTag = args.nextInt("nodeTag");
  const int dof = args.nextInt("dof");
  const double incr = args.nextDouble("incr");
  int numIter = 1;
  double dUmin = incr, dUmax = incr;
  if (!args.done()) {
    numIter = args.nextInt("numIter");
    dUmin = args.nextDouble("dUmin");
    dUmax = args.nextDouble("dUmax");
  }
  args.expectEnd();
  if (dof < 1) args.fail("dof must be at least 1 (dofs are 1-based), got " + std::to_string(dof));
  if (incr == 0.0) args.fail("incr must be nonzero");
  if (numIter < 0) args.fail("numIter must be non-negative");
  return std::make_unique<DisplacementControl>(nodeTag, dof - 1, incr, numIter, dUmin, dUmax);
}
void registerDisplacementControl(Registry& r) { r.integrators.add("DisplacementControl", &buildDisplacementControl); }
}  // namespace
BEAMSOLID_REGISTER(registerDisplacementControl);

}  // namespace beamsolid
