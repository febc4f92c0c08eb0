#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/Recorder.h"
#include "core/RecorderOutput.h"
#include "core/Response.h"

namespace beamsolid {

class CommandArgs;
class Element;

// recorder('Element', '-file', f, <'-time'>, '-ele', *tags, *responseArgs):
// one row per record() with the concatenated Response vectors of the
// elements in the given order. The response arguments go unchanged (numbers
// as text) to Element::setResponse, once, when the recorder is made.
class ElementRecorder : public Recorder {
 public:
  struct Spec {
    std::vector<int> elementTags;
    std::vector<std::string> responseArgs;
    RecorderOutput::Options output;
    std::string context;  // "recorder Element"

    // Parses the arguments after the recorder type; checks the elements exist.
    static Spec parse(CommandArgs& args, const Domain& domain, const std::string& recorderType);
  };

  // Asks every element for its response; an element without it is left out with a warning (OpenSees').
  ElementRecorder(const Domain& domain, Spec spec);

  std::string className() const override { return "ElementRecorder"; }
  void record(Domain& domain, double time) override;
  void flush() override;
  void close() override;

  const Spec& spec() const { return spec_; }
  const RecorderOutput& output() const { return *output_; }
  // The response arguments joined by spaces, e.g. "section 2 force".
  std::string responseName() const;

 protected:
  ElementRecorder(const Domain& domain, Spec spec, bool envelope);
  // The response values now, element by element (no time).
  void readValues(const Domain& domain, std::vector<double>& out);
  // No element answered the response: nothing is ever written.
  bool empty() const { return entries_.empty(); }

  Spec spec_;
  std::unique_ptr<RecorderOutput> output_;
  std::vector<double> values_;
  std::vector<double> row_;

 private:
  struct Entry {
    int tag;
    const Element* element;  // to notice an element removed since
    Response response;
  };
  std::vector<Entry> entries_;
};

}  // namespace beamsolid
