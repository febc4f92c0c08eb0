#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/Recorder.h"
#include "core/RecorderOutput.h"
#include "core/Types.h"

namespace beamsolid {

class CommandArgs;
class Node;
class TimeSeries;

// recorder('Node', '-file', f, <'-time'>, '-node', *tags, '-dof', *dofs, 'disp'):
// one row per record() with, for each node in the given order, one value per
// requested dof (0 for a dof beyond the node's ndf).
class NodeRecorder : public Recorder {
 public:
  enum class Quantity { Disp, Vel, Accel, IncrDisp, Reaction, Unbalance, Eigen };

  // What to record, as parsed from the command.
  struct Spec {
    std::vector<int> nodeTags;
    std::vector<int> dofs;  // 0-based
    Quantity quantity = Quantity::Disp;
    std::string responseName;  // e.g. "disp", "eigen 2"
    int mode = 0;              // eigen: 1-based mode number
    // -timeSeries: one series tag per dof (0: none), added to 'accel' to
    // give the absolute acceleration under a uniform ground motion.
    std::vector<int> accelSeries;
    RecorderOutput::Options output;
    std::string context;  // "recorder Node"

    // Parses the arguments after the recorder type; checks nodes and series.
    static Spec parse(CommandArgs& args, const Domain& domain, const std::string& recorderType);
  };

  NodeRecorder(const Domain& domain, Spec spec);

  std::string className() const override { return "NodeRecorder"; }
  void record(Domain& domain, double time) override;
  void flush() override;
  void close() override;

  const Spec& spec() const { return spec_; }
  const RecorderOutput& output() const { return *output_; }
  // Prefix of the XML ResponseType names, e.g. "D" for disp (D1, D2, ...).
  static const char* responsePrefix(Quantity q);

 protected:
  NodeRecorder(const Domain& domain, Spec spec, bool envelope);
  // The requested values now, node by node and dof by dof (no time).
  // For incrDisp this also advances the stored previous displacements.
  void readValues(Domain& domain, double time, std::vector<double>& out);

  Spec spec_;
  std::unique_ptr<RecorderOutput> output_;
  std::vector<double> values_;
  std::vector<double> row_;

 private:
  std::vector<std::shared_ptr<TimeSeries>> series_;  // per dof, may be null
  std::vector<Vector> previousDisp_;                 // incrDisp: per node, at the last record
};

}  // namespace beamsolid
