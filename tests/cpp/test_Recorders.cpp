// Recorders write what the nodes and elements hold: every value read back from
// the files is compared with the state the test put into the Domain.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/OutputFileClaim.h"
#include "core/Recorder.h"
#include "core/Registry.h"
#include "elements/Element.h"

using namespace beamsolid;
using V = CommandArgs::Value;
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------
// A test-only element: diagonal stiffness k_i = 10 (i + 1) on its dofs, so the
// resisting force is known in closed form. Responses:
//   'force'                -> resisting force, names P1..Pn
//   'section', s, 'force'  -> {s * u_0, 1000 * tag + s}, names N, M
class ProbeElement : public Element {
 public:
  ProbeElement(int tag, std::vector<int> nodeTags) : Element(tag, std::move(nodeTags)) {}
  std::string className() const override { return "ProbeElement"; }

  void update() override {
    int offset = 0;
    for (Node* n : nodes()) {
      u_.segment(offset, n->ndf()) = n->trialDisp();
      offset += n->ndf();
    }
    force_ = stiffness_.cwiseProduct(u_);
  }
  MatrixView tangentStiff() override { return viewOf(K_); }
  MatrixView initialStiff() override { return viewOf(K_); }
  VectorView resistingForce() override { return viewOf(force_); }

  Response setResponse(const std::vector<std::string>& args) override {
    if (args.size() == 1 && args[0] == "force")
      return Response::named(Response::numberedNames("P", numDOF()), [this] { return force_; });
    if (args.size() == 3 && args[0] == "section" && args[2] == "force") {
      const int section = std::stoi(args[1]);
      return Response::named({"N", "M"}, [this, section] {
        Vector v(2);
        v << section * u_[0], 1000.0 * tag() + section;
        return v;
      });
    }
    return {};
  }

 protected:
  void setDomain(Domain&) override {
    const int n = numDOF();
    u_ = Vector::Zero(n);
    force_ = Vector::Zero(n);
    stiffness_ = Vector::LinSpaced(n, 10.0, 10.0 * n);
    K_ = stiffness_.asDiagonal();
  }

 private:
  Vector u_, force_, stiffness_;
  Matrix K_;
};

// ---------------------------------------------------------------------------
// The model: node 1 (ndf 3), nodes 2 and 3 (ndf 6); element 7 = (1, 2), element 8 = (2, 3).
const std::map<int, int> kNdf{{1, 3}, {2, 6}, {3, 6}};
const std::map<int, std::vector<int>> kElements{{7, {1, 2}}, {8, {2, 3}}};

double timeOf(int step) { return 0.1 * step; }
// Nonlinear in the step, so increments differ from step to step.
double dispOf(int step, int node, int dof) {
  return 1e-3 * step * (10 * node + dof + 1) * (dof % 2 ? -1.0 : 1.0) + 1e-4 * step * step * (dof + 1);
}
double loadOf(int step, int node, int dof) { return 100.0 * step + node + 0.5 * dof; }

std::unique_ptr<Domain> makeDomain() {
  auto d = std::make_unique<Domain>();
  d->addNode(std::make_unique<Node>(1, 3, Vector3(0.0, 0.0, 0.0)), "test");
  d->addNode(std::make_unique<Node>(2, 6, Vector3(1.0, 0.0, 0.0)), "test");
  d->addNode(std::make_unique<Node>(3, 6, Vector3(2.0, 0.5, -1.0)), "test");
  for (const auto& [tag, nodes] : kElements) d->addElement(std::make_unique<ProbeElement>(tag, nodes), "test");
  return d;
}

// One converged step: loads, displacements (vel = 2u, accel = 3u), commit (records).
void commitStep(Domain& d, int step) {
  d.applyLoad(timeOf(step));
  for (const auto& [tag, ndf] : kNdf) {
    Node& n = d.node(tag, "test");
    Vector u(ndf), p(ndf);
    for (int i = 0; i < ndf; ++i) {
      u[i] = dispOf(step, tag, i);
      p[i] = loadOf(step, tag, i);
    }
    n.setTrialDisp(u);
    n.setTrialVel(2.0 * u);
    n.setTrialAccel(3.0 * u);
    n.addUnbalancedLoad(p, 1.0);
  }
  d.update();
  d.commit();
}

// Reaction computed here from the closed-form element forces: sum of k_i u_i over
// the elements at the node, minus the applied load.
double reactionOf(int step, int node, int dof) {
  double r = -loadOf(step, node, dof);
  for (const auto& [tag, nodes] : kElements) {
    int offset = 0;
    for (int n : nodes) {
      if (n == node) r += 10.0 * (offset + dof + 1) * dispOf(step, node, dof);
      offset += kNdf.at(n);
    }
  }
  return r;
}

// Element force component `i` (element dof order).
double elementForceOf(int step, int element, int i) {
  int offset = 0;
  for (int n : kElements.at(element)) {
    const int ndf = kNdf.at(n);
    if (i < offset + ndf) return 10.0 * (i + 1) * dispOf(step, n, i - offset);
    offset += ndf;
  }
  return NAN;
}

// ---------------------------------------------------------------------------
// Files.
class RecorderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("beamsolid_rec_" + std::to_string(::getpid())) /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    domain_ = makeDomain();
  }
  void TearDown() override {
    domain_.reset();
    if (std::getenv("BEAMSOLID_KEEP_TEST_FILES")) return;
    std::error_code ec;
    fs::remove_all(dir_, ec);
    fs::remove(dir_.parent_path(), ec);  // only succeeds once empty
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  // Builds a recorder through the registry and adds it to the domain.
  Recorder& add(const std::string& type, std::vector<V> args) {
    CommandArgs a("recorder", std::move(args));
    std::unique_ptr<Recorder> r = Registry::global().recorders.get(type)(a, *domain_);
    Recorder& ref = *r;
    domain_->addRecorder(std::move(r));
    return ref;
  }
  std::string error(const std::string& type, std::vector<V> args) {
    try {
      add(type, std::move(args));
    } catch (const OpenSeesError& e) {
      return e.what();
    }
    return "(no error)";
  }

  fs::path dir_;
  std::unique_ptr<Domain> domain_;
};

V s(const char* text) { return std::string(text); }
V s(const std::string& text) { return text; }

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::vector<std::vector<double>> parseRows(const std::string& text, char delimiter) {
  std::vector<std::vector<double>> rows;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (delimiter != ' ') {
      EXPECT_EQ(line.find(' '), std::string::npos) << "unexpected space in '" << line << "'";
      std::replace(line.begin(), line.end(), delimiter, ' ');
    }
    std::istringstream fields(line);
    std::vector<double> row;
    std::string field;
    while (fields >> field) {
      std::size_t used = 0;
      row.push_back(std::stod(field, &used));
      EXPECT_EQ(used, field.size()) << "'" << field << "' is not a number";
    }
    rows.push_back(row);
  }
  return rows;
}

