#include "core/DriftRecorder.h"

#include <cmath>
#include <sstream>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {

// One value per pair, or one value for all pairs.
std::vector<int> perPair(const std::vector<int>& given, std::size_t pairs, const char* option, CommandArgs& args) {
  if (given.size() == pairs) return given;
  if (given.size() == 1) return std::vector<int>(pairs, given.front());
  args.fail(std::string("'") + option + "' needs one value, or one per node pair (" + std::to_string(pairs) +
            "), got " + std::to_string(given.size()));
}

}  // namespace

DriftRecorder::Spec DriftRecorder::Spec::parse(CommandArgs& args, const Domain& domain,
                                               const std::string& recorderType) {
  Spec s;
  s.context = "recorder " + recorderType;
  args.setContext(s.context);
  std::vector<int> iNodes, jNodes, dofs, dirs;
  while (!args.done()) {
    if (s.output.parse(args)) continue;
    if (args.nextFlag("-iNode") || args.nextFlag("-iNodes")) {
      for (int t : args.nextInts("iNode tags", 1)) iNodes.push_back(t);
    } else if (args.nextFlag("-jNode") || args.nextFlag("-jNodes")) {
      for (int t : args.nextInts("jNode tags", 1)) jNodes.push_back(t);
    } else if (args.nextFlag("-dof")) {
      const std::size_t at = args.position();
      for (int d : args.nextInts("dof", 1)) {
        if (d < 1) args.failAt(at, "dof", "dof numbers >= 1 (1-based)");
        dofs.push_back(d - 1);
      }
    } else if (args.nextFlag("-perpDirn")) {
      const std::size_t at = args.position();
      for (int d : args.nextInts("perpDirn", 1)) {
        if (d < 1 || d > 3) args.failAt(at, "perpDirn", "a global direction 1 (X), 2 (Y) or 3 (Z)");
        dirs.push_back(d - 1);
      }
    } else {
      args.failAt(args.position(), "option",
                  "a recorder option ('-file', '-xml', '-time', '-precision', '-dT', '-closeOnWrite', "
                  "'-iNode', '-jNode', '-dof', '-perpDirn')");
    }
  }
  s.output.requireFile(args);
  if (iNodes.empty()) args.fail("no iNodes given; expected '-iNode', *tags");
  if (jNodes.empty()) args.fail("no jNodes given; expected '-jNode', *tags");
  if (iNodes.size() != jNodes.size())
    args.fail("'-iNode' and '-jNode' need the same number of nodes, got " + std::to_string(iNodes.size()) + " and " +
              std::to_string(jNodes.size()));
  if (dofs.empty()) args.fail("'-dof' is missing; expected '-dof', dof (1-based)");
  if (dirs.empty()) args.fail("'-perpDirn' is missing; expected '-perpDirn', 1 (X), 2 (Y) or 3 (Z)");
  dofs = perPair(dofs, iNodes.size(), "-dof", args);
  dirs = perPair(dirs, iNodes.size(), "-perpDirn", args);

  for (std::size_t k = 0; k < iNodes.size(); ++k) {
    const Node& ni = domain.node(iNodes[k], s.context + " (iNode)");
    const Node& nj = domain.node(jNodes[k], s.context + " (jNode)");
    Pair p{iNodes[k], jNodes[k], dofs[k], dirs[k], 0.0};
    const std::string pair = "pair " + std::to_string(k + 1) + " (iNode " + std::to_string(p.iNode) + ", jNode " +
                             std::to_string(p.jNode) + ")";
    if (p.dof >= ni.ndf() || p.dof >= nj.ndf())
      args.fail("'-dof' " + std::to_string(p.dof + 1) + " of " + pair + " exceeds the nodes' ndf");
    if (p.perpDirn >= ni.ndm() || p.perpDirn >= nj.ndm())
      args.fail("'-perpDirn' " + std::to_string(p.perpDirn + 1) + " of " + pair + " exceeds the model's ndm");
    p.length = std::fabs(nj.crd()[p.perpDirn] - ni.crd()[p.perpDirn]);
    if (!(p.length > 0.0))
      args.fail("'-perpDirn' " + std::to_string(p.perpDirn + 1) + ": the nodes of " + pair +
                " have the same coordinate in that direction (zero length)");
    s.pairs.push_back(p);
  }
  return s;
}

