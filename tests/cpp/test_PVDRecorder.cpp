// The PVD recorder's files as XML: every DataArray holds exactly tuples x
// components values, the cell arrays agree with each other, the .pvd is a
// complete document after every record, and the written model follows
// changes of the Domain. (Values against the model: tests/python/test_pvd_recorder.py.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/PVDRecorder.h"
#include "core/Registry.h"
#include "support/Script.h"

using namespace beamsolid;
using beamsolid::testing::Script;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// One <DataArray> of a .vtu: its attributes, the section it is in
// (FieldData, PointData, CellData, Points, Cells) and its values as text.
struct DataArray {
  std::map<std::string, std::string> attributes;
  std::string section;
  std::vector<std::string> values;
  int components() const {
    auto it = attributes.find("NumberOfComponents");
    return it == attributes.end() ? 1 : std::stoi(it->second);
  }
};

std::map<std::string, std::string> attributesOf(const std::string& tag) {
  std::map<std::string, std::string> out;
  static const std::regex attribute(R"re((\w+)="([^"]*)")re");
  for (std::sregex_iterator it(tag.begin(), tag.end(), attribute), end; it != end; ++it)
    out[(*it)[1]] = (*it)[2];
  return out;
}

// The DataArrays of a VTK XML file in order, by a scan that knows the
// sections; the whole must be <VTKFile> ... </VTKFile>.
std::vector<DataArray> dataArrays(const std::string& xml, std::map<std::string, std::string>& piece) {
  std::vector<DataArray> out;
  std::string section;
  std::size_t at = 0;
  while ((at = xml.find('<', at)) != std::string::npos) {
    const std::size_t end = xml.find('>', at);
    const std::string tag = xml.substr(at, end - at + 1);
    at = end + 1;
    for (const char* s : {"FieldData", "PointData", "CellData", "Points", "Cells"}) {
      if (tag.rfind(std::string("<") + s, 0) == 0 && !std::isalpha(static_cast<unsigned char>(tag[1 + std::strlen(s)])))
        section = s;
    }
    if (tag.rfind("<Piece ", 0) == 0) piece = attributesOf(tag);
    if (tag.rfind("<DataArray ", 0) == 0) {
      DataArray a{attributesOf(tag), section, {}};
      const std::size_t close = xml.find("</DataArray>", at);
      std::istringstream values(xml.substr(at, close - at));
      for (std::string v; values >> v;) a.values.push_back(v);
      out.push_back(std::move(a));
      at = close;
    }
  }
  return out;
}

const DataArray* find(const std::vector<DataArray>& arrays, const std::string& section, const std::string& name) {
  for (const auto& a : arrays)
    if (a.section == section && a.attributes.count("Name") && a.attributes.at("Name") == name) return &a;
  return nullptr;
}

class PVDRecorderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("beamsolid_pvd_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A unit cube brick 1 (nodes 1-8, ndf 3) with node 8 loaded, a truss 2
  // from node 7 to node 9, and a zeroLength 3 from node 9 to node 10 (which
  // nothing else uses); ndf-6 node 11 and 12 with beam 4.
  void buildModel(Script& s) {
    s("wipe");
    s("model", "basic", "-ndm", 3, "-ndf", 3);
    const double xyz[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (int k = 0; k < 8; ++k) s("node", k + 1, xyz[k][0], xyz[k][1], xyz[k][2]);
    for (int k = 1; k <= 4; ++k) s("fix", k, 1, 1, 1);
    s("node", 9, 1.0, 1.0, 2.0);
    s("node", 10, 1.0, 1.0, 2.0);
    s("fix", 10, 1, 1, 1);
    s("nDMaterial", "ElasticIsotropic", 1, 1000.0, 0.25);
    s("uniaxialMaterial", "Elastic", 1, 1000.0);
    s("element", "stdBrick", 1, 1, 2, 3, 4, 5, 6, 7, 8, 1);
    s("element", "truss", 2, 7, 9, 1.0, 1);
    s("element", "zeroLength", 3, 9, 10, "-mat", 1, "-dir", 1);
    s("fix", 9, 0, 1, 1);
    s("model", "basic", "-ndm", 3, "-ndf", 6);
    s("node", 11, 3.0, 0.0, 0.0);
    s("node", 12, 3.0, 0.0, 1.0);
    s("fix", 11, 1, 1, 1, 1, 1, 1);
    s("geomTransf", "Linear", 1, 1.0, 0.0, 0.0);
    s("element", "elasticBeamColumn", 4, 11, 12, 0.01, 2e5, 8e4, 1e-5, 1e-5, 1e-5, 1);
    s("timeSeries", "Linear", 1);
    s("pattern", "Plain", 1, 1);
    s("load", 8, 1.0, 2.0, -3.0);
    s("load", 12, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0);
    s("integrator", "LoadControl", 0.25);
    s("analysis", "Static");
  }

  fs::path dir_;
};

// Checks one .vtu: every array's value count, the cell arrays, and returns
// the counts of points and cells.
void checkGrid(const fs::path& file, std::size_t& points, std::size_t& cells) {
  const std::string xml = slurp(file);
  ASSERT_EQ(xml.rfind("<?xml", 0), 0u) << file;
  ASSERT_NE(xml.find("<VTKFile type=\"UnstructuredGrid\""), std::string::npos);
  ASSERT_EQ(xml.substr(xml.size() - 11), "</VTKFile>\n");
  std::map<std::string, std::string> piece;
  const auto arrays = dataArrays(xml, piece);
  points = std::stoul(piece.at("NumberOfPoints"));
  cells = std::stoul(piece.at("NumberOfCells"));
  for (const auto& a : arrays) {
    const std::string name = a.attributes.count("Name") ? a.attributes.at("Name") : "";
    EXPECT_EQ(a.attributes.at("format"), "ascii") << name;
    if (a.section == "PointData" || a.section == "Points")
      EXPECT_EQ(a.values.size(), points * a.components()) << name;
    else if (a.section == "CellData")
      EXPECT_EQ(a.values.size(), cells * a.components()) << name;
    else if (a.section == "FieldData")
      EXPECT_EQ(a.values.size(), 1u) << name;
    // Named components: one name per component.
    int named = 0;
    while (a.attributes.count("ComponentName" + std::to_string(named))) ++named;
    if (named) EXPECT_EQ(named, a.components()) << name;
  }
  const DataArray* connectivity = find(arrays, "Cells", "connectivity");
  const DataArray* offsets = find(arrays, "Cells", "offsets");
  const DataArray* types = find(arrays, "Cells", "types");
  ASSERT_TRUE(connectivity && offsets && types);
  ASSERT_EQ(offsets->values.size(), cells);
  ASSERT_EQ(types->values.size(), cells);
  std::size_t previous = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    const std::size_t offset = std::stoul(offsets->values[c]);
    const int type = std::stoi(types->values[c]);
    const std::size_t expected = type == 12 ? 8 : type == 3 ? 2 : type == 1 ? 1 : 0;
    EXPECT_EQ(offset - previous, expected) << "cell " << c << " of type " << type;
    previous = offset;
  }
  EXPECT_EQ(previous, connectivity->values.size());
  for (const auto& v : connectivity->values) EXPECT_LT(std::stoul(v), points);
}

std::vector<std::string> collectionFiles(const fs::path& pvd) {
  const std::string xml = slurp(pvd);
  EXPECT_NE(xml.find("<VTKFile type=\"Collection\""), std::string::npos);
  EXPECT_EQ(xml.substr(xml.size() - 27), "  </Collection>\n</VTKFile>\n") << "a complete document";
  std::vector<std::string> files;
  static const std::regex dataset(R"re(<DataSet timestep="[^"]*" group="" part="0" file="([^"]*)"/>)re");
  for (std::sregex_iterator it(xml.begin(), xml.end(), dataset), end; it != end; ++it) files.push_back((*it)[1]);
  return files;
}

}  // namespace