std::vector<std::vector<double>> readTable(const std::string& path, char delimiter = ' ') {
  return parseRows(slurp(path), delimiter);
}

// |written - exact| <= half a unit in the last of `digits` significant digits.
::testing::AssertionResult closeAtPrecision(double written, double exact, int digits = 6) {
  const double tol = 0.5000001 * std::pow(10.0, 1 - digits) * std::fabs(exact) + 1e-300;
  if (std::fabs(written - exact) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << written << " vs " << exact << " (tolerance " << tol << ")";
}

// ---------------------------------------------------------------------------
// A small JSON reader, enough to check that the sidecar parses.
struct Json {
  enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
  double number = 0;
  bool boolean = false;
  std::string string;
  std::vector<Json> array;
  std::vector<std::pair<std::string, Json>> object;

  bool has(const std::string& key) const {
    for (const auto& kv : object)
      if (kv.first == key) return true;
    return false;
  }
  const Json& operator[](const std::string& key) const {
    for (const auto& kv : object)
      if (kv.first == key) return kv.second;
    throw std::runtime_error("no key " + key);
  }
};

class JsonReader {
 public:
  explicit JsonReader(std::string text) : s_(std::move(text)) {}
  Json document() {
    Json j = value();
    skip();
    if (i_ != s_.size()) throw std::runtime_error("trailing characters");
    return j;
  }

 private:
  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  char peek() {
    skip();
    if (i_ >= s_.size()) throw std::runtime_error("unexpected end");
    return s_[i_];
  }
  void expect(char c) {
    if (peek() != c) throw std::runtime_error(std::string("expected ") + c + " at " + std::to_string(i_));
    ++i_;
  }
  std::string str() {
    expect('"');
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      if (s_[i_] == '\\') {
        ++i_;
        const char e = s_.at(i_);
        if (e == 'n') out += '\n';
        else if (e == 't') out += '\t';
        else if (e == 'r') out += '\r';
        else if (e == 'u') { out += '?'; i_ += 4; }
        else out += e;
        ++i_;
      } else {
        out += s_[i_++];
      }
    }
    expect('"');
    return out;
  }
  Json value() {
    Json j;
    const char c = peek();
    if (c == '{') {
      j.type = Json::Type::Object;
      ++i_;
      if (peek() == '}') { ++i_; return j; }
      while (true) {
        std::string key = str();
        expect(':');
        j.object.emplace_back(key, value());
        if (peek() == ',') { ++i_; continue; }
        expect('}');
        return j;
      }
    }
    if (c == '[') {
      j.type = Json::Type::Array;
      ++i_;
      if (peek() == ']') { ++i_; return j; }
      while (true) {
        j.array.push_back(value());
        if (peek() == ',') { ++i_; continue; }
        expect(']');
        return j;
      }
    }
    if (c == '"') {
      j.type = Json::Type::String;
      j.string = str();
      return j;
    }
    if (s_.compare(i_, 4, "true") == 0) { i_ += 4; j.type = Json::Type::Bool; j.boolean = true; return j; }
    if (s_.compare(i_, 5, "false") == 0) { i_ += 5; j.type = Json::Type::Bool; return j; }
    if (s_.compare(i_, 4, "null") == 0) { i_ += 4; return j; }
    std::size_t used = 0;
    j.number = std::stod(s_.substr(i_), &used);
    j.type = Json::Type::Number;
    i_ += used;
    return j;
  }
  std::string s_;
  std::size_t i_ = 0;
};

Json readSidecar(const std::string& dataFile) { return JsonReader(slurp(dataFile + ".json")).document(); }

// ---------------------------------------------------------------------------
// A small XML checker: nesting must balance; collects ResponseType texts, the
// opening tags of the output blocks, and the text of <Data>.
struct XmlSummary {
  std::string root;
  std::vector<std::string> blocks;  // opening tags incl. attributes, e.g. NodeOutput nodeTag="1" ...
  std::vector<std::string> responseTypes;
  std::string data;
};

XmlSummary checkXml(const std::string& text) {
  XmlSummary out;
  std::vector<std::string> stack;
  std::size_t i = 0;
  while ((i = text.find('<', i)) != std::string::npos) {
    const std::size_t end = text.find('>', i);
    if (end == std::string::npos) throw std::runtime_error("unterminated tag");
    std::string tag = text.substr(i + 1, end - i - 1);
    const std::size_t contentStart = end + 1;
    i = end + 1;
    if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
    if (tag[0] == '/') {
      if (stack.empty() || stack.back() != tag.substr(1)) throw std::runtime_error("mismatched </" + tag + ">");
      stack.pop_back();
      continue;
    }
    const bool selfClosing = tag.back() == '/';
    const std::string name = tag.substr(0, tag.find_first_of(" \t\r\n/"));
    if (stack.empty()) out.root = name;
    if (name == "NodeOutput" || name == "ElementOutput" || name == "TimeOutput") out.blocks.push_back(tag);
    const std::size_t next = text.find('<', contentStart);
    if (name == "ResponseType") out.responseTypes.push_back(text.substr(contentStart, next - contentStart));
    if (name == "Data") out.data = text.substr(contentStart, next - contentStart);
    if (!selfClosing) stack.push_back(name);
  }
  if (!stack.empty()) throw std::runtime_error("unclosed <" + stack.back() + ">");
  return out;
}

}  // namespace

// ===========================================================================

TEST_F(RecorderTest, NodeDispTextMatchesNodesWithTimeColumnAndZeroPadding) {
  const std::string f = file("disp.out");
  // dof 5 is beyond node 1's ndf of 3: written as 0.
  Recorder& r = add("Node", {s("-file"), s(f), s("-time"), s("-node"), 1LL, 3LL, s("-dof"), 1LL, 3LL, 5LL, s("disp")});
  EXPECT_EQ(r.className(), "NodeRecorder");
  for (int step = 1; step <= 4; ++step) commitStep(*domain_, step);
  r.close();

  const auto rows = readTable(f);
  ASSERT_EQ(rows.size(), 4u);
  const int dofs[] = {0, 2, 4};
  for (int step = 1; step <= 4; ++step) {
    const auto& row = rows[step - 1];
    ASSERT_EQ(row.size(), 7u);
    EXPECT_TRUE(closeAtPrecision(row[0], timeOf(step)));
    int c = 1;
    for (int node : {1, 3})
      for (int d : dofs) {
        const double exact = d < kNdf.at(node) ? dispOf(step, node, d) : 0.0;
        EXPECT_TRUE(closeAtPrecision(row[c], exact)) << "step " << step << " node " << node << " dof " << d + 1;
        ++c;
      }
  }
  // Text: space separated, no header, 6 significant digits by default.
  const std::string text = slurp(f);
  EXPECT_EQ(text.find(','), std::string::npos);
  EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(text[0])));
}

