#pragma once
#include "core/NodeRecorder.h"
#include "core/ResponseEnvelope.h"

namespace beamsolid {

// recorder('EnvelopeNode', ...): the same options as 'Node', but the file
// holds three rows, the min, max and max |value| of every column over all
// records (with -time, each value is preceded by the time it occurred). The
// file is rewritten on every flush(), so it always holds the current envelope.
class EnvelopeNodeRecorder : public NodeRecorder {
 public:
  EnvelopeNodeRecorder(const Domain& domain, Spec spec);
  // Writes the envelope before the file closes.
  ~EnvelopeNodeRecorder() override;
  std::string className() const override { return "EnvelopeNodeRecorder"; }
  void record(Domain& domain, double time) override;
  void flush() override;
  void close() override;

 private:
  ResponseEnvelope envelope_;
  bool changed_ = false;
};

}  // namespace beamsolid
