#include "core/RecorderOutput.h"

#include <bit>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "core/CommandArgs.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

namespace {

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

const std::string& givenPath(const std::string& path, const std::string& context) {
  if (path.empty()) throw OpenSeesError(context + ": no output file given");
  return path;
}

}  // namespace

bool RecorderOutput::Options::parse(CommandArgs& args) {
  auto setFile = [&](Format f, bool add, const char* what) {
    if (!path.empty()) args.fail("the output file is given twice ('" + path + "' and another)");
    path = args.nextString(what);
    if (path.empty()) args.fail(std::string("argument ") + std::to_string(args.position()) + " (" + what +
                                "): expected a file name, got ''");
    format = f;
    append = add;
  };
  if (args.nextFlag("-file")) setFile(Format::Text, false, "file");
  else if (args.nextFlag("-fileAdd")) setFile(Format::Text, true, "fileAdd");
  else if (args.nextFlag("-csv") || args.nextFlag("-fileCSV")) setFile(Format::CSV, false, "csv file");
  else if (args.nextFlag("-xml") || args.nextFlag("-fileXML")) setFile(Format::XML, false, "xml file");
  else if (args.nextFlag("-binary") || args.nextFlag("-fileBinary")) setFile(Format::Binary, false, "binary file");
  else if (args.nextFlag("-time") || args.nextFlag("-load")) echoTime = true;
  else if (args.nextFlag("-precision")) {
    const std::size_t at = args.position();
    precision = args.nextInt("precision");
    if (precision < 1 || precision > 17) args.failAt(at, "precision", "a number of significant digits from 1 to 17");
  } else if (args.nextFlag("-scientific")) scientific = true;
  else if (args.nextFlag("-closeOnWrite")) closeOnWrite = true;
  else if (args.nextFlag("-dT") || args.nextFlag("-dt")) {
    const std::size_t at = args.position();
    deltaT = args.nextDouble("dT");
    if (deltaT < 0.0) args.failAt(at, "dT", "a time interval >= 0");
  } else if (args.nextFlag("-rTolDt")) {
    const std::size_t at = args.position();
    relDeltaTTol = args.nextDouble("rTolDt");
    if (relDeltaTTol < 0.0) args.failAt(at, "rTolDt", "a relative tolerance >= 0");
  } else if (auto s = args.peekString(); s && (*s == "-tcp" || *s == "-nc" || *s == "-database")) {
    args.fail("output option '" + *s + "' is not supported; use '-file', '-csv', '-xml' or '-binary'");
  } else {
    return false;
  }
  return true;
}

void RecorderOutput::Options::requireFile(const CommandArgs& args) const {
  if (path.empty())
    args.fail("no output file; expected '-file', '-fileAdd', '-csv', '-xml' or '-binary' followed by a file name");
}

const char* RecorderOutput::formatName(Format f) {
  switch (f) {
    case Format::Text: return "text";
    case Format::CSV: return "csv";
    case Format::XML: return "xml";
    case Format::Binary: return "binary";
  }
  return "?";
}

std::string RecorderOutput::jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

RecorderOutput::RecorderOutput(Options options, std::vector<Column> columns, std::vector<XmlBlock> xmlBlocks,
                               std::string rowsDescription, std::string context, OutputFileClaim::Holder holder)
    : options_(std::move(options)),
      columns_(std::move(columns)),
      xmlBlocks_(std::move(xmlBlocks)),
      rowsDescription_(std::move(rowsDescription)),
      context_(std::move(context)),
      claim_(givenPath(options_.path, context_), std::move(holder), context_) {
  open(!options_.append);
  std::error_code ec;
  baseSize_ = options_.append ? std::filesystem::file_size(options_.path, ec) : 0;
  if (ec) baseSize_ = 0;
  writeHeader();
  check("writing");
  if (options_.closeOnWrite) file_.close();
  if (options_.format != Format::XML) writeSidecar();
}

RecorderOutput::~RecorderOutput() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw; close() was the last chance to report.
  }
}

void RecorderOutput::open(bool truncate) {
  const auto mode = std::ios::out | std::ios::binary | (truncate ? std::ios::trunc : std::ios::app);
  file_.open(options_.path, mode);
  if (!file_) throw OpenSeesError(context_ + ": cannot open file '" + options_.path + "' for writing");
}

void RecorderOutput::check(const char* action) {
  if (!file_) throw OpenSeesError(context_ + ": " + action + " file '" + options_.path + "' failed");
}

// The XML layout is OpenSees' to the byte (checked against OpenSeesPy
// 3.7.1): the schema attributes on the root, four spaces per level, data rows
// indented by eight with a blank after every value.
void RecorderOutput::writeHeader() {
  if (options_.format != Format::XML) return;
  file_ << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           " <OpenSees\n"
           "  xmlns:xsi = \"http://www.w3.org/2001/XMLSchema-instance\"\n"
           "  xsi:noNamespaceSchemaLocation = \"http://OpenSees.berkeley.edu/xml-schema/xmlns/OpenSees.xsd\">\n";
  for (const XmlBlock& b : xmlBlocks_) writeBlock(b, 1);
  file_ << "    <Data>\n";
}

void RecorderOutput::writeBlock(const XmlBlock& b, int depth) {
  const std::string indent(4 * depth, ' ');
  file_ << indent << '<' << b.element;
  for (const auto& [name, value] : b.attributes) file_ << ' ' << name << "=\"" << xmlEscape(value) << '"';
  if (b.responseTypes.empty() && b.children.empty()) {
    file_ << "/>\n";  // an element without the response, as OpenSees writes it
    return;
  }
  file_ << ">\n";
  for (const std::string& r : b.responseTypes) {
    if (b.timeBeforeEach) writeBlock(timeBlock(), depth + 1);
    file_ << indent << "    <ResponseType>" << xmlEscape(r) << "</ResponseType>\n";
  }
  for (const XmlBlock& child : b.children) writeBlock(child, depth + 1);
  file_ << indent << "</" << b.element << ">\n";
}