TEST_F(RecorderTest, SidecarNamesEveryColumn) {
  const std::string f = file("disp.out");
  Recorder& r = add("Node", {s("-file"), s(f), s("-time"), s("-node"), 2LL, 1LL, s("-dof"), 2LL, 4LL, s("disp")});
  commitStep(*domain_, 1);
  r.close();
  const Json j = readSidecar(f);
  EXPECT_EQ(j["format"].string, "text");
  EXPECT_EQ(j["rows"].string.rfind("one per converged step", 0), 0u);
  const auto& cols = j["columns"].array;
  ASSERT_EQ(cols.size(), 5u);
  EXPECT_EQ(j["columnCount"].number, 5.0);
  EXPECT_EQ(cols[0]["index"].number, 0.0);
  EXPECT_EQ(cols[0]["name"].string, "time");
  const int nodes[] = {2, 2, 1, 1};
  const int dofs[] = {2, 4, 2, 4};
  for (int c = 1; c < 5; ++c) {
    EXPECT_EQ(cols[c]["index"].number, c);
    EXPECT_EQ(cols[c]["node"].number, nodes[c - 1]);
    EXPECT_EQ(cols[c]["dof"].number, dofs[c - 1]);
    EXPECT_EQ(cols[c]["response"].string, "disp");
  }
  // The row really has as many values as the sidecar names.
  EXPECT_EQ(readTable(f).at(0).size(), cols.size());
}

TEST_F(RecorderTest, ReactionCsvEqualsElementForcesMinusLoads) {
  const std::string f = file("reaction.csv");
  Recorder& r = add("Node", {s("-csv"), s(f), s("-nodeRange"), 1LL, 3LL, s("-dof"), 1LL, 2LL, 3LL, 4LL, 5LL, 6LL,
                             s("reaction")});
  for (int step = 1; step <= 3; ++step) commitStep(*domain_, step);
  r.close();
  const auto rows = readTable(f, ',');
  ASSERT_EQ(rows.size(), 3u);
  for (int step = 1; step <= 3; ++step) {
    ASSERT_EQ(rows[step - 1].size(), 18u);
    int c = 0;
    for (int node = 1; node <= 3; ++node)
      for (int d = 0; d < 6; ++d, ++c) {
        const double exact = d < kNdf.at(node) ? reactionOf(step, node, d) : 0.0;
        EXPECT_TRUE(closeAtPrecision(rows[step - 1][c], exact)) << "step " << step << " node " << node << " dof " << d;
      }
  }
  EXPECT_EQ(readSidecar(f)["format"].string, "csv");
}

TEST_F(RecorderTest, IncrDispIsTheIncrementOfTheStepJustCommitted) {
  const std::string f = file("incr.out");
  Recorder& r = add("Node", {s("-file"), s(f), s("-node"), 2LL, s("-dof"), 1LL, 2LL, 6LL, s("incrDisp")});
  for (int step = 1; step <= 4; ++step) commitStep(*domain_, step);
  r.close();
  const auto rows = readTable(f);
  ASSERT_EQ(rows.size(), 4u);
  for (int step = 1; step <= 4; ++step) {
    int c = 0;
    for (int d : {0, 1, 5}) {
      const double exact = dispOf(step, 2, d) - (step > 1 ? dispOf(step - 1, 2, d) : 0.0);
      EXPECT_TRUE(closeAtPrecision(rows[step - 1][c++], exact)) << "step " << step << " dof " << d + 1;
    }
  }
}

TEST_F(RecorderTest, VelAccelUnbalanceAndEigenColumns) {
  Matrix phi(6, 3);
  for (int i = 0; i < 6; ++i)
    for (int m = 0; m < 3; ++m) phi(i, m) = 0.1 * (i + 1) - 0.37 * m;
  domain_->node(3, "test").setEigenvectors(phi);
  const std::string fv = file("vel.out"), fa = file("accel.out"), fu = file("unbalance.out"), fe = file("eigen.out");
  add("Node", {s("-file"), s(fv), s("-node"), 3LL, s("-dof"), 1LL, 5LL, s("vel")});
  add("Node", {s("-file"), s(fa), s("-node"), 3LL, s("-dof"), 1LL, 5LL, s("accel")});
  add("Node", {s("-file"), s(fu), s("-node"), 3LL, s("-dof"), 1LL, 5LL, s("unbalance")});
  add("Node", {s("-file"), s(fe), s("-node"), 3LL, 1LL, s("-dof"), 1LL, 5LL, s("eigen"), 2LL});
  commitStep(*domain_, 1);
  commitStep(*domain_, 2);
  domain_->removeRecorders();
  const auto vel = readTable(fv), accel = readTable(fa), unbalance = readTable(fu), eigen = readTable(fe);
  ASSERT_EQ(vel.size(), 2u);
  ASSERT_EQ(accel.size(), 2u);
  ASSERT_EQ(unbalance.size(), 2u);
  ASSERT_EQ(eigen.size(), 2u);
  for (int step = 1; step <= 2; ++step) {
    int c = 0;
    for (int d : {0, 4}) {
      EXPECT_TRUE(closeAtPrecision(vel[step - 1][c], 2.0 * dispOf(step, 3, d)));
      EXPECT_TRUE(closeAtPrecision(accel[step - 1][c], 3.0 * dispOf(step, 3, d)));
      EXPECT_TRUE(closeAtPrecision(unbalance[step - 1][c], loadOf(step, 3, d)));
      ++c;
    }
    // Mode 2 of node 3 (column 1); node 1 has no eigenvectors: 0.
    EXPECT_TRUE(closeAtPrecision(eigen[step - 1][0], phi(0, 1)));
    EXPECT_TRUE(closeAtPrecision(eigen[step - 1][1], phi(4, 1)));
    EXPECT_EQ(eigen[step - 1][2], 0.0);
    EXPECT_EQ(eigen[step - 1][3], 0.0);
  }
  EXPECT_EQ(readSidecar(fe)["columns"].array[0]["response"].string, "eigen 2");
}

