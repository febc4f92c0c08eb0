#include "elements/TangentCheck.h"

#include "core/Node.h"
#include "elements/Element.h"

namespace beamsolid {

TangentCheck TangentCheck::of(Element& element, double h) {
  TangentCheck check;
  element.update();
  check.tangent = element.tangentStiff();
  check.difference.resize(element.numDOF(), element.numDOF());
  int column = 0;
  for (Node* node : element.nodes()) {
    for (int dof = 0; dof < node->ndf(); ++dof, ++column) {
      const double u = node->trialDisp()[dof];
      try {
        node->setTrialDisp(dof, u + h);
        element.update();
        const Vector plus = element.resistingForce();
        node->setTrialDisp(dof, u - h);
        element.update();
        check.difference.col(column) = (plus - Vector(element.resistingForce())) / (2.0 * h);
      } catch (...) {
        // The model stays as it was, also when the element refuses a state.
        node->setTrialDisp(dof, u);
        element.update();
        throw;
      }
      node->setTrialDisp(dof, u);
    }
  }
  element.update();
  return check;
}

}  // namespace beamsolid
