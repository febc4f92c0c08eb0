#pragma once
#include <vector>

#include "core/Types.h"

namespace beamsolid {

// A node: coordinates, ndf dofs with committed/trial response, lumped mass,
// the applied (unbalanced) load of the current time, and the reaction.
// Coordinates are stored padded to 3 with zeros, so geometry code works in
// every space; ndm says how many the user gave (and gets back).
class Node {
 public:
  Node(int tag, int ndf, const Vector3& coordinates, int ndm = 3);

  int tag() const { return tag_; }
  int ndf() const { return ndf_; }
  int ndm() const { return ndm_; }
  const Vector3& crd() const { return crd_; }
  // The ndm coordinates the user gave.
  Vector coordinates() const { return crd_.head(ndm_); }
  // setNodeCoord: the elements on this node must re-read it (Domain::nodeMoved).
  void setCoordinate(int dim, double value) { crd_[dim] = value; }

  const Vector& trialDisp() const { return trialDisp_; }
  const Vector& committedDisp() const { return committedDisp_; }
  // Increment since the last commit (trial - committed).
  Vector incrDisp() const { return trialDisp_ - committedDisp_; }
  const Vector& trialVel() const { return trialVel_; }
  const Vector& trialAccel() const { return trialAccel_; }
  const Vector& committedVel() const { return committedVel_; }
  const Vector& committedAccel() const { return committedAccel_; }

  void setTrialDisp(const Vector& u) { trialDisp_ = u; }
  void setTrialDisp(int dof, double value) { trialDisp_[dof] = value; }
  void incrTrialDisp(int dof, double du) { trialDisp_[dof] += du; }
  void setTrialVel(const Vector& v) { trialVel_ = v; }
  void setTrialAccel(const Vector& a) { trialAccel_ = a; }
  // An initial condition: trial and committed velocity of one dof.
  void setVelocity(int dof, double v) { trialVel_[dof] = committedVel_[dof] = v; }
  // One dof's trial response (transient integrators).
  void setTrialResponse(int dof, double u, double v, double a) {
    trialDisp_[dof] = u;
    trialVel_[dof] = v;
    trialAccel_[dof] = a;
  }

  void commitState();
  void revertToLastCommit();
  void revertToStart();

  // Diagonal lumped mass, one entry per dof.
  const Vector& mass() const { return mass_; }
  void setMass(const Vector& m) { mass_ = m; }
  // alphaM of a region(..., '-rayleigh', ...) that holds this node; it
  // replaces the global one until the next rayleigh() clears it.
  void setRegionAlphaM(double a) { regionAlphaM_ = a; hasRegionAlphaM_ = true; }
  void clearRegionAlphaM() { hasRegionAlphaM_ = false; }
  double alphaM(double global) const { return hasRegionAlphaM_ ? regionAlphaM_ : global; }

  // Nodal load of the current time, summed over load patterns.
  const Vector& unbalancedLoad() const { return load_; }
  void zeroUnbalancedLoad() { load_.setZero(); }
  void addUnbalancedLoad(const Vector& p, double factor) { load_ += factor * p; }

  const Vector& reaction() const { return reaction_; }
  void zeroReaction() { reaction_.setZero(); }
  void addReaction(const Vector& r) { reaction_ += r; }

  // Mode shapes from the last eigen analysis, one column per mode.
  const Matrix& eigenvectors() const { return eigenvectors_; }
  void setEigenvectors(Matrix phi) { eigenvectors_ = std::move(phi); }

 private:
  int tag_;
  int ndf_;
  int ndm_;
  Vector3 crd_;
  Vector trialDisp_, committedDisp_;
  Vector trialVel_, committedVel_;
  Vector trialAccel_, committedAccel_;
  Vector mass_;
  double regionAlphaM_ = 0.0;
  bool hasRegionAlphaM_ = false;
  Vector load_;
  Vector reaction_;
  Matrix eigenvectors_;
};

}  // namespace beamsolid