TEST_F(RecorderTest, ElementRecorderWritesResponseVectorsInTagOrder) {
  const std::string ff = file("force.out"), fs2 = file("section.out");
  add("Element", {s("-file"), s(ff), s("-time"), s("-ele"), 8LL, 7LL, s("force")});
  // Numbers after the response name reach setResponse as their text ("2").
  add("Element", {s("-file"), s(fs2), s("-eleRange"), 7LL, 8LL, s("section"), 2LL, s("force")});
  for (int step = 1; step <= 3; ++step) commitStep(*domain_, step);
  domain_->removeRecorders();

  const auto force = readTable(ff);
  ASSERT_EQ(force.size(), 3u);
  for (int step = 1; step <= 3; ++step) {
    const auto& row = force[step - 1];
    ASSERT_EQ(row.size(), 1u + 12u + 9u);  // time, element 8 (6+6 dofs), element 7 (3+6 dofs)
    EXPECT_TRUE(closeAtPrecision(row[0], timeOf(step)));
    int c = 1;
    for (int e : {8, 7}) {
      const int n = e == 8 ? 12 : 9;
      for (int i = 0; i < n; ++i, ++c)
        EXPECT_TRUE(closeAtPrecision(row[c], elementForceOf(step, e, i))) << "element " << e << " component " << i;
    }
  }
  const auto section = readTable(fs2);
  ASSERT_EQ(section.size(), 3u);
  for (int step = 1; step <= 3; ++step) {
    ASSERT_EQ(section[step - 1].size(), 4u);
    EXPECT_TRUE(closeAtPrecision(section[step - 1][0], 2.0 * dispOf(step, 1, 0)));
    EXPECT_TRUE(closeAtPrecision(section[step - 1][1], 7002.0));
    EXPECT_TRUE(closeAtPrecision(section[step - 1][2], 2.0 * dispOf(step, 2, 0)));
    EXPECT_TRUE(closeAtPrecision(section[step - 1][3], 8002.0));
  }

  const Json j = readSidecar(ff);
  const auto& cols = j["columns"].array;
  ASSERT_EQ(cols.size(), 22u);
  EXPECT_EQ(cols[1]["element"].number, 8.0);
  EXPECT_EQ(cols[1]["response"].string, "force");
  EXPECT_EQ(cols[1]["component"].string, "P1");
  EXPECT_EQ(cols[13]["element"].number, 7.0);
  EXPECT_EQ(cols[21]["component"].string, "P9");
  const Json js = readSidecar(fs2);
  EXPECT_EQ(js["columns"].array[0]["response"].string, "section 2 force");
  EXPECT_EQ(js["columns"].array[1]["component"].string, "M");
}

TEST_F(RecorderTest, UnknownElementResponseLeavesTheElementOut) {
  // As OpenSees: no error; the element is left out and, as no element answers, nothing is written.
  EXPECT_EQ(error("Element", {s("-file"), s(file("x.out")), s("-ele"), 7LL, s("stresses"), 3LL}), "(no error)");
}

TEST_F(RecorderTest, UnknownTagsAndBadArgumentsThrow) {
  const std::string f = file("x.out");
  std::string m = error("Node", {s("-file"), s(f), s("-node"), 1LL, 42LL, s("-dof"), 1LL, s("disp")});
  EXPECT_NE(m.find("node 42 does not exist"), std::string::npos) << m;
  m = error("Element", {s("-file"), s(f), s("-ele"), 99LL, s("force")});
  EXPECT_NE(m.find("element 99"), std::string::npos) << m;
  m = error("Node", {s("-file"), s(f), s("-node"), 1LL, s("-dof"), 1LL, s("pressure")});
  EXPECT_NE(m.find("pressure"), std::string::npos) << m;
  m = error("Node", {s("-node"), 1LL, s("-dof"), 1LL, s("disp")});
  EXPECT_NE(m.find("no output file"), std::string::npos) << m;
  m = error("Node", {s("-file"), s(f), s("-node"), 1LL, s("-dof"), 0LL, s("disp")});
  EXPECT_NE(m.find("1-based"), std::string::npos) << m;
  m = error("Node", {s("-file"), s(f), s("-node"), 1LL, s("-dof"), 1LL});
  EXPECT_NE(m.find("response type is missing"), std::string::npos) << m;
  m = error("Node", {s("-file"), s(f), s("-node"), 1LL, s("-bogus"), s("disp")});
  EXPECT_NE(m.find("'-bogus'"), std::string::npos) << m;
  m = error("Node", {s("-file"), s(f), s("-node"), 1LL, s("disp"), 3LL});
  EXPECT_NE(m.find("unexpected extra argument"), std::string::npos) << m;
  m = error("Node", {s("-file"), (dir_ / "missing_dir" / "x.out").string(), s("-node"), 1LL, s("disp")});
  EXPECT_NE(m.find("cannot open file"), std::string::npos) << m;
}

TEST_F(RecorderTest, XmlHasHeaderBlocksAndClosedDataBlock) {
  const std::string f = file("disp.xml");
  Recorder& r = add("Node", {s("-xml"), s(f), s("-time"), s("-node"), 1LL, 2LL, s("-dof"), 1LL, 2LL, s("disp")});
  add("Element", {s("-xml"), s(file("force.xml")), s("-ele"), 7LL, s("section"), 1LL, s("force")});
  for (int step = 1; step <= 3; ++step) commitStep(*domain_, step);
  r.close();
  domain_->removeRecorders();

  const XmlSummary x = checkXml(slurp(f));
  EXPECT_EQ(x.root, "OpenSees");
  ASSERT_EQ(x.blocks.size(), 3u);
  EXPECT_EQ(x.blocks[0], "TimeOutput");
  EXPECT_EQ(x.blocks[1].rfind("NodeOutput nodeTag=\"1\"", 0), 0u) << x.blocks[1];
  EXPECT_NE(x.blocks[2].find("coord1=\"1\""), std::string::npos) << x.blocks[2];
  const std::vector<std::string> types{"time", "D1", "D2", "D1", "D2"};
  EXPECT_EQ(x.responseTypes, types);
  const auto rows = parseRows(x.data, ' ');
  ASSERT_EQ(rows.size(), 3u);
  for (int step = 1; step <= 3; ++step) {
    ASSERT_EQ(rows[step - 1].size(), 5u);
    EXPECT_TRUE(closeAtPrecision(rows[step - 1][0], timeOf(step)));
    EXPECT_TRUE(closeAtPrecision(rows[step - 1][1], dispOf(step, 1, 0)));
    EXPECT_TRUE(closeAtPrecision(rows[step - 1][4], dispOf(step, 2, 1)));
  }
  EXPECT_FALSE(fs::exists(f + ".json"));  // XML describes itself

  const XmlSummary xe = checkXml(slurp(file("force.xml")));
  ASSERT_EQ(xe.blocks.size(), 1u);
  EXPECT_EQ(xe.blocks[0].rfind("ElementOutput eleType=\"ProbeElement\" eleTag=\"7\" node1=\"1\" node2=\"2\"", 0), 0u)
      << xe.blocks[0];
  EXPECT_EQ(xe.responseTypes, (std::vector<std::string>{"N", "M"}));
  EXPECT_EQ(parseRows(xe.data, ' ').size(), 3u);
}

