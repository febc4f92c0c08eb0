#include "analysis/SensitivityAlgorithm.h"

#include <unordered_map>

#include "analysis/AnalysisModel.h"
#include "analysis/Integrator.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/Element.h"

namespace beamsolid {

namespace {

const char* kContext = "sensitivityAlgorithm";

// Each element's view of each parameter: [gradient][element index].
using Bindings = std::vector<std::vector<Element::SensitivityParameter>>;

Bindings bind(const ParameterMap& parameters, const std::vector<Element*>& elements) {
  std::unordered_map<int, int> index;
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) index[elements[e]->tag()] = e;
  Bindings bound(parameters.size(), std::vector<Element::SensitivityParameter>(elements.size()));
  int k = 0;
  for (const auto& [tag, parameter] : parameters) {
    const std::string where = std::string(kContext) + ": parameter " + std::to_string(tag);
    for (const Parameter::Target& t : parameter.targets) {
      if (t.kind == "element") {
        auto it = index.find(t.tag);
        if (it == index.end()) throw OpenSeesError(where + ": element " + std::to_string(t.tag) + " does not exist");
        Element& e = *elements[it->second];
        const int id = e.sensitivityParameter(t.args);
        std::string name;
        for (const auto& s : t.args) name += (name.empty() ? "" : " ") + s;
        if (id == 0)
          throw OpenSeesError(where + ": element " + std::to_string(t.tag) + " (" + e.className() +
                              ") has no parameter '" + name + "' it can differentiate");
        bound[k][it->second].id = id;
      } else {
        const int dim = std::stoi(t.args.at(0)) - 1;
        for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
          const auto& nodes = elements[e]->nodeTags();
          for (int n = 0; n < static_cast<int>(nodes.size()); ++n)
            if (nodes[n] == t.tag) {
              bound[k][e].node = n;
              bound[k][e].dim = dim;
            }
        }
      }
    }
    ++k;
  }
  return bound;
}

}  // namespace

void SensitivityAlgorithm::compute(AnalysisModel& model, Integrator& integrator) {
  results_.clear();
  if (parameters_.empty()) return;
  // Load control prescribes lambda; displacement control a dof, and lambda
  // follows. Other integrators (arc length, transient) are not built.
  std::vector<DofMap::Term> control;
  const bool controlled = integrator.controlledDof(control);
  if (integrator.name() != "LoadControl" && !controlled)
    throw OpenSeesError(std::string(kContext) + ": sensitivities are computed in static analyses under "
                        "integrator('LoadControl', ...) or ('DisplacementControl', ...); " + integrator.name() +
                        " is not supported");
  const DofMap& map = model.dofMap();
  const std::vector<Element*>& elements = map.elements();
  const Bindings bound = bind(parameters_, elements);
  const int numGradients = static_cast<int>(parameters_.size());
  for (const auto& [tag, parameter] : parameters_) results_.parameterTags.push_back(tag);
  for (const Node* n : map.nodes()) results_.nodeDisp[n->tag()] = Matrix::Zero(n->ndf(), numGradients);

  // The tangent at the converged state.
  integrator.formTangent(model, AnalysisModel::Stiffness::Current);
  if (!model.factor(AnalysisModel::Stiffness::Current))
    throw OpenSeesError(std::string(kContext) + ": the tangent at the converged state is singular: " +
                        model.describeFactorFailure());

  const int numEquations = model.numEquations();
  Vector rhs(numEquations), x(numEquations), reference;
  double eReference = 0.0;
  auto controlledValue = [&](const Vector& v) {
    double c = 0.0;
    for (const auto& t : control) c += t.coefficient * v[t.equation];
    return c;
  };
  if (controlled) {
    Vector load;
    model.formReferenceLoad(load);
    model.system().solve(load, reference);
    eReference = controlledValue(reference);
    if (eReference == 0.0)
      throw OpenSeesError(std::string(kContext) + ": the reference load does not move the controlled dof");
  }
  results_.lambda.assign(numGradients, 0.0);
  for (int k = 0; k < numGradients; ++k) {
    rhs.setZero();
    for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
      const Vector dR = elements[e]->resistingForceSensitivity(k, bound[k][e]);
      for (int i = 0; i < static_cast<int>(dR.size()); ++i)
        for (auto* t = map.elementTermsBegin(e, i); t != map.elementTermsEnd(e, i); ++t)
          rhs[t->equation] -= t->coefficient * dR[i];
    }
    model.system().solve(rhs, x);
    if (controlled) {
      results_.lambda[k] = -controlledValue(x) / eReference;
      x += results_.lambda[k] * reference;
    }
    for (int f = 0; f < map.numFullDofs(); ++f) {
      double du = 0.0;
      for (auto* t = map.fullTermsBegin(f); t != map.fullTermsEnd(f); ++t) du += t->coefficient * x[t->equation];
      results_.nodeDisp[map.nodeOfFull(f)->tag()](map.dofOfFull(f), k) = du;
    }
    for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
      Element& element = *elements[e];
      Vector dU(element.numDOF());
      int offset = 0;
      for (const Node* n : element.nodes()) {
        dU.segment(offset, n->ndf()) = results_.nodeDisp[n->tag()].col(k);
        offset += n->ndf();
      }
      element.commitSensitivity(k, bound[k][e], dU, numGradients);
    }
  }
}

}  // namespace beamsolid
