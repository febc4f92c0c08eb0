#include "core/EnvelopeElementRecorder.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

EnvelopeElementRecorder::EnvelopeElementRecorder(const Domain& domain, Spec spec)
    : ElementRecorder(domain, std::move(spec), true) {}

EnvelopeElementRecorder::~EnvelopeElementRecorder() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw.
  }
}

void EnvelopeElementRecorder::record(Domain& domain, double time) {
  if (empty() || output_->closed() || !output_->due(time)) return;
  readValues(domain, values_);
  envelope_.add(time, values_);
  output_->noteRecorded(time);
  changed_ = true;
}

void EnvelopeElementRecorder::flush() {
  if (output_->closed() || !changed_) return;
  output_->rewriteRows(envelope_.rows(spec_.output.echoTime));
  changed_ = false;
}

void EnvelopeElementRecorder::close() {
  flush();
  output_->close();
}

namespace {

std::unique_ptr<Recorder> buildEnvelopeElementRecorder(CommandArgs& args, Domain& domain) {
  return std::make_unique<EnvelopeElementRecorder>(domain,
                                                   ElementRecorder::Spec::parse(args, domain, "EnvelopeElement"));
}

void registerEnvelopeElementRecorder(Registry& r) {
  r.recorders.add("EnvelopeElement", &buildEnvelopeElementRecorder);
}

}  // namespace
BEAMSOLID_REGISTER(registerEnvelopeElementRecorder);

}  // namespace beamsolid