TEST_F(RecorderTest, XmlLayoutIsOpenSeesToTheByte) {
  // The layout OpenSeesPy 3.7.1 writes (tests/python/oracle_scripts compares
  // whole files): schema attributes on the root, four spaces per level,
  // coordinates at the recorder's precision, data rows indented by eight with
  // a blank after every value; envelopes name the node only and put a time
  // block before each response type.
  const std::string f = file("exact.xml"), fe = file("envelope.xml");
  add("Node", {s("-xml"), s(f), s("-time"), s("-precision"), 3LL, s("-node"), 3LL, s("-dof"), 1LL, 2LL, s("disp")});
  add("EnvelopeNode", {s("-xml"), s(fe), s("-time"), s("-node"), 3LL, s("-dof"), 2LL, s("disp")});
  Vector u = Vector::Zero(6);
  u << 0.123456, -2.5e-5, 0.0, 0.0, 0.0, 0.0;
  domain_->node(3, "test").setTrialDisp(u);
  domain_->record();
  domain_->removeRecorders();
  const std::string header =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      " <OpenSees\n"
      "  xmlns:xsi = \"http://www.w3.org/2001/XMLSchema-instance\"\n"
      "  xsi:noNamespaceSchemaLocation = \"http://OpenSees.berkeley.edu/xml-schema/xmlns/OpenSees.xsd\">\n";
  EXPECT_EQ(slurp(f), header +
                          "    <TimeOutput>\n"
                          "        <ResponseType>time</ResponseType>\n"
                          "    </TimeOutput>\n"
                          "    <NodeOutput nodeTag=\"3\" coord1=\"2\" coord2=\"0.5\" coord3=\"-1\">\n"
                          "        <ResponseType>D1</ResponseType>\n"
                          "        <ResponseType>D2</ResponseType>\n"
                          "    </NodeOutput>\n"
                          "    <Data>\n"
                          "        0 0.123 -2.5e-05 \n"
                          "        </Data>\n"
                          "</OpenSees>\n");
  const std::string envelope = slurp(fe);
  EXPECT_EQ(envelope.substr(0, envelope.find("    <Data>")), header +
                                                                "    <NodeOutput nodeTag=\"3\">\n"
                                                                "        <TimeOutput>\n"
                                                                "            <ResponseType>time</ResponseType>\n"
                                                                "        </TimeOutput>\n"
                                                                "        <ResponseType>D2</ResponseType>\n"
                                                                "    </NodeOutput>\n");
}

TEST_F(RecorderTest, BinaryRowsAreNativeDoublesAndNewline) {
  const std::string f = file("disp.bin");
  Recorder& r = add("Node", {s("-binary"), s(f), s("-time"), s("-node"), 3LL, s("-dof"), 1LL, 2LL, 3LL, s("disp")});
  for (int step = 1; step <= 3; ++step) commitStep(*domain_, step);
  r.close();
  const std::string bytes = slurp(f);
  const std::size_t rowBytes = 4 * sizeof(double) + 1;
  ASSERT_EQ(bytes.size(), 3 * rowBytes);
  for (int step = 1; step <= 3; ++step) {
    const char* row = bytes.data() + (step - 1) * rowBytes;
    double v[4];
    std::memcpy(v, row, sizeof v);
    EXPECT_EQ(row[4 * sizeof(double)], '\n');
    // Binary keeps every bit: exact comparison.
    EXPECT_EQ(v[0], timeOf(step));
    for (int d = 0; d < 3; ++d) EXPECT_EQ(v[d + 1], dispOf(step, 3, d));
  }
  const Json j = readSidecar(f);
  EXPECT_EQ(j["format"].string, "binary");
  EXPECT_EQ(j["bytesPerRow"].number, static_cast<double>(rowBytes));
  EXPECT_EQ(j["columns"].array.size(), 4u);
}

TEST_F(RecorderTest, DeltaTSkipsRowsUntilTheIntervalHasPassed) {
  const std::string f = file("thin.out");
  // Steps at t = 0.1 .. 1.0; dT = 0.3 keeps 0.1, 0.4, 0.7, 1.0 (t = 0.4 is 0.1 + 0.3
  // only up to rounding: the relative tolerance keeps it).
  Recorder& r = add("Node", {s("-file"), s(f), s("-time"), s("-dT"), 0.3, s("-node"), 1LL, s("-dof"), 1LL, s("disp")});
  for (int step = 1; step <= 10; ++step) commitStep(*domain_, step);
  r.close();
  const auto rows = readTable(f);
  const int kept[] = {1, 4, 7, 10};
  ASSERT_EQ(rows.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_TRUE(closeAtPrecision(rows[k][0], timeOf(kept[k])));
    EXPECT_TRUE(closeAtPrecision(rows[k][1], dispOf(kept[k], 1, 0)));
  }
}

TEST_F(RecorderTest, FlushPutsEveryRowOnDiskWithoutClose) {
  const std::string f = file("disp.out"), fc = file("disp.csv"), fb = file("disp.bin");
  add("Node", {s("-file"), s(f), s("-node"), 2LL, s("-dof"), 1LL, s("disp")});
  add("Node", {s("-csv"), s(fc), s("-node"), 2LL, s("-dof"), 1LL, s("disp")});
  add("Node", {s("-binary"), s(fb), s("-node"), 2LL, s("-dof"), 1LL, s("disp")});
  for (int step = 1; step <= 5; ++step) commitStep(*domain_, step);
  domain_->flushRecorders();
  const auto rows = readTable(f);
  ASSERT_EQ(rows.size(), 5u);
  for (int step = 1; step <= 5; ++step) EXPECT_TRUE(closeAtPrecision(rows[step - 1][0], dispOf(step, 2, 0)));
  EXPECT_EQ(readTable(fc, ',').size(), 5u);
  EXPECT_EQ(fs::file_size(fb), 5 * (sizeof(double) + 1));
}

