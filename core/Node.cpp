#include "core/Node.h"

namespace beamsolid {

Node::Node(int tag, int ndf, const Vector3& coordinates, int ndm)
    : tag_(tag),
      ndf_(ndf),
      ndm_(ndm),
      crd_(coordinates),
      trialDisp_(Vector::Zero(ndf)),
      committedDisp_(Vector::Zero(ndf)),
      trialVel_(Vector::Zero(ndf)),
      committedVel_(Vector::Zero(ndf)),
      trialAccel_(Vector::Zero(ndf)),
      committedAccel_(Vector::Zero(ndf)),
      mass_(Vector::Zero(ndf)),
      load_(Vector::Zero(ndf)),
      reaction_(Vector::Zero(ndf)) {}

void Node::commitState() {
  committedDisp_ = trialDisp_;
  committedVel_ = trialVel_;
  committedAccel_ = trialAccel_;
}

void Node::revertToLastCommit() {
  trialDisp_ = committedDisp_;
  trialVel_ = committedVel_;
  trialAccel_ = committedAccel_;
}

void Node::revertToStart() {
  for (Vector* v : {&trialDisp_, &committedDisp_, &trialVel_, &committedVel_, &trialAccel_,
                    &committedAccel_, &reaction_})
    v->setZero();
}

}  // namespace beamsolid
