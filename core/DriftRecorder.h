#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/Recorder.h"
#include "core/RecorderOutput.h"
#include "core/ResponseEnvelope.h"

namespace beamsolid {

class CommandArgs;
class Domain;

// recorder('Drift', '-file', f, <'-time'>, '-iNode', *i, '-jNode', *j, '-dof', *dofs, '-perpDirn', *dirs):
// one column per node pair k, the drift (u_j - u_i) / |X_j - X_i| of the
// pair's dof, the distance taken along the pair's perpendicular global
// direction (the storey height). One -dof / -perpDirn value serves every pair.
// With envelope, recorder('EnvelopeDrift', ...): the file holds three rows,
// min, max and max |value| over all records (each preceded by its time with -time).
class DriftRecorder : public Recorder {
 public:
  struct Pair {
    int iNode = 0, jNode = 0;
    int dof = 0;        // 0-based
    int perpDirn = 0;   // 0-based
    double length = 0;  // |X_j - X_i| along perpDirn, > 0
  };
  struct Spec {
    std::vector<Pair> pairs;
    RecorderOutput::Options output;
    std::string context;  // "recorder Drift"
    // Parses the arguments after the recorder type; checks nodes, dofs and lengths.
    static Spec parse(CommandArgs& args, const Domain& domain, const std::string& recorderType);
  };

  DriftRecorder(const Domain& domain, Spec spec, bool envelope);
  ~DriftRecorder() override;

  std::string className() const override { return envelope_ ? "EnvelopeDriftRecorder" : "DriftRecorder"; }
  void record(Domain& domain, double time) override;
  void flush() override;
  void close() override;

 private:
  Spec spec_;
  bool envelope_;
  std::unique_ptr<RecorderOutput> output_;
  ResponseEnvelope envelopeData_;
  bool changed_ = false;
  std::vector<double> values_, row_;
};

}  // namespace beamsolid