TEST_F(RecorderTest, CloseOnWriteLeavesCompleteFileAfterEveryRow) {
  const std::string f = file("disp.out");
  add("Node", {s("-file"), s(f), s("-closeOnWrite"), s("-node"), 1LL, s("-dof"), 2LL, s("disp")});
  for (int step = 1; step <= 3; ++step) {
    commitStep(*domain_, step);
    // No flush, no close: the row is already in the file.
    const auto rows = readTable(f);
    ASSERT_EQ(rows.size(), static_cast<std::size_t>(step));
    EXPECT_TRUE(closeAtPrecision(rows.back()[0], dispOf(step, 1, 1)));
  }
  domain_->removeRecorders();
  EXPECT_EQ(readTable(f).size(), 3u);
}

TEST_F(RecorderTest, FileAddAppendsToExistingContent) {
  const std::string f = file("disp.out");
  std::ofstream(f) << "1 2\n";
  Recorder& r = add("Node", {s("-fileAdd"), s(f), s("-node"), 1LL, s("-dof"), 1LL, 2LL, s("disp")});
  commitStep(*domain_, 1);
  r.close();
  const auto rows = readTable(f);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], (std::vector<double>{1.0, 2.0}));
  EXPECT_TRUE(closeAtPrecision(rows[1][1], dispOf(1, 1, 1)));
}

TEST_F(RecorderTest, PrecisionOptionSetsSignificantDigits) {
  const std::string f6 = file("p6.out"), f12 = file("p12.out");
  add("Node", {s("-file"), s(f6), s("-node"), 3LL, s("-dof"), 1LL, 2LL, 3LL, 4LL, 5LL, 6LL, s("disp")});
  add("Node", {s("-file"), s(f12), s("-precision"), 12LL, s("-node"), 3LL, s("-dof"), 1LL, 2LL, 3LL, 4LL, 5LL, 6LL,
               s("disp")});
  // Values with endless decimal expansions, over several magnitudes.
  Vector u(6);
  u << 1.0 / 3.0, -2.0 / 7.0, 1e-5 / 3.0, 12345.678901234, -9.87654321e7, 5.0 / 9.0;
  domain_->node(3, "test").setTrialDisp(u);
  domain_->record();
  domain_->removeRecorders();
  const auto r6 = readTable(f6), r12 = readTable(f12);
  ASSERT_EQ(r6.size(), 1u);
  ASSERT_EQ(r12.size(), 1u);
  for (int d = 0; d < 6; ++d) {
    EXPECT_TRUE(closeAtPrecision(r12[0][d], u[d], 12));
    EXPECT_TRUE(closeAtPrecision(r6[0][d], u[d], 6));
    // 6 digits cannot hold these values to 12 digits.
    EXPECT_FALSE(closeAtPrecision(r6[0][d], u[d], 12));
  }
  // Count significant digits of every written token: at most 6 resp. 12.
  auto maxSignificantDigits = [](const std::string& text) {
    std::istringstream words(text);
    std::string w;
    std::size_t most = 0;
    while (words >> w) {
      std::string mantissa = w.substr(0, w.find_first_of("eE"));
      std::string digits;
      for (char c : mantissa)
        if (std::isdigit(static_cast<unsigned char>(c))) digits += c;
      const std::size_t lead = digits.find_first_not_of('0');
      most = std::max(most, lead == std::string::npos ? std::size_t{1} : digits.size() - lead);
    }
    return most;
  };
  EXPECT_EQ(maxSignificantDigits(slurp(f6)), 6u);
  EXPECT_EQ(maxSignificantDigits(slurp(f12)), 12u);
}

TEST_F(RecorderTest, ScientificWritesPrecisionDigitsAfterThePoint) {
  // OpenSees' -scientific: %.pe with p = -precision (default 6), so p + 1
  // significant digits (checked against OpenSeesPy 3.7.1).
  const std::string f6 = file("sci6.out"), f3 = file("sci3.out");
  add("Node", {s("-file"), s(f6), s("-scientific"), s("-node"), 3LL, s("-dof"), 1LL, 2LL, 3LL, s("disp")});
  add("Node", {s("-file"), s(f3), s("-precision"), 3LL, s("-scientific"), s("-node"), 3LL, s("-dof"), 1LL, 2LL, 3LL,
               s("disp")});
  Vector u = Vector::Zero(6);
  u << 0.1, -98765.4321, 0.0, 0.0, 0.0, 0.0;
  domain_->node(3, "test").setTrialDisp(u);
  domain_->record();
  domain_->removeRecorders();
  EXPECT_EQ(slurp(f6), "1.000000e-01 -9.876543e+04 0.000000e+00\n");
  EXPECT_EQ(slurp(f3), "1.000e-01 -9.877e+04 0.000e+00\n");
}

TEST_F(RecorderTest, RemovedElementRecordsZeros) {
  const std::string f = file("force.out");
  add("Element", {s("-file"), s(f), s("-ele"), 7LL, s("section"), 3LL, s("force")});
  commitStep(*domain_, 1);
  domain_->removeElement(7, "test");
  commitStep(*domain_, 2);
  domain_->removeRecorders();
  const auto rows = readTable(f);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_TRUE(closeAtPrecision(rows[0][1], 7003.0));
  EXPECT_EQ(rows[1], (std::vector<double>{0.0, 0.0}));
}

TEST_F(RecorderTest, DestroyingTheDomainClosesFiles) {
  const std::string f = file("disp.xml");
  add("Node", {s("-xml"), s(f), s("-node"), 1LL, s("-dof"), 1LL, s("disp")});
  commitStep(*domain_, 1);
  commitStep(*domain_, 2);
  domain_.reset();
  const XmlSummary x = checkXml(slurp(f));  // throws if </Data> or </OpenSees> is missing
  EXPECT_EQ(parseRows(x.data, ' ').size(), 2u);
}

