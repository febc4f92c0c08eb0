#include "core/NodeRecorder.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "core/ResponseEnvelope.h"
#include "core/TimeSeries.h"

namespace beamsolid {

namespace {

const char* const kResponseList = "disp, vel, accel, incrDisp, reaction, unbalance or eigen <mode>";

bool quantityFromName(const std::string& name, NodeRecorder::Quantity& q) {
  using Q = NodeRecorder::Quantity;
  if (name == "disp") q = Q::Disp;
  else if (name == "vel") q = Q::Vel;
  else if (name == "accel") q = Q::Accel;
  else if (name == "incrDisp") q = Q::IncrDisp;
  else if (name == "reaction") q = Q::Reaction;
  else if (name == "unbalance") q = Q::Unbalance;
  else if (name == "eigen") q = Q::Eigen;
  else return false;
  return true;
}

std::string rowsDescription(const RecorderOutput::Options& o) {
  std::ostringstream os;
  os << "one per converged step (and per record() call)";
  if (o.deltaT > 0.0) os << ", only when the time has advanced by at least dT = " << o.deltaT;
  return os.str();
}

}  // namespace

const char* NodeRecorder::responsePrefix(Quantity q) {
  switch (q) {
    case Quantity::Disp: return "D";
    case Quantity::Vel: return "V";
    case Quantity::Accel: return "A";
    case Quantity::IncrDisp: return "dD";
    case Quantity::Reaction: return "R";
    case Quantity::Unbalance: return "P";
    case Quantity::Eigen: return "E";
  }
  return "?";
}

NodeRecorder::Spec NodeRecorder::Spec::parse(CommandArgs& args, const Domain& domain, const std::string& recorderType) {
  Spec s;
  s.context = "recorder " + recorderType;
  args.setContext(s.context);
  bool haveResponse = false;
  while (!args.done()) {
    if (s.output.parse(args)) continue;
    if (args.nextFlag("-node") || args.nextFlag("-nodes")) {
      for (int t : args.nextInts("node tags", 1)) s.nodeTags.push_back(t);
    } else if (args.nextFlag("-nodeRange")) {
      const int first = args.nextInt("first node");
      const int last = args.nextInt("last node");
      if (last < first) args.fail("'-nodeRange' " + std::to_string(first) + " " + std::to_string(last) +
                                  ": the last tag is smaller than the first");
      std::size_t found = 0;
      for (const auto& [tag, node] : domain.nodes())
        if (tag >= first && tag <= last) {
          s.nodeTags.push_back(tag);
          ++found;
        }
      if (found == 0) args.fail("'-nodeRange' " + std::to_string(first) + " " + std::to_string(last) +
                                ": no node has a tag in this range");
    } else if (args.nextFlag("-region")) {
      const int tag = args.nextInt("regTag");
      const Domain::Region& region = domain.region(tag, s.context);
      if (region.nodes.empty()) args.fail("region " + std::to_string(tag) + " holds no nodes");
      s.nodeTags.insert(s.nodeTags.end(), region.nodes.begin(), region.nodes.end());
    } else if (args.nextFlag("-dof")) {
      const std::size_t at = args.position();
      for (int d : args.nextInts("dof", 1)) {
        if (d < 1) args.failAt(at, "dof", "dof numbers >= 1 (1-based)");
        s.dofs.push_back(d - 1);
      }
    } else if (args.nextFlag("-timeSeries")) {
      s.accelSeries = args.nextInts("timeSeries tags", 1);
    } else if (auto word = args.peekString()) {
      if (word->empty() || (*word)[0] == '-')
        args.failAt(args.position(), "option",
                    "a recorder option ('-file', '-time', '-node', '-dof', ...) or a response type (" +
                        std::string(kResponseList) + ")");
      const std::size_t at = args.position();
      s.responseName = args.nextString("response");
      if (!quantityFromName(s.responseName, s.quantity))
        args.failAt(at, "response", std::string("one of ") + kResponseList);
      if (s.quantity == Quantity::Eigen) {
        const std::size_t modeAt = args.position();
        s.mode = args.nextInt("mode");
        if (s.mode < 1) args.failAt(modeAt, "mode", "a mode number >= 1");
        s.responseName.append(1, ' ').append(std::to_string(s.mode));
      }
      haveResponse = true;
      break;
    } else {
      args.failAt(args.position(), "option", "a recorder option or a response type");
    }
  }
  if (!haveResponse) args.fail(std::string("the response type is missing; expected one of ") + kResponseList);
  args.expectEnd();
  s.output.requireFile(args);
  if (s.nodeTags.empty())
    args.fail("no nodes given; expected '-node', *tags, '-nodeRange', first, last or '-region', regTag");

  int maxNdf = 0;
  for (int t : s.nodeTags) maxNdf = std::max(maxNdf, domain.node(t, s.context).ndf());
  if (s.dofs.empty())
    for (int d = 0; d < maxNdf; ++d) s.dofs.push_back(d);

  if (!s.accelSeries.empty()) {
    // OpenSees adds the series value to disp, vel and accel alike (the
    // user passes the ground's displacement, velocity or acceleration series).
    if (s.quantity != Quantity::Accel && s.quantity != Quantity::Vel && s.quantity != Quantity::Disp)
      args.fail("'-timeSeries' (absolute response under ground motion) is supported for 'disp', 'vel' and 'accel'");
    if (s.accelSeries.size() != s.dofs.size())
      args.fail("'-timeSeries' needs one series tag per recorded dof (" + std::to_string(s.dofs.size()) +
                "), got " + std::to_string(s.accelSeries.size()));
    for (int t : s.accelSeries)
      if (t > 0) domain.timeSeries.get(t, s.context);
  }
  return s;
}

NodeRecorder::NodeRecorder(const Domain& domain, Spec spec) : NodeRecorder(domain, std::move(spec), false) {}

NodeRecorder::NodeRecorder(const Domain& domain, Spec spec, bool envelope) : spec_(std::move(spec)) {
  if (spec_.context.empty()) spec_.context = envelope ? "recorder EnvelopeNode" : "recorder Node";
  if (spec_.nodeTags.empty()) throw OpenSeesError(spec_.context + ": no nodes given");
  for (int d : spec_.dofs)
    if (d < 0) throw OpenSeesError(spec_.context + ": dof numbers must be >= 1");

  for (int t : spec_.accelSeries) series_.push_back(t > 0 ? domain.timeSeries.shared(t, spec_.context) : nullptr);

  const bool echoTime = spec_.output.echoTime;
  const std::string prefix = responsePrefix(spec_.quantity);
  std::vector<RecorderOutput::Column> columns;
  std::vector<RecorderOutput::XmlBlock> blocks;
  if (echoTime && !envelope) {
    columns.push_back(RecorderOutput::Column::time());
    blocks.push_back(RecorderOutput::timeBlock());
  }
  for (int tag : spec_.nodeTags) {
    const Node& node = domain.node(tag, spec_.context);
    previousDisp_.push_back(node.trialDisp());
    // OpenSees' XML: coordinates at the recorder's precision; an envelope
    // names the node only and puts a time block before each response type.
    RecorderOutput::XmlBlock block{"NodeOutput", {{"nodeTag", std::to_string(tag)}}, {}};
    if (!envelope) {
      for (int i = 0; i < node.ndm(); ++i) {
        char coord[64];
        std::snprintf(coord, sizeof coord, "%.*g", spec_.output.precision, node.crd()[i]);
        block.attributes.emplace_back("coord" + std::to_string(i + 1), coord);
      }
    }
    block.timeBeforeEach = envelope && echoTime;
    for (int d : spec_.dofs) {
      const std::string type = prefix + std::to_string(d + 1);
      columns.push_back(RecorderOutput::Column::ofNode("n" + std::to_string(tag) + "_" + type, tag, d + 1,
                                                       spec_.responseName));
      block.responseTypes.push_back(type);
    }
    blocks.push_back(std::move(block));
  }

  std::string rows = rowsDescription(spec_.output);
  if (envelope) {
    columns = ResponseEnvelope::columns(columns, echoTime);
    rows = "three rows: min, max and max |value| of each column over all records";
  }
  const char* type = envelope ? "EnvelopeNode" : "Node";
  output_ = std::make_unique<RecorderOutput>(spec_.output, std::move(columns), std::move(blocks), rows,
                                             spec_.context, OutputFileClaim::Holder::beingAddedTo(domain, type));
  values_.reserve(spec_.nodeTags.size() * spec_.dofs.size());
}

void NodeRecorder::readValues(Domain& domain, double time, std::vector<double>& out) {
  out.clear();
  if (spec_.quantity == Quantity::Reaction) domain.calculateReactions();
  for (std::size_t n = 0; n < spec_.nodeTags.size(); ++n) {
    const Node* node = domain.findNode(spec_.nodeTags[n]);
    if (!node) {  // removed since the recorder was made
      out.insert(out.end(), spec_.dofs.size(), 0.0);
      continue;
    }
    const Vector* source = nullptr;
    Vector increment;
    switch (spec_.quantity) {
      case Quantity::Disp: source = &node->trialDisp(); break;
      case Quantity::Vel: source = &node->trialVel(); break;
      case Quantity::Accel: source = &node->trialAccel(); break;
      case Quantity::Reaction: source = &node->reaction(); break;
      case Quantity::Unbalance: source = &node->unbalancedLoad(); break;
      case Quantity::IncrDisp:
        if (previousDisp_[n].size() != node->trialDisp().size()) previousDisp_[n] = Vector::Zero(node->ndf());
        increment = node->trialDisp() - previousDisp_[n];
        previousDisp_[n] = node->trialDisp();
        source = &increment;
        break;
      case Quantity::Eigen: break;
    }
    for (std::size_t k = 0; k < spec_.dofs.size(); ++k) {
      const int d = spec_.dofs[k];
      double v = 0.0;
      if (spec_.quantity == Quantity::Eigen) {
        const Matrix& phi = node->eigenvectors();
        if (d < phi.rows() && spec_.mode - 1 < phi.cols()) v = phi(d, spec_.mode - 1);
      } else if (d < source->size()) {
        v = (*source)[d];
      }
      if (k < series_.size() && series_[k]) v += series_[k]->factor(time);
      out.push_back(v);
    }
  }
}

void NodeRecorder::record(Domain& domain, double time) {
  if (output_->closed()) return;
  const bool due = output_->due(time);
  // incrDisp must see every step to know the previous displacement.
  if (!due && spec_.quantity != Quantity::IncrDisp) return;
  readValues(domain, time, values_);
  if (!due) return;
  row_.clear();
  if (spec_.output.echoTime) row_.push_back(time);
  row_.insert(row_.end(), values_.begin(), values_.end());
  output_->writeRow(time, row_);
}

void NodeRecorder::flush() { output_->flush(); }

void NodeRecorder::close() { output_->close(); }

namespace {

std::unique_ptr<Recorder> buildNodeRecorder(CommandArgs& args, Domain& domain) {
  return std::make_unique<NodeRecorder>(domain, NodeRecorder::Spec::parse(args, domain, "Node"));
}

void registerNodeRecorder(Registry& r) { r.recorders.add("Node", &buildNodeRecorder); }

}  // namespace
BEAMSOLID_REGISTER(registerNodeRecorder);

}  // namespace beamsolid
