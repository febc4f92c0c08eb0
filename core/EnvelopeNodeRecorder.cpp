#include "core/EnvelopeNodeRecorder.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

EnvelopeNodeRecorder::EnvelopeNodeRecorder(const Domain& domain, Spec spec)
    : NodeRecorder(domain, std::move(spec), true) {}

EnvelopeNodeRecorder::~EnvelopeNodeRecorder() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw.
  }
}

void EnvelopeNodeRecorder::record(Domain& domain, double time) {
  if (output_->closed()) return;
  const bool due = output_->due(time);
  if (!due && spec_.quantity != Quantity::IncrDisp) return;
  readValues(domain, time, values_);
  if (!due) return;
  envelope_.add(time, values_);
  output_->noteRecorded(time);
  changed_ = true;
}

void EnvelopeNodeRecorder::flush() {
  if (output_->closed() || !changed_) return;
  output_->rewriteRows(envelope_.rows(spec_.output.echoTime));
  changed_ = false;
}

void EnvelopeNodeRecorder::close() {
  flush();
  output_->close();
}

namespace {

std::unique_ptr<Recorder> buildEnvelopeNodeRecorder(CommandArgs& args, Domain& domain) {
  return std::make_unique<EnvelopeNodeRecorder>(domain, NodeRecorder::Spec::parse(args, domain, "EnvelopeNode"));
}

void registerEnvelopeNodeRecorder(Registry& r) { r.recorders.add("EnvelopeNode", &buildEnvelopeNodeRecorder); }

}  // namespace
BEAMSOLID_REGISTER(registerEnvelopeNodeRecorder);

}  // namespace beamsolid