TEST_F(RecorderTest, EnvelopeNodeHoldsMinMaxAbsMaxWithTimes) {
  const std::string f = file("env.out");
  Recorder& r = add("EnvelopeNode", {s("-file"), s(f), s("-time"), s("-node"), 2LL, s("-dof"), 1LL, 2LL, s("disp")});
  EXPECT_EQ(r.className(), "EnvelopeNodeRecorder");
  auto expectEnvelope = [&](int steps) {
    const auto rows = readTable(f);
    ASSERT_EQ(rows.size(), 3u);
    int c = 0;
    for (int d : {0, 1}) {
      int minStep = 1, maxStep = 1, absStep = 1;
      for (int k = 2; k <= steps; ++k) {
        if (dispOf(k, 2, d) < dispOf(minStep, 2, d)) minStep = k;
        if (dispOf(k, 2, d) > dispOf(maxStep, 2, d)) maxStep = k;
        if (std::fabs(dispOf(k, 2, d)) > std::fabs(dispOf(absStep, 2, d))) absStep = k;
      }
      EXPECT_TRUE(closeAtPrecision(rows[0][c], timeOf(minStep)));
      EXPECT_TRUE(closeAtPrecision(rows[0][c + 1], dispOf(minStep, 2, d)));
      EXPECT_TRUE(closeAtPrecision(rows[1][c], timeOf(maxStep)));
      EXPECT_TRUE(closeAtPrecision(rows[1][c + 1], dispOf(maxStep, 2, d)));
      EXPECT_TRUE(closeAtPrecision(rows[2][c], timeOf(absStep)));
      EXPECT_TRUE(closeAtPrecision(rows[2][c + 1], std::fabs(dispOf(absStep, 2, d))));
      c += 2;
    }
  };
  for (int step = 1; step <= 3; ++step) commitStep(*domain_, step);
  r.flush();
  expectEnvelope(3);  // the current envelope is on disk after flush
  for (int step = 4; step <= 6; ++step) commitStep(*domain_, step);
  r.close();
  expectEnvelope(6);  // rewritten, still three rows
  const Json j = readSidecar(f);
  ASSERT_EQ(j["columns"].array.size(), 4u);
  EXPECT_EQ(j["columns"].array[0]["name"].string, "time_n2_D1");
  EXPECT_EQ(j["columns"].array[1]["dof"].number, 1.0);
}

TEST_F(RecorderTest, EnvelopeElementWrittenWhenDomainIsDestroyed) {
  const std::string f = file("env.out");
  add("EnvelopeElement", {s("-file"), s(f), s("-ele"), 7LL, s("section"), 2LL, s("force")});
  for (int step = 1; step <= 4; ++step) commitStep(*domain_, step);
  domain_.reset();
  const auto rows = readTable(f);
  ASSERT_EQ(rows.size(), 3u);
  double lo = 1e300, hi = -1e300, absMax = 0.0;
  for (int step = 1; step <= 4; ++step) {
    const double v = 2.0 * dispOf(step, 1, 0);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    absMax = std::max(absMax, std::fabs(v));
  }
  EXPECT_TRUE(closeAtPrecision(rows[0][0], lo));
  EXPECT_TRUE(closeAtPrecision(rows[1][0], hi));
  EXPECT_TRUE(closeAtPrecision(rows[2][0], absMax));
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(closeAtPrecision(rows[k][1], 7002.0));
}

TEST_F(RecorderTest, XmlWithCloseOnWriteIsCompleteAfterClose) {
  const std::string f = file("disp.xml");
  Recorder& r = add("Node", {s("-xml"), s(f), s("-closeOnWrite"), s("-node"), 2LL, s("-dof"), 3LL, s("disp")});
  for (int step = 1; step <= 2; ++step) commitStep(*domain_, step);
  r.close();
  const XmlSummary x = checkXml(slurp(f));
  const auto rows = parseRows(x.data, ' ');
  ASSERT_EQ(rows.size(), 2u);
  for (int step = 1; step <= 2; ++step) EXPECT_TRUE(closeAtPrecision(rows[step - 1][0], dispOf(step, 2, 2)));
}

TEST_F(RecorderTest, EnvelopeRewriteKeepsAppendedToContent) {
  const std::string f = file("env.out");
  std::ofstream(f) << "9 9\n";
  Recorder& r = add("EnvelopeNode", {s("-fileAdd"), s(f), s("-node"), 1LL, s("-dof"), 1LL, s("disp")});
  commitStep(*domain_, 1);
  r.flush();
  commitStep(*domain_, 2);
  r.close();
  const auto rows = readTable(f);
  ASSERT_EQ(rows.size(), 4u);  // the old line, then min, max, absmax
  EXPECT_EQ(rows[0], (std::vector<double>{9.0, 9.0}));
  EXPECT_TRUE(closeAtPrecision(rows[1][0], std::min(dispOf(1, 1, 0), dispOf(2, 1, 0))));
  EXPECT_TRUE(closeAtPrecision(rows[2][0], std::max(dispOf(1, 1, 0), dispOf(2, 1, 0))));
}

// ===========================================================================
// One writer per file: a second recorder on a claimed file is refused before
// it opens (and so truncates) the file.

TEST_F(RecorderTest, SecondRecorderOnAFileIsRefusedAndTheFirstKeepsItsRows) {
  add("Node", {s("-file"), s(file("other.out")), s("-node"), 3LL, s("disp")});  // tag 0
  const std::string f = file("disp.out");
  add("Node", {s("-file"), s(f), s("-time"), s("-node"), 2LL, s("-dof"), 1LL, 2LL, s("disp")});  // tag 1
  commitStep(*domain_, 1);
  domain_->flushRecorders();

  fs::create_directory_symlink(dir_, dir_ / "link");
  const std::string relative = fs::relative(f, fs::current_path()).string();
  ASSERT_NE(relative, f);
  const std::vector<std::string> spellings = {f, (dir_ / "." / "disp.out").string(),
                                              (dir_ / "nowhere" / ".." / "disp.out").string(),
                                              (dir_ / "link" / "disp.out").string(), relative};
  for (const std::string& spelling : spellings)
    for (const char* flag : {"-file", "-fileAdd", "-csv", "-xml", "-binary"}) {
      const std::string m = error("Node", {s(flag), s(spelling), s("-node"), 1LL, s("disp")});
      EXPECT_EQ(m.rfind("recorder Node: file '" + spelling + "' is already written by recorder 1 (Node)", 0), 0u)
          << m;
      EXPECT_NE(m.find("remove that recorder first or choose another file"), std::string::npos) << m;
      EXPECT_EQ(m.find("another model"), std::string::npos) << m;
      // A different spelling is shown with the holder's.
      const bool namesHolderSpelling = m.find(", which opened it as '" + f + "'") != std::string::npos;
      EXPECT_EQ(namesHolderSpelling, spelling != f) << m;
    }
  std::string m = error("Element", {s("-csv"), s(f), s("-ele"), 7LL, s("force")});
  EXPECT_EQ(m.rfind("recorder Element: file '" + f + "' is already written by recorder 1 (Node)", 0), 0u) << m;
  m = error("EnvelopeNode", {s("-file"), s(f), s("-node"), 1LL, s("disp")});
  EXPECT_EQ(m.rfind("recorder EnvelopeNode: file '" + f + "'", 0), 0u) << m;
  m = error("EnvelopeElement", {s("-binary"), s(f), s("-ele"), 8LL, s("force")});
  EXPECT_EQ(m.rfind("recorder EnvelopeElement: file '" + f + "'", 0), 0u) << m;
  m = error("PVD", {s((dir_ / "disp").string())});  // writes disp.pvd, not disp.out: allowed
  EXPECT_EQ(m, "(no error)");
  EXPECT_EQ(domain_->recorders().size(), 3u);  // refused recorders were never added

  // The holder's file was not touched: every row of every step, nothing else.
  for (int step = 2; step <= 3; ++step) commitStep(*domain_, step);
  domain_->removeRecorders();
  const auto rows = readTable(f);
  ASSERT_EQ(rows.size(), 3u);
  for (int step = 1; step <= 3; ++step) {
    ASSERT_EQ(rows[step - 1].size(), 3u);
    EXPECT_TRUE(closeAtPrecision(rows[step - 1][0], timeOf(step)));
    EXPECT_TRUE(closeAtPrecision(rows[step - 1][1], dispOf(step, 2, 0)));
    EXPECT_TRUE(closeAtPrecision(rows[step - 1][2], dispOf(step, 2, 1)));
  }
  EXPECT_EQ(readSidecar(f)["columnCount"].number, 3.0);  // the holder's sidecar, not a refused one's
}

