#include "core/ElementRecorder.h"

#include <iostream>
#include <sstream>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesClassName.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "core/ResponseEnvelope.h"
#include "elements/Element.h"

namespace beamsolid {

ElementRecorder::Spec ElementRecorder::Spec::parse(CommandArgs& args, const Domain& domain,
                                                   const std::string& recorderType) {
  Spec s;
  s.context = "recorder " + recorderType;
  args.setContext(s.context);
  while (!args.done()) {
    if (s.output.parse(args)) continue;
    if (args.nextFlag("-ele") || args.nextFlag("-eles") || args.nextFlag("-element")) {
      for (int t : args.nextInts("element tags", 1)) s.elementTags.push_back(t);
    } else if (args.nextFlag("-eleRange")) {
      const int first = args.nextInt("first element");
      const int last = args.nextInt("last element");
      if (last < first) args.fail("'-eleRange' " + std::to_string(first) + " " + std::to_string(last) +
                                  ": the last tag is smaller than the first");
      std::size_t found = 0;
      for (const auto& [tag, e] : domain.elements())
        if (tag >= first && tag <= last) {
          s.elementTags.push_back(tag);
          ++found;
        }
      if (found == 0) args.fail("'-eleRange' " + std::to_string(first) + " " + std::to_string(last) +
                                ": no element has a tag in this range");
    } else if (args.nextFlag("-region")) {
      const int tag = args.nextInt("regTag");
      const Domain::Region& region = domain.region(tag, s.context);
      if (region.elements.empty()) args.fail("region " + std::to_string(tag) + " holds no elements");
      s.elementTags.insert(s.elementTags.end(), region.elements.begin(), region.elements.end());
    } else if (args.nextIsString()) {
      // Everything from here on belongs to the element.
      s.responseArgs = args.restAsStrings();
    } else {
      args.failAt(args.position(), "option", "a recorder option ('-file', '-time', '-ele', ...) or a response");
    }
  }
  s.output.requireFile(args);
  if (s.elementTags.empty())
    args.fail("no elements given; expected '-ele', *tags, '-eleRange', first, last or '-region', regTag");
  if (s.responseArgs.empty()) args.fail("the response is missing, e.g. 'force'");
  for (int t : s.elementTags) domain.element(t, s.context);
  return s;
}

ElementRecorder::ElementRecorder(const Domain& domain, Spec spec) : ElementRecorder(domain, std::move(spec), false) {}

ElementRecorder::ElementRecorder(const Domain& domain, Spec spec, bool envelope) : spec_(std::move(spec)) {
  if (spec_.context.empty()) spec_.context = envelope ? "recorder EnvelopeElement" : "recorder Element";
  if (spec_.elementTags.empty()) throw OpenSeesError(spec_.context + ": no elements given");
  const std::string response = responseName();

  const bool echoTime = spec_.output.echoTime;
  std::vector<RecorderOutput::Column> columns;
  std::vector<RecorderOutput::XmlBlock> blocks;
  if (echoTime && !envelope) {
    columns.push_back(RecorderOutput::Column::time());
    blocks.push_back(RecorderOutput::timeBlock());
  }
  std::size_t width = 0;
  for (int tag : spec_.elementTags) {
    Element& element = domain.element(tag, spec_.context);
    Response r = element.setResponse(spec_.responseArgs);
    // OpenSees' XML: eleType (its class name) before eleTag; an envelope
    // with -time wraps each element's block with one time block per value.
    RecorderOutput::XmlBlock block{
        "ElementOutput", {{"eleType", openSeesClassName(element)}, {"eleTag", std::to_string(tag)}}, {}};
    for (std::size_t i = 0; i < element.nodeTags().size(); ++i)
      block.attributes.emplace_back("node" + std::to_string(i + 1), std::to_string(element.nodeTags()[i]));
    if (!r) {
      // As OpenSees: the element is left out of the data (its XML block
      // stays, empty), so a script that records a name some element lacks
      // still runs; the warning says which.
      std::cerr << "WARNING " << spec_.context << ": element " << tag << " (" << element.className()
                << ") has no response '" << response << "'; it is left out of the file\n";
      if (!envelope) blocks.push_back(std::move(block));
      continue;
    }
    for (const std::string& component : r.componentNames) {
      columns.push_back(
          RecorderOutput::Column::ofElement("e" + std::to_string(tag) + "_" + component, tag, response, component));
      block.responseTypes.push_back(component);
    }
    if (envelope && echoTime) {
      RecorderOutput::XmlBlock wrapper{"EnvelopeElementOutput", {}, {}};
      wrapper.children.push_back(std::move(block));
      wrapper.children.insert(wrapper.children.end(), r.componentNames.size(), RecorderOutput::timeBlock());
      blocks.push_back(std::move(wrapper));
    } else {
      blocks.push_back(std::move(block));
    }
    width += r.size();
    entries_.push_back({tag, &element, std::move(r)});
  }

  // No element answers: OpenSees still writes the time column (-time) of
  // an Element recorder, and nothing for an envelope.
  if (entries_.empty() && envelope) {
    columns.clear();
    blocks.clear();
  }
  std::ostringstream rows;
  if (envelope) {
    columns = ResponseEnvelope::columns(columns, echoTime);
    rows << "three rows: min, max and max |value| of each column over all records";
  } else {
    rows << "one per converged step (and per record() call)";
    if (spec_.output.deltaT > 0.0)
      rows << ", only when the time has advanced by at least dT = " << spec_.output.deltaT;
  }
  const char* type = envelope ? "EnvelopeElement" : "Element";
  output_ = std::make_unique<RecorderOutput>(spec_.output, std::move(columns), std::move(blocks), rows.str(),
                                             spec_.context, OutputFileClaim::Holder::beingAddedTo(domain, type));
  values_.reserve(width);
}

std::string ElementRecorder::responseName() const {
  std::string out;
  for (const std::string& a : spec_.responseArgs) out += (out.empty() ? "" : " ") + a;
  return out;
}

void ElementRecorder::readValues(const Domain& domain, std::vector<double>& out) {
  out.clear();
  for (const Entry& e : entries_) {
    if (domain.findElement(e.tag) != e.element) {  // removed since the recorder was made
      out.insert(out.end(), e.response.size(), 0.0);
      continue;
    }
    const Vector v = e.response.value();
    if (static_cast<std::size_t>(v.size()) != e.response.size())
      throw OpenSeesError(spec_.context + ": element " + std::to_string(e.tag) + " response '" + responseName() +
                          "' returned " + std::to_string(v.size()) + " values, but names " +
                          std::to_string(e.response.size()) + " components");
    out.insert(out.end(), v.data(), v.data() + v.size());
  }
}

void ElementRecorder::record(Domain& domain, double time) {
  // With -time, rows of the time alone when no element answers (OpenSees).
  if ((empty() && !spec_.output.echoTime) || output_->closed() || !output_->due(time)) return;
  readValues(domain, values_);
  row_.clear();
  if (spec_.output.echoTime) row_.push_back(time);
  row_.insert(row_.end(), values_.begin(), values_.end());
  output_->writeRow(time, row_);
}

void ElementRecorder::flush() { output_->flush(); }

void ElementRecorder::close() { output_->close(); }

namespace {

std::unique_ptr<Recorder> buildElementRecorder(CommandArgs& args, Domain& domain) {
  return std::make_unique<ElementRecorder>(domain, ElementRecorder::Spec::parse(args, domain, "Element"));
}

void registerElementRecorder(Registry& r) { r.recorders.add("Element", &buildElementRecorder); }

}  // namespace
BEAMSOLID_REGISTER(registerElementRecorder);

}  // namespace beamsolid