DriftRecorder::DriftRecorder(const Domain& domain, Spec spec, bool envelope)
    : spec_(std::move(spec)), envelope_(envelope) {
  if (spec_.pairs.empty()) throw OpenSeesError(spec_.context + ": no node pairs given");
  const bool echoTime = spec_.output.echoTime;
  std::vector<RecorderOutput::Column> columns;
  std::vector<RecorderOutput::XmlBlock> blocks;
  if (echoTime && !envelope_) {
    columns.push_back(RecorderOutput::Column::time());
    blocks.push_back(RecorderOutput::timeBlock());
  }
  for (const Pair& p : spec_.pairs) {
    const std::string name = "drift_" + std::to_string(p.iNode) + "_" + std::to_string(p.jNode);
    RecorderOutput::Column c{name, -1, p.dof + 1, -1, "drift", {}, {}};
    c.meaning = "(u_j - u_i) / |X_j - X_i| of dof " + std::to_string(p.dof + 1) + ", length along direction " +
                std::to_string(p.perpDirn + 1) + ": iNode " + std::to_string(p.iNode) + ", jNode " +
                std::to_string(p.jNode);
    columns.push_back(std::move(c));
    RecorderOutput::XmlBlock block{"DriftOutput",
                                   {{"node1", std::to_string(p.iNode)},
                                    {"node2", std::to_string(p.jNode)},
                                    {"dof", std::to_string(p.dof + 1)},
                                    {"perpDirn", std::to_string(p.perpDirn + 1)}},
                                   {"drift"}};
    block.timeBeforeEach = envelope_ && echoTime;
    blocks.push_back(std::move(block));
  }
  std::string rows = "one per converged step (and per record() call)";
  if (spec_.output.deltaT > 0.0) {
    std::ostringstream os;
    os << ", only when the time has advanced by at least dT = " << spec_.output.deltaT;
    rows += os.str();
  }
  if (envelope_) {
    columns = ResponseEnvelope::columns(columns, echoTime);
    rows = "three rows: min, max and max |value| of each column over all records";
  }
  const char* type = envelope_ ? "EnvelopeDrift" : "Drift";
  output_ = std::make_unique<RecorderOutput>(spec_.output, std::move(columns), std::move(blocks), rows,
                                             spec_.context, OutputFileClaim::Holder::beingAddedTo(domain, type));
}

DriftRecorder::~DriftRecorder() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw.
  }
}

void DriftRecorder::record(Domain& domain, double time) {
  if (output_->closed() || !output_->due(time)) return;
  values_.clear();
  for (const Pair& p : spec_.pairs) {
    const Node* ni = domain.findNode(p.iNode);
    const Node* nj = domain.findNode(p.jNode);
    // A node removed since the recorder was made reads as zero displacement.
    const double ui = ni && p.dof < ni->trialDisp().size() ? ni->trialDisp()[p.dof] : 0.0;
    const double uj = nj && p.dof < nj->trialDisp().size() ? nj->trialDisp()[p.dof] : 0.0;
    values_.push_back((uj - ui) / p.length);
  }
  if (envelope_) {
    envelopeData_.add(time, values_);
    output_->noteRecorded(time);
    changed_ = true;
    return;
  }
  row_.clear();
  if (spec_.output.echoTime) row_.push_back(time);
  row_.insert(row_.end(), values_.begin(), values_.end());
  output_->writeRow(time, row_);
}

void DriftRecorder::flush() {
  if (output_->closed()) return;
  if (envelope_) {
    if (!changed_) return;
    output_->rewriteRows(envelopeData_.rows(spec_.output.echoTime));
    changed_ = false;
    return;
  }
  output_->flush();
}

void DriftRecorder::close() {
  flush();
  output_->close();
}

namespace {

std::unique_ptr<Recorder> buildDriftRecorder(CommandArgs& args, Domain& domain) {
  return std::make_unique<DriftRecorder>(domain, DriftRecorder::Spec::parse(args, domain, "Drift"), false);
}

std::unique_ptr<Recorder> buildEnvelopeDriftRecorder(CommandArgs& args, Domain& domain) {
  return std::make_unique<DriftRecorder>(domain, DriftRecorder::Spec::parse(args, domain, "EnvelopeDrift"), true);
}

void registerDriftRecorders(Registry& r) {
  r.recorders.add("Drift", &buildDriftRecorder);
  r.recorders.add("EnvelopeDrift", &buildEnvelopeDriftRecorder);
}

}  // namespace
BEAMSOLID_REGISTER(registerDriftRecorders);

}  // namespace beamsolid