TEST_F(RecorderTest, FileIsFreeOnceItsRecorderIsRemovedClosedOrDestroyed) {
  const std::string f = file("disp.out");
  const std::vector<V> args = {s("-file"), s(f), s("-node"), 1LL, s("-dof"), 1LL, s("disp")};
  add("Node", args);
  EXPECT_NE(error("Node", args), "(no error)");
  EXPECT_TRUE(domain_->removeRecorder(0));
  add("Node", args);  // tag 1
  domain_->removeRecorders();
  Recorder& r = add("Node", args);  // tag 2
  commitStep(*domain_, 1);
  r.close();  // writes no more: the file may be taken
  add("Node", args);
  domain_ = makeDomain();  // destroys the old domain and its recorders
  add("Node", args);
  commitStep(*domain_, 1);
  commitStep(*domain_, 2);
  domain_->removeRecorders();
  EXPECT_EQ(readTable(f).size(), 2u);  // the last recorder's rows alone
}

TEST_F(RecorderTest, TwoDomainsCannotShareAFile) {
  const std::string f = file("disp.out");
  add("Node", {s("-file"), s(f), s("-node"), 1LL, s("disp")});
  auto other = makeDomain();
  CommandArgs a("recorder", {s("-csv"), s(f), s("-node"), 2LL, s("disp")});
  try {
    Registry::global().recorders.get("Node")(a, *other);
    ADD_FAILURE() << "a second domain took the file";
  } catch (const OpenSeesError& e) {
    EXPECT_EQ(std::string(e.what()),
              "recorder Node: file '" + f + "' is already written by recorder 0 (Node) in another model; "
              "remove that recorder first or choose another file");
  }
  domain_->removeRecorders();
  CommandArgs again("recorder", {s("-csv"), s(f), s("-node"), 2LL, s("disp")});
  other->addRecorder(Registry::global().recorders.get("Node")(again, *other));
}

TEST_F(RecorderTest, FailedRecorderLeavesNoClaim) {
  const std::string f = file("x.out");
  // Refused by its own checks before it claims ...
  EXPECT_NE(error("Element", {s("-file"), s(f), s("-ele"), 77LL, s("force")}).find("77"), std::string::npos);
  EXPECT_NE(error("Node", {s("-file"), s(f), s("-node"), 42LL, s("disp")}).find("node 42"), std::string::npos);
  // ... and after it claimed: the folder does not exist yet.
  const std::string g = (dir_ / "later" / "x.out").string();
  EXPECT_NE(error("Node", {s("-file"), s(g), s("-node"), 1LL, s("disp")}).find("cannot open file"),
            std::string::npos);
  std::ofstream(dir_ / "blocker") << "a file where the PVD folder would go\n";
  const std::string pvd = (dir_ / "blocker" / "model").string();
  EXPECT_NE(error("PVD", {s(pvd)}).find("cannot create the folder"), std::string::npos);
  EXPECT_EQ(domain_->recorders().size(), 0u);

  fs::create_directory(dir_ / "later");
  fs::remove(dir_ / "blocker");
  add("Node", {s("-file"), s(f), s("-node"), 1LL, s("disp")});
  add("Node", {s("-file"), s(g), s("-node"), 1LL, s("disp")});
  add("PVD", {s(pvd)});
  EXPECT_EQ(domain_->recorders().size(), 3u);
}

TEST_F(RecorderTest, PvdRecordersOnOneNameAreRefused) {
  const std::string name = file("model");
  add("Node", {s("-file"), s(file("d.out")), s("-node"), 1LL, s("disp")});  // tag 0
  add("PVD", {s(name)});                                                     // tag 1
  std::string m = error("PVD", {s(name)});
  EXPECT_EQ(m.rfind("recorder PVD: file '" + name + ".pvd' is already written by recorder 1 (PVD)", 0), 0u) << m;
  m = error("vtk", {s(name + ".pvd")});
  EXPECT_EQ(m.rfind("recorder vtk: file '" + name + ".pvd' is already written by recorder 1 (PVD)", 0), 0u) << m;
  m = error("Node", {s("-file"), s(name + ".pvd"), s("-node"), 1LL, s("disp")});
  EXPECT_NE(m.find("recorder 1 (PVD)"), std::string::npos) << m;
  EXPECT_TRUE(domain_->removeRecorder(1));
  add("PVD", {s(name)});
}

TEST(OutputFileClaim, OneOfManyThreadsWinsAFile) {
  const std::string path = (fs::temp_directory_path() / "beamsolid_claim_race.out").string();
  Domain domain;
  std::atomic<int> won{0}, refused{0};
  std::vector<std::unique_ptr<OutputFileClaim>> claims(8);
  std::vector<std::thread> threads;
  for (int i = 0; i < 8; ++i)
    threads.emplace_back([&, i] {
      try {
        claims[i] = std::make_unique<OutputFileClaim>(path, OutputFileClaim::Holder{&domain, i, "Node"}, "test");
        ++won;
      } catch (const OpenSeesError&) {
        ++refused;
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(won, 1);
  EXPECT_EQ(refused, 7);
  claims.clear();
  OutputFileClaim again(path, OutputFileClaim::Holder{&domain, 9, "Node"}, "test");
  EXPECT_TRUE(again.held());
}