TEST_F(PVDRecorderTest, EveryFileIsCompleteAndEveryArrayHasOneTuplePerPointOrCell) {
  Script s;
  buildModel(s);
  s("recorder", "PVD", (dir_ / "run").string(), "reaction", "vel");
  for (int step = 1; step <= 3; ++step) {
    ASSERT_EQ(s.integer("analyze", 1), 0);
    const auto files = collectionFiles(dir_ / "run.pvd");
    ASSERT_EQ(files.size(), static_cast<std::size_t>(step));
    std::size_t points = 0, cells = 0;
    checkGrid(dir_ / files.back(), points, cells);
    // brick + truss + beam (zeroLength left out); nodes 1-9, 11, 12 (10 only in the zeroLength).
    EXPECT_EQ(cells, 3u);
    EXPECT_EQ(points, 11u);
  }
  EXPECT_FALSE(fs::exists(dir_ / "run" / "run_000000.vtu.part"));
}

TEST_F(PVDRecorderTest, FollowsTheModelWhenElementsAreRemoved) {
  Script s;
  buildModel(s);
  s("recorder", "VTK", (dir_ / "staged").string());
  ASSERT_EQ(s.integer("analyze", 1), 0);
  s("remove", "ele", 2);  // the truss: node 9 loses its last written cell
  ASSERT_EQ(s.integer("analyze", 1), 0);
  const auto files = collectionFiles(dir_ / "staged.pvd");
  ASSERT_EQ(files.size(), 2u);
  std::size_t points = 0, cells = 0;
  checkGrid(dir_ / files[0], points, cells);
  EXPECT_EQ(cells, 3u);
  EXPECT_EQ(points, 11u);
  checkGrid(dir_ / files[1], points, cells);
  EXPECT_EQ(cells, 2u);
  EXPECT_EQ(points, 10u);
}

TEST_F(PVDRecorderTest, TheCollectionStaysCompleteWhenTheInterpreterGoes) {
  {
    Script s;
    buildModel(s);
    s("recorder", "pvd", (dir_ / "a").string());
    ASSERT_EQ(s.integer("analyze", 2), 0);
  }  // the Domain closes its recorders
  EXPECT_EQ(collectionFiles(dir_ / "a.pvd"), (std::vector<std::string>{"a/a_000000.vtu", "a/a_000001.vtu"}));
}

TEST(PVDRecorderRegistry, AllFourNamesBuildThePVDRecorder) {
  for (const char* name : {"PVD", "pvd", "vtk", "VTK"}) EXPECT_TRUE(Registry::global().recorders.has(name)) << name;
  PVDRecorder::CellKind kind;
  EXPECT_TRUE(PVDRecorder::cellKindOf("stdBrick", kind));
  EXPECT_EQ(kind, PVDRecorder::CellKind::Solid);
  EXPECT_TRUE(PVDRecorder::cellKindOf("BeamContact3D", kind));
  EXPECT_EQ(kind, PVDRecorder::CellKind::Contact);
  EXPECT_FALSE(PVDRecorder::cellKindOf("zeroLength", kind));
}
