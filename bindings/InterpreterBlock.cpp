// block2D: a structured mesh of four-node quadrilaterals over a block given by
// its corners 1-4 and optional edge midpoints 5-8 and centre 9 (OpenSees'
// FEAP-style block). The block is mapped from the square [-1, 1]^2 by the
// nine-node Lagrange interpolation; a missing edge point is the midpoint of
// its edge's corners and a missing centre the mean of the four corners.
// Nodes run in local x first (tag startNode + j (numX + 1) + i), elements
// likewise; each element lists its nodes counterclockwise and gets eleArgs.
//
// block3D: the same for eight-node bricks over a block given by its corners
// 1-8 (bottom face 1-4, top face 5-8) and optional points 9-27: midpoints of
// the vertical edges 1-5, 2-6, 3-7, 4-8 (9-12), of the bottom edges 1-2, 2-3,
// 3-4, 4-1 (13-16), the bottom face centre (17), the top edges 5-6, 6-7,
// 7-8, 8-5 (18-21), the top face centre (22), the centres of the faces
// y = -1, x = +1, y = +1, x = -1 (23-26) and the block centre (27), as
// OpenSees numbers them (found by running OpenSeesPy). Mapped by the
// 27-point Lagrange interpolation; a missing point is where the corners'
// trilinear map puts it. Nodes run x, then y, then z.
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
      {"shellMITC4", 1},   // OpenSees' other names of ShellMITC4
      {"Shell", 1},
      {"shell", 1},
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

// block3D's element types and the element arguments each takes before the
// coordinates: eight-node bricks, one material tag.
int brickArgumentCount(const std::string& type) {
  static const std::map<std::string, int> counts = {
      {"stdBrick", 1}, {"bbarBrick", 1}, {"SSPbrick", 1}, {"FLBrick", 1}, {"Brick", 1},
  };
  auto it = counts.find(type);
  return it == counts.end() ? -1 : it->second;
}

// Grid position (0, 1, 2 per axis) of block3D's points 1-27.
constexpr int kBlock3DGrid[27][3] = {
    {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2},  // corners
    {0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1},                                          // vertical edges
    {1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}, {1, 1, 0},                               // bottom
    {1, 0, 2}, {2, 1, 2}, {1, 2, 2}, {0, 1, 2}, {1, 1, 2},                               // top
    {1, 0, 1}, {2, 1, 1}, {1, 2, 1}, {0, 1, 1}, {1, 1, 1},                               // faces, centre
};

// One-dimensional quadratic Lagrange polynomials through -1, 0, 1.
std::array<double, 3> lagrange3(double t) {
  return {0.5 * t * (t - 1.0), 1.0 - t * t, 0.5 * t * (t + 1.0)};
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
           "' is not a quadrilateral block2D can mesh (expected quad, enhancedQuad, bbarQuad, SSPquad, ShellMITC4 (shell), "
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

Result Interpreter::block3D(CommandArgs& a) {
  requireModel(a);
  if (domain_->ndm() != 3) a.fail("block3D needs a 3D model (ndm 3), this one has ndm " + std::to_string(domain_->ndm()));
  int num[3];
  for (int d = 0; d < 3; ++d) {
    const char* what = d == 0 ? "numX" : d == 1 ? "numY" : "numZ";
    const std::size_t at = a.position();
    num[d] = a.nextInt(what);
    if (num[d] < 1) a.failAt(at, what, "an integer >= 1");
  }
  const int startNode = a.nextInt("startNode");
  const int startEle = a.nextInt("startEle");
  const std::string type = a.nextString("eleType");
  const int count = brickArgumentCount(type);
  if (count < 0)
    a.fail("element type '" + type +
           "' is not an eight-node brick block3D can mesh (expected stdBrick, bbarBrick, SSPbrick, FLBrick or Brick)");
  if (static_cast<int>(a.remaining()) < count) a.fail("expected " + std::to_string(count) + " eleArgs for " + type);
  std::vector<CommandArgs::Value> eleArgs;
  for (int k = 0; k < count; ++k) eleArgs.push_back(a.at(a.position() + k));
  a.seek(a.position() + count);

  std::array<std::array<double, 3>, 27> x{};
  std::array<bool, 27> given{};
  while (!a.done()) {
    const std::size_t at = a.position();
    const int id = a.nextInt("block point (1-27)");
    if (id < 1 || id > 27) a.failAt(at, "block point", "1 to 27");
    if (given[id - 1]) a.failAt(at, "block point", "each of 1-27 at most once");
    for (int d = 0; d < 3; ++d) x[id - 1][d] = a.nextDouble(d == 0 ? "x" : d == 1 ? "y" : "z");
    given[id - 1] = true;
  }
  for (int k = 0; k < 8; ++k)
    if (!given[k]) a.fail("block point " + std::to_string(k + 1) + " is missing (corners 1-8 are required)");
  for (int k = 8; k < 27; ++k) {
    if (given[k]) continue;
    // The corners' trilinear map at the point's place.
    double w[3][2];
    for (int d = 0; d < 3; ++d) {
      const double t = 0.5 * kBlock3DGrid[k][d];
      w[d][0] = 1.0 - t;
      w[d][1] = t;
    }
    for (int c = 0; c < 8; ++c) {
      const double weight = w[0][kBlock3DGrid[c][0] / 2] * w[1][kBlock3DGrid[c][1] / 2] * w[2][kBlock3DGrid[c][2] / 2];
      for (int d = 0; d < 3; ++d) x[k][d] += weight * x[c][d];
    }
  }

  auto run = [&](const char* command, std::vector<CommandArgs::Value> values) {
    try {
      call(command, std::move(values));
    } catch (const OpenSeesError& e) {
      a.fail(e.what());
    }
  };
  const long long nx = num[0] + 1, nxy = static_cast<long long>(num[0] + 1) * (num[1] + 1);
  for (int k = 0; k <= num[2]; ++k)
    for (int j = 0; j <= num[1]; ++j)
      for (int i = 0; i <= num[0]; ++i) {
        const auto lx = lagrange3(-1.0 + 2.0 * i / num[0]);
        const auto ly = lagrange3(-1.0 + 2.0 * j / num[1]);
        const auto lz = lagrange3(-1.0 + 2.0 * k / num[2]);
        double c[3] = {0.0, 0.0, 0.0};
        for (int p = 0; p < 27; ++p) {
          const double n = lx[kBlock3DGrid[p][0]] * ly[kBlock3DGrid[p][1]] * lz[kBlock3DGrid[p][2]];
          for (int d = 0; d < 3; ++d) c[d] += n * x[p][d];
        }
        run("node", {static_cast<long long>(startNode + k * nxy + j * nx + i), c[0], c[1], c[2]});
      }
  for (int k = 0; k < num[2]; ++k)
    for (int j = 0; j < num[1]; ++j)
      for (int i = 0; i < num[0]; ++i) {
        const long long n1 = startNode + k * nxy + j * nx + i;
        const long long tag = startEle + (static_cast<long long>(k) * num[1] + j) * num[0] + i;
        std::vector<CommandArgs::Value> values{type, tag, n1, n1 + 1, n1 + 1 + nx, n1 + nx,
                                               n1 + nxy, n1 + 1 + nxy, n1 + 1 + nx + nxy, n1 + nx + nxy};
        values.insert(values.end(), eleArgs.begin(), eleArgs.end());
        run("element", std::move(values));
      }
  return {};
}

}  // namespace beamsolid
