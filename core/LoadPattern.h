#pragma once
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/Constraints.h"
#include "core/ElementLoad.h"
#include "core/TimeSeries.h"
#include "core/Types.h"

namespace beamsolid {

class Domain;

// Plain load pattern: nodal loads, element loads and imposed displacements,
// all scaled by one time series. loadConst freezes its factor.
class LoadPattern {
 public:
  LoadPattern(int tag, std::shared_ptr<TimeSeries> series, double scale = 1.0);
  virtual ~LoadPattern() = default;
  // OpenSees' pattern type: Plain, UniformExcitation, MultipleSupport.
  virtual std::string typeName() const { return "Plain"; }

  int tag() const { return tag_; }
  const TimeSeries& series() const { return *series_; }

  struct NodalLoad {
    int nodeTag;
    Vector load;
  };
  struct EleLoad {
    int elementTag;
    ElementLoad load;
  };

  void addNodalLoad(int nodeTag, Vector load) { nodalLoads_.push_back({nodeTag, std::move(load)}); }
  void addElementLoad(int elementTag, ElementLoad load) { elementLoads_.push_back({elementTag, std::move(load)}); }
  void addSP(SPConstraint sp) {
    spDofs_.insert(dofKey(sp.nodeTag, sp.dof));
    sps_.push_back(sp);
  }
  bool removeSP(int nodeTag, int dof);
  bool hasSP(int nodeTag, int dof) const { return spDofs_.count(dofKey(nodeTag, dof)) > 0; }

  const std::vector<NodalLoad>& nodalLoads() const { return nodalLoads_; }
  const std::vector<EleLoad>& elementLoads() const { return elementLoads_; }
  const std::vector<SPConstraint>& sps() const { return sps_; }

  double factor(double time) const;
  double factorSlope(double time) const;
  virtual void setLoadConst(double time);
  bool isConstant() const { return constant_; }

  // Adds factor(time) * loads to nodes and elements of the domain.
  virtual void applyLoad(Domain& domain, double time) const;
  // The value an imposed displacement of this pattern has at time t.
  virtual double imposedValue(const SPConstraint& sp, double time) const { return factor(time) * sp.value; }
  // Adds slope(time) * nodal loads to `out` via the callback (reference load).
  void removeReferencesTo(int nodeTag, int elementTag);

 private:
  int tag_;
  std::shared_ptr<TimeSeries> series_;
  double scale_;
  bool constant_ = false;
  double constFactor_ = 0.0;
  std::vector<NodalLoad> nodalLoads_;
  std::vector<EleLoad> elementLoads_;
  std::vector<SPConstraint> sps_;
  std::unordered_set<std::int64_t> spDofs_;  // dofKey()s of sps_ (the sp command checks them per call)
};

}  // namespace beamsolid
