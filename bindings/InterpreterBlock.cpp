// block2D: a structured mesh of four-node quadrilaterals over a block given by
// its corners 1-4 and optional edge midpoints 5-8 and centre 9 (OpenSees'
// FEAP-style block). The block is mapped from the square [-1, 1]^2 by the
// nine-node Lagrange interpolation; a missing edge point is the midpoint of
// its edge's corners and a missing centre the mean of the four corners.
// Nodes run in local x first (tag startNode + j (numX + 1) + i), elements
// likewise; each element lists its nodes counterclockwise and gets eleArgs.
#include <array>
#include <map>

#include "bindings/Interpreter.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

using Result = Interpreter::Result;

namespace {

// How many element arguments follow the element type (the coordinates come
// after them): the fixed part of each quadrilateral's command.
int elementArgumentCount(const std::string& type) {
  static const std::map<std::string, int> counts = {
      {"quad", 3},         // thick, type, matTag
      {"enhancedQuad", 3}, // thick, type, matTag
      {"bbarQuad", 2},     // thick, matTag
      {"SSPquad", 3},      // matTag, type, thick
      {"ShellMITC4", 1},   // secTag
      {"ShellDKGQ", 1},
      {"ShellNLDKGQ", 1},
  };
  auto it = counts.find(type);
  return it == counts.end() ? -1 : it->second;
}

// The nine-node Lagrange shape functions at (xi, eta); corners 1-4
// counterclockwise from (-1, -1), edge points 5-8 on edges 1-2, 2-3, 3-4,
// 4-1, centre 9.
std::array<double, 9> lagrange9(double xi, double eta) {
  const double lx[3] = {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
  const double ly[3] = {0.5 * eta * (eta - 1.0), 1.0 - eta * eta, 0.5 * eta * (eta + 1.0)};
  // (ix, iy) index of each point in the 3 x 3 grid.
  static const int grid[9][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0}, {2, 1}, {1, 2}, {0, 1}, {1, 1}};
  std::array<double, 9> n{};
  for (int k = 0; k < 9; ++k) n[k] = lx[grid[k][0]] * ly[grid[k][1]];
  return n;
}

}  // namespace

Result Interpreter::block2D(CommandArgs& a) {
  requireModel(a);
  const int ndm = domain_->ndm();
  const std::size_t numXAt = a.position();
  const int numX = a.nextInt("numX");
  if (numX < 1) a.failAt(numXAt, "numX", "an integer >= 1");
  const std::size_t numYAt = a.position();
  const int numY = a.nextInt("numY");
  if (numY < 1) a.failAt(numYAt, "numY", "an integer >= 1");
  const int startNode = a.nextInt("startNode");
  const int startEle = a.nextInt("startEle");
  const std::string type = a.nextString("eleType");
  const int count = elementArgumentCount(type);
  if (count < 0)
    a.fail("element type '" + type +
           "' is not a quadrilateral block2D can mesh (expected quad, enhancedQuad, bbarQuad, SSPquad, ShellMITC4, "
           "ShellDKGQ or ShellNLDKGQ)");
  if (static_cast<int>(a.remaining()) < count) a.fail("expected " + std::to_string(count) + " eleArgs for " + type);
  std::vector<CommandArgs::Value> eleArgs;
  for (int k = 0; k < count; ++k) eleArgs.push_back(a.at(a.position() + k));
  a.seek(a.position() + count);

  // Block points: tag (1-9) then ndm coordinates (a missing z is 0 in 3D).
  std::array<std::array<double, 3>, 9> x{};
  std::array<bool, 9> given{};
  while (!a.done()) {
    const std::size_t at = a.position();
    const int id = a.nextInt("block point (1-9)");
    if (id < 1 || id > 9) a.failAt(at, "block point", "1 to 9");
    if (given[id - 1]) a.failAt(at, "block point", "each of 1-9 at most once");
    for (int d = 0; d < ndm; ++d) x[id - 1][d] = a.nextDouble(d == 0 ? "x" : d == 1 ? "y" : "z");
    given[id - 1] = true;
  }
  for (int k = 0; k < 4; ++k)
    if (!given[k]) a.fail("block point " + std::to_string(k + 1) + " is missing (corners 1-4 are required)");
  for (int k = 4; k < 8; ++k)
    if (!given[k])
      for (int d = 0; d < 3; ++d) x[k][d] = 0.5 * (x[k - 4][d] + x[(k - 3) % 4][d]);
  if (!given[8])
    for (int d = 0; d < 3; ++d) x[8][d] = 0.25 * (x[0][d] + x[1][d] + x[2][d] + x[3][d]);

  // Nodes and elements through the ordinary commands, so tags, coordinates
  // and element arguments are checked as there; a failure names block2D.
  auto run = [&](const char* command, std::vector<CommandArgs::Value> values) {
    try {
      call(command, std::move(values));
    } catch (const OpenSeesError& e) {
      a.fail(e.what());
    }
  };
  for (int j = 0; j <= numY; ++j)
    for (int i = 0; i <= numX; ++i) {
      const auto n = lagrange9(-1.0 + 2.0 * i / numX, -1.0 + 2.0 * j / numY);
      std::vector<CommandArgs::Value> values{static_cast<long long>(startNode + j * (numX + 1) + i)};
      for (int d = 0; d < ndm; ++d) {
        double c = 0.0;
        for (int k = 0; k < 9; ++k) c += n[k] * x[k][d];
        values.emplace_back(c);
      }
      run("node", std::move(values));
    }
  for (int j = 0; j < numY; ++j)
    for (int i = 0; i < numX; ++i) {
      const long long n1 = startNode + j * (numX + 1) + i;
      std::vector<CommandArgs::Value> values{type, static_cast<long long>(startEle + j * numX + i), n1, n1 + 1,
                                             n1 + 1 + (numX + 1), n1 + (numX + 1)};
      values.insert(values.end(), eleArgs.begin(), eleArgs.end());
      run("element", std::move(values));
    }
  return {};
}

}  // namespace beamsolid