void RecorderOutput::writeValues(const std::vector<double>& row) {
  if (row.size() != columns_.size())
    throw OpenSeesError(context_ + ": internal error: row of " + std::to_string(row.size()) + " values for " +
                        std::to_string(columns_.size()) + " columns");
  if (options_.format == Format::Binary) {
    file_.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size() * sizeof(double)));
    file_.put('\n');
    return;
  }
  const char delimiter = options_.format == Format::CSV ? ',' : ' ';
  const bool xml = options_.format == Format::XML;
  buffer_.clear();
  if (xml) buffer_ += "        ";
  char number[64];
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i && !xml) buffer_ += delimiter;
    // OpenSees: -precision p gives %.pg, or %.pe (p digits after the point)
    // with -scientific.
    const int n = options_.scientific ? std::snprintf(number, sizeof number, "%.*e", options_.precision, row[i])
                                      : std::snprintf(number, sizeof number, "%.*g", options_.precision, row[i]);
    buffer_.append(number, static_cast<std::size_t>(n));
    if (xml) buffer_ += ' ';
  }
  buffer_ += '\n';
  file_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
}

bool RecorderOutput::due(double time) const {
  if (options_.deltaT <= 0.0 || !anyRow_) return true;
  return time - (lastRowTime_ + options_.deltaT) >= -options_.relDeltaTTol * options_.deltaT;
}

void RecorderOutput::noteRecorded(double time) {
  anyRow_ = true;
  lastRowTime_ = time;
}

void RecorderOutput::writeRow(double time, const std::vector<double>& row) {
  if (closed_) return;
  if (options_.closeOnWrite) open(false);
  writeValues(row);
  check("writing");
  if (options_.closeOnWrite) file_.close();
  noteRecorded(time);
}

void RecorderOutput::rewriteRows(const std::vector<std::vector<double>>& rows) {
  if (closed_) return;
  if (file_.is_open()) file_.close();
  std::error_code ec;
  // Only a regular file can be cut back to its header; a device such as
  // /dev/null has nothing to cut (resize_file fails there with EINVAL).
  if (std::filesystem::is_regular_file(options_.path, ec)) std::filesystem::resize_file(options_.path, baseSize_, ec);
  if (ec) throw OpenSeesError(context_ + ": cannot rewrite file '" + options_.path + "': " + ec.message());
  open(false);
  writeHeader();
  for (const auto& row : rows) writeValues(row);
  file_.flush();
  check("writing");
  if (options_.closeOnWrite) file_.close();
}

void RecorderOutput::flush() {
  if (closed_ || !file_.is_open()) return;
  file_.flush();
  check("flushing");
}

void RecorderOutput::close() {
  if (closed_) return;
  closed_ = true;
  // Closed, this recorder writes no more, so the file is free even when
  // closing it failed.
  try {
    finish();
  } catch (...) {
    claim_.release();
    throw;
  }
  claim_.release();
}

void RecorderOutput::finish() {
  if (options_.format == Format::XML) {
    if (!file_.is_open()) open(false);
    file_ << "        </Data>\n</OpenSees>\n";
  }
  if (file_.is_open()) {
    file_.flush();
    const bool ok = static_cast<bool>(file_);
    file_.close();
    if (!ok) throw OpenSeesError(context_ + ": writing file '" + options_.path + "' failed");
  }
}

void RecorderOutput::writeSidecar() const {
  const std::string sidecar = options_.path + ".json";
  std::ofstream out(sidecar, std::ios::out | std::ios::trunc);
  if (!out) throw OpenSeesError(context_ + ": cannot write the column description '" + sidecar + "'");
  const std::string fileName = std::filesystem::path(options_.path).filename().string();
  out << "{\n  \"file\": " << jsonString(fileName) << ",\n  \"format\": \"" << formatName(options_.format) << "\",\n";
  if (options_.format == Format::Binary) {
    out << "  \"dtype\": \"float64\",\n  \"byteOrder\": \""
        << (std::endian::native == std::endian::little ? "little" : "big") << "\",\n"
        << "  \"rowTerminator\": \"\\n\",\n  \"bytesPerRow\": " << columns_.size() * sizeof(double) + 1 << ",\n";
  } else {
    out << "  \"delimiter\": \"" << (options_.format == Format::CSV ? "," : " ") << "\",\n"
        << "  \"precision\": " << options_.precision << ",\n";
  }
  out << "  \"rows\": " << jsonString(rowsDescription_) << ",\n";
  if (options_.append) out << "  \"appended\": true,\n";
  out << "  \"columnCount\": " << columns_.size() << ",\n  \"columns\": [";
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    const Column& c = columns_[i];
    out << (i ? ",\n    " : "\n    ") << "{\"index\": " << i << ", \"name\": " << jsonString(c.name);
    if (c.node >= 0) out << ", \"node\": " << c.node;
    if (c.dof > 0) out << ", \"dof\": " << c.dof;
    if (c.element >= 0) out << ", \"element\": " << c.element;
    if (!c.response.empty()) out << ", \"response\": " << jsonString(c.response);
    if (!c.component.empty()) out << ", \"component\": " << jsonString(c.component);
    if (!c.meaning.empty()) out << ", \"meaning\": " << jsonString(c.meaning);
    out << '}';
  }
  out << "\n  ]\n}\n";
  if (!out) throw OpenSeesError(context_ + ": writing the column description '" + sidecar + "' failed");
}

}  // namespace beamsolid
