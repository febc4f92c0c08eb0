#pragma once
#include <cstdint>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "core/OutputFileClaim.h"

namespace beamsolid {

class CommandArgs;

// Where and how a recorder writes its rows: the file and its format (text,
// CSV, XML, binary), precision, -dT thinning and close-on-write. Rows are
// written as given (the recorder prepends time itself). Text, CSV and binary
// files get a JSON sidecar `<file>.json` naming every column.
class RecorderOutput {
 public:
  enum class Format { Text, CSV, XML, Binary };

  // The options every recorder shares.
  struct Options {
    Format format = Format::Text;
    std::string path;
    bool append = false;        // -fileAdd
    bool echoTime = false;      // -time / -load: the recorder writes the time column
    int precision = 6;          // significant digits
    bool scientific = false;    // -scientific
    bool closeOnWrite = false;  // reopen and close the file for every row
    double deltaT = 0.0;        // -dT: record only when t >= last recorded + dT
    double relDeltaTTol = 1e-5; // -rTolDt, relative to dT

    // Consumes one shared option at the current position; false when the
    // next argument is none of them.
    bool parse(CommandArgs& args);
    // Throws unless an output file was given.
    void requireFile(const CommandArgs& args) const;
  };

  // One column of a row, described in the sidecar. node/element < 0 and
  // dof == 0 mean "not given"; an empty string is left out.
  struct Column {
    std::string name;
    int node = -1;
    int dof = 0;  // 1-based
    int element = -1;
    std::string response;
    std::string component;
    std::string meaning;  // e.g. "time at which the extreme occurred"

    static Column time() { return Column{"time", -1, 0, -1, {}, {}, {}}; }
    static Column ofNode(std::string name, int node, int dof, std::string response) {
      return Column{std::move(name), node, dof, -1, std::move(response), {}, {}};
    }
    static Column ofElement(std::string name, int element, std::string response, std::string component) {
      return Column{std::move(name), -1, 0, element, std::move(response), std::move(component), {}};
    }
  };

  // One block of the XML header, e.g. <NodeOutput nodeTag="3" ...> with its
  // <ResponseType> entries, then its nested blocks. With timeBeforeEach, a
  // <TimeOutput> block precedes every ResponseType (OpenSees' envelope layout).
  struct XmlBlock {
    std::string element;
    std::vector<std::pair<std::string, std::string>> attributes;
    std::vector<std::string> responseTypes;
    std::vector<XmlBlock> children = {};
    bool timeBeforeEach = false;
  };
  static XmlBlock timeBlock() { return XmlBlock{"TimeOutput", {}, {"time"}}; }

  // Claims the file for `holder` (refused while another recorder writes it),
  // opens it (creates or truncates; appends with -fileAdd), writes the XML
  // header or the sidecar. Errors are OpenSeesErrors prefixed by context.
  RecorderOutput(Options options, std::vector<Column> columns, std::vector<XmlBlock> xmlBlocks,
                 std::string rowsDescription, std::string context, OutputFileClaim::Holder holder);
  ~RecorderOutput();
  RecorderOutput(const RecorderOutput&) = delete;
  RecorderOutput& operator=(const RecorderOutput&) = delete;

  const Options& options() const { return options_; }
  std::size_t columnCount() const { return columns_.size(); }
  bool closed() const { return closed_; }

  // -dT: whether a row at `time` is due (always true without -dT and for the first row).
  bool due(double time) const;
  // Notes that a row for `time` was taken (the clock of -dT).
  void noteRecorded(double time);
  // Appends one row (exactly columnCount() values) and notes its time for -dT.
  void writeRow(double time, const std::vector<double>& row);
  // Replaces every row written so far (envelope recorders).
  void rewriteRows(const std::vector<std::vector<double>>& rows);
  // Buffered rows go to the operating system: readers see them.
  void flush();
  // Flushes, closes the XML document and the file, and lets other recorders
  // have it. Later calls do nothing.
  void close();

  static const char* formatName(Format f);
  static std::string jsonString(const std::string& s);

 private:
  void open(bool truncate);
  void writeHeader();
  void writeBlock(const XmlBlock& block, int depth);
  void writeValues(const std::vector<double>& row);
  void writeSidecar() const;
  void check(const char* action);
  // close() without the bookkeeping: the XML trailer, flushing, closing the file.
  void finish();

  Options options_;
  std::vector<Column> columns_;
  std::vector<XmlBlock> xmlBlocks_;
  std::string rowsDescription_;
  std::string context_;
  OutputFileClaim claim_;  // before file_: the file is claimed before it is opened
  std::ofstream file_;
  std::uintmax_t baseSize_ = 0;  // size of an appended-to file before our output
  bool closed_ = false;
  bool anyRow_ = false;
  double lastRowTime_ = 0.0;
  std::string buffer_;  // one formatted row, reused
};

}  // namespace beamsolid
