#include "core/PVDRecorder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/Element.h"

namespace beamsolid {

namespace fs = std::filesystem;

namespace {

const char* const kResponseList = "disp, vel, accel, incrDisp, reaction, unbalance or eigen <mode>";

// VTK cell type numbers (vtkCellType.h).
constexpr std::uint8_t kVtkVertex = 1;
constexpr std::uint8_t kVtkLine = 3;
constexpr std::uint8_t kVtkTriangle = 5;
constexpr std::uint8_t kVtkQuad = 9;
constexpr std::uint8_t kVtkTetra = 10;
constexpr std::uint8_t kVtkHexahedron = 12;

// Times in the .pvd and the TimeValue field: enough digits that distinct
// steps stay distinct, few enough that 0.1 + 0.2 prints as 0.3.
constexpr int kTimeDigits = 15;

const char* const kCollectionTrailer = "  </Collection>\n</VTKFile>\n";

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

const char* byteOrder() { return std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian"; }

void appendReal(std::string& out, double v, int digits) {
  char number[40];
  const int n = std::snprintf(number, sizeof number, "%.*g", digits, v);
  out.append(number, static_cast<std::size_t>(n));
}

void appendInt(std::string& out, long long v) { out += std::to_string(v); }

// <DataArray ...> opening tag; component names become ComponentName<i>
// attributes, which ParaView shows in its component menus.
void openArray(std::string& out, const char* type, const std::string& name, int components,
               const std::vector<std::string>& componentNames = {}) {
  out += "        <DataArray type=\"";
  out += type;
  out += "\" Name=\"";
  out += xmlEscape(name);
  out += "\" NumberOfComponents=\"";
  appendInt(out, components);
  out += '"';
  for (std::size_t i = 0; i < componentNames.size(); ++i) {
    out += " ComponentName";
    appendInt(out, static_cast<long long>(i));
    out += "=\"";
    out += xmlEscape(componentNames[i]);
    out += '"';
  }
  out += " format=\"ascii\">\n";
}

void closeArray(std::string& out) { out += "        </DataArray>\n"; }

// One tuple per line.
template <class Tuple>
void appendTuple(std::string& out, const Tuple& values, int digits) {
  out += "          ";
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (i) out += ' ';
    appendReal(out, values[i], digits);
  }
  out += '\n';
}

// The translational part (the first ndm dofs, at most 3) of a vector.
Vector3 translational(const Vector& v, int ndm = 3) {
  Vector3 out = Vector3::Zero();
  for (Eigen::Index i = 0; i < std::min<Eigen::Index>(ndm, v.size()); ++i) out[i] = v[i];
  return out;
}

// The rotational part of a node's vector: dofs 4-6 of an ndf-6 node; the
// rotation about Z (dof 3) of a 2D node with ndf 3; zeros otherwise.
Vector3 rotational(const Vector& v, const Node& n) {
  if (n.ndm() == 2 && n.ndf() == 3 && v.size() >= 3) return Vector3(0.0, 0.0, v[2]);
  if (n.ndf() != 6 || v.size() < 6) return Vector3::Zero();
  return v.segment<3>(3);
}

// Names of the two point arrays (translations, rotations) of an extra quantity.
std::pair<std::string, std::string> extraNames(const PVDRecorder::Spec::Extra& e) {
  using Q = PVDRecorder::NodeQuantity;
  switch (e.quantity) {
    case Q::Vel: return {"velocity", "angularVelocity"};
    case Q::Accel: return {"acceleration", "angularAcceleration"};
    case Q::IncrDisp: return {"incrDisp", "incrRotation"};
    case Q::Reaction: return {"reaction", "reactionMoment"};
    case Q::Unbalance: return {"unbalancedLoad", "unbalancedMoment"};
    case Q::Eigen:
      return {"eigen_" + std::to_string(e.mode), "eigenRotation_" + std::to_string(e.mode)};
  }
  return {"?", "?"};
}

// The mean of the 6-component blocks of a per-Gauss-point response
// (stresses, strains); zeros when the response is not such a list.
Eigen::Matrix<double, 6, 1> gaussPointMean(const Response& r) {
  Eigen::Matrix<double, 6, 1> mean = Eigen::Matrix<double, 6, 1>::Zero();
  if (!r) return mean;
  const Vector v = r.value();
  const Eigen::Index points = v.size() / 6;
  if (points == 0 || v.size() % 6 != 0) return mean;
  for (Eigen::Index g = 0; g < points; ++g) mean += v.segment<6>(6 * g);
  return mean / static_cast<double>(points);
}

// The mean of the per-Gauss-point blocks of a quad's response, as a
// 6-component xx yy zz xy yz xz tuple: blocks of 3 (11 22 12) for plane
// strain and stress, of 4 (11 22 33 12: bbarQuad's out-of-plane strain)
// when the third component is named ..33.
Eigen::Matrix<double, 6, 1> planeMean(const Response& r) {
  Eigen::Matrix<double, 6, 1> out = Eigen::Matrix<double, 6, 1>::Zero();
  if (!r) return out;
  const auto& names = r.componentNames;
  const bool withOutOfPlane =
      names.size() >= 3 && names[2].size() >= 2 && names[2].compare(names[2].size() - 2, 2, "33") == 0;
  const Eigen::Index block = withOutOfPlane ? 4 : 3;
  const Vector v = r.value();
  const Eigen::Index points = v.size() / block;
  if (points == 0 || v.size() % block != 0) return out;
  Vector mean = Vector::Zero(block);
  for (Eigen::Index g = 0; g < points; ++g) mean += v.segment(block * g, block);
  mean /= static_cast<double>(points);
  out[0] = mean[0];
  out[1] = mean[1];
  if (withOutOfPlane) out[2] = mean[2];
  out[3] = mean[block - 1];
  return out;
}

// End forces in local axes as 12 values [N Vy Vz T My Mz] at end 1 then end
// 2, from a 'localForce' response: a beam's 12 values; a truss' ndf values
// per end; a corotational truss' axial force N alone (-N at end 1, N at end 2,
// the truss' layout).
// In a 2D model an end has at most N, Vy, Mz (ndf 3) or N, Vy (ndf 2).
Eigen::Matrix<double, 12, 1> localEndForces(const Response& r, bool planar) {
  Eigen::Matrix<double, 12, 1> out = Eigen::Matrix<double, 12, 1>::Zero();
  if (!r) return out;
  const Vector v = r.value();
  if (v.size() == 1) {
    out[0] = -v[0];
    out[6] = v[0];
  } else if (planar && (v.size() == 4 || v.size() == 6)) {
    static constexpr int slot[3] = {0, 1, 5};
    const Eigen::Index perEnd = v.size() / 2;
    for (Eigen::Index k = 0; k < perEnd; ++k) {
      out[slot[k]] = v[k];
      out[6 + slot[k]] = v[perEnd + k];
    }
  } else if (v.size() % 2 == 0 && v.size() <= 12) {
    const Eigen::Index perEnd = v.size() / 2;
    out.segment(0, perEnd) = v.segment(0, perEnd);
    out.segment(6, perEnd) = v.segment(perEnd, perEnd);
  }
  return out;
}

double firstValue(const Response& r) {
  if (!r) return 0.0;
  const Vector v = r.value();
  return v.size() > 0 ? v[0] : 0.0;
}

Vector3 firstThree(const Response& r) {
  if (!r) return Vector3::Zero();
  return translational(r.value());
}

// The node a contact is drawn at: its vertexNode(), else the beam contact
// elements' soil node (the third).
std::size_t vertexOf(const Element& e) {
  const int v = e.vertexNode();
  return v >= 0 ? static_cast<std::size_t>(v) : 2u;
}

// A Spec built in C++ may leave the context out.
PVDRecorder::Spec withContext(PVDRecorder::Spec s) {
  if (s.context.empty()) s.context = "recorder PVD";
  return s;
}

}  // namespace

bool PVDRecorder::cellKindOf(const std::string& className, CellKind& kind) {
  static const std::map<std::string, CellKind> kinds = {
      {"stdBrick", CellKind::Solid},
      {"bbarBrick", CellKind::Solid},
      {"SSPbrick", CellKind::Solid},
      {"quad", CellKind::Quad},
      {"bbarQuad", CellKind::Quad},
      {"SSPquad", CellKind::Quad},
      {"ShellMITC4", CellKind::Shell},
      {"tri31", CellKind::Quad},
      {"FourNodeTetrahedron", CellKind::Solid},
      {"elasticBeamColumn", CellKind::Beam},
      {"dispBeamColumn", CellKind::Beam},
      {"forceBeamColumn", CellKind::Beam},
      {"truss", CellKind::Truss},
      {"trussSection", CellKind::Truss},
      {"corotTruss", CellKind::Truss},
      {"BeamContact3D", CellKind::Contact},
      {"BeamContact3Dp", CellKind::Contact},
      {"BeamEndContact3D", CellKind::Contact},
  };
  auto it = kinds.find(className);
  if (it == kinds.end()) return false;
  kind = it->second;
  return true;
}

PVDRecorder::Spec PVDRecorder::Spec::parse(CommandArgs& args, const std::string& recorderType) {
  Spec s;
  s.context = "recorder " + recorderType;
  args.setContext(s.context);

  const std::size_t nameAt = args.position();
  std::string name = args.nextString("name");
  while (name.size() > 1 && name.back() == '/') name.pop_back();
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".pvd") == 0) name.resize(name.size() - 4);
  s.stem = fs::path(name).filename().string();
  if (s.stem.empty() || s.stem == "." || s.stem == "..")
    args.failAt(nameAt, "name",
                "a name for the output such as 'out' (which writes out.pvd and the folder out/)");
  s.directory = name;
  s.collectionPath = name + ".pvd";

  auto wanted = [&](NodeQuantity q, int mode) {
    for (const Extra& e : s.extras)
      if (e.quantity == q && e.mode == mode) return;
    s.extras.push_back({q, mode});
  };
  while (!args.done()) {
    if (args.nextFlag("-precision")) {
      const std::size_t at = args.position();
      s.precision = args.nextInt("precision");
      if (s.precision < 1 || s.precision > 17) args.failAt(at, "precision", "a number of significant digits from 1 to 17");
    } else if (args.nextFlag("-dT") || args.nextFlag("-dt")) {
      const std::size_t at = args.position();
      s.deltaT = args.nextDouble("dT");
      if (s.deltaT < 0.0) args.failAt(at, "dT", "a time interval >= 0");
    } else if (args.nextFlag("-rTolDt")) {
      const std::size_t at = args.position();
      s.relDeltaTTol = args.nextDouble("rTolDt");
      if (s.relDeltaTTol < 0.0) args.failAt(at, "rTolDt", "a relative tolerance >= 0");
    } else if (args.nextFlag("-time") || args.nextFlag("-load")) {
      // Times are always written (the .pvd and each file's TimeValue).
    } else if (auto word = args.peekString(); word && !word->empty() && (*word)[0] != '-') {
      const std::size_t at = args.position();
      const std::string response = args.nextString("response");
      if (response == "disp") {
        // Displacements and rotations are always written.
      } else if (response == "vel") {
        wanted(NodeQuantity::Vel, 0);
      } else if (response == "accel") {
        wanted(NodeQuantity::Accel, 0);
      } else if (response == "incrDisp") {
        wanted(NodeQuantity::IncrDisp, 0);
      } else if (response == "reaction") {
        wanted(NodeQuantity::Reaction, 0);
      } else if (response == "unbalance" || response == "unbalancedLoad") {
        wanted(NodeQuantity::Unbalance, 0);
      } else if (response == "eigen") {
        const std::size_t modeAt = args.position();
        const int mode = args.nextInt("mode");
        if (mode < 1) args.failAt(modeAt, "mode", "a mode number >= 1");
        wanted(NodeQuantity::Eigen, mode);
      } else {
        args.failAt(at, "response", std::string("one of ") + kResponseList);
      }
    } else {
      args.failAt(args.position(), "option",
                  std::string("'-precision', '-dT', '-rTolDt', '-time' or a response (") + kResponseList + ")");
    }
  }
  return s;
}

PVDRecorder::PVDRecorder(const Domain& domain, Spec spec)
    : spec_(withContext(std::move(spec))),
      claim_(spec_.collectionPath, OutputFileClaim::Holder::beingAddedTo(domain, "PVD"), spec_.context) {
  std::error_code ec;
  fs::create_directories(spec_.directory, ec);
  if (ec || !fs::is_directory(spec_.directory))
    throw OpenSeesError(spec_.context + ": cannot create the folder '" + spec_.directory + "'" +
                        (ec ? ": " + ec.message() : std::string()));
  collection_.open(spec_.collectionPath, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!collection_) throw OpenSeesError(spec_.context + ": cannot open file '" + spec_.collectionPath + "' for writing");
  collection_ << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"" << byteOrder()
              << "\">\n  <Collection>\n";
  trailerAt_ = collection_.tellp();
  collection_ << kCollectionTrailer;
  collection_.flush();
  if (!collection_) throw OpenSeesError(spec_.context + ": writing file '" + spec_.collectionPath + "' failed");
  if (wants(NodeQuantity::IncrDisp)) rememberDisplacements(domain);
}

PVDRecorder::~PVDRecorder() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw; close() was the last chance to report.
  }
}

bool PVDRecorder::wants(NodeQuantity q) const {
  return std::any_of(spec_.extras.begin(), spec_.extras.end(), [q](const Spec::Extra& e) { return e.quantity == q; });
}

void PVDRecorder::rememberDisplacements(const Domain& domain) {
  for (const auto& [tag, node] : domain.nodes()) previousDisp_[tag] = node->trialDisp();
}

bool PVDRecorder::due(double time) const {
  if (spec_.deltaT <= 0.0 || !anyRecord_) return true;
  return time - (lastRecordTime_ + spec_.deltaT) >= -spec_.relDeltaTTol * spec_.deltaT;
}

void PVDRecorder::record(Domain& domain, double time) {
  if (closed_) return;
  if (!due(time)) {
    // incrDisp is the increment since the previous record() call.
    if (wants(NodeQuantity::IncrDisp)) rememberDisplacements(domain);
    return;
  }
  updateTopology(domain);
  char fileName[64];
  std::snprintf(fileName, sizeof fileName, "_%06d.vtu", recordCount_);
  const std::string name = spec_.stem + fileName;
  writeGrid(domain, time, (fs::path(spec_.directory) / name).string());
  appendToCollection(time, spec_.stem + "/" + name);
  ++recordCount_;
  anyRecord_ = true;
  lastRecordTime_ = time;
  if (wants(NodeQuantity::IncrDisp)) rememberDisplacements(domain);
}

void PVDRecorder::updateTopology(Domain& domain) {
  if (anyTopology_ && topologyStamp_ == domain.modelStamp()) return;
  anyTopology_ = true;
  topologyStamp_ = domain.modelStamp();
  cells_.clear();
  points_.clear();
  haveKind_.fill(false);

  // Solids first, then lines, then contact vertices, each by element tag
  // (readers such as meshio group consecutive cells of one type).
  std::vector<Cell> solids, quads, shells, lines, contacts;
  for (const auto& [tag, element] : domain.elements()) {
    CellKind kind;
    // Classes by name, and any element that says it is a point (vertexNode).
    if (!cellKindOf(element->className(), kind)) {
      if (element->vertexNode() < 0) continue;
      kind = CellKind::Contact;
    }
    const auto& nodes = element->nodes();
    Cell cell;
    cell.element = element.get();
    cell.kind = kind;
    switch (kind) {
      case CellKind::Solid:
        if (nodes.size() != 8 && nodes.size() != 4) continue;
        // The bricks' order (bottom face counterclockwise seen from above,
        // then the top face, node 5 above node 1) is VTK_HEXAHEDRON's; a
        // tetrahedron of positive volume is a VTK_TETRA as it stands.
        cell.vtkType = nodes.size() == 8 ? kVtkHexahedron : kVtkTetra;
        cell.responses = {element->setResponse({"stresses"}), element->setResponse({"strains"}),
                          element->setResponse({"plasticStrains"}), element->setResponse({"equivalentPlasticStrains"})};
        solids.push_back(std::move(cell));
        break;
      case CellKind::Quad:
        if (nodes.size() != 4 && nodes.size() != 3) continue;
        // The quads' and triangles' nodes run counterclockwise, as VTK_QUAD's and VTK_TRIANGLE's.
        cell.vtkType = nodes.size() == 4 ? kVtkQuad : kVtkTriangle;
        cell.responses = {element->setResponse({"stresses"}), element->setResponse({"strains"}),
                          element->setResponse({"plasticStrains"}), element->setResponse({"equivalentPlasticStrains"})};
        quads.push_back(std::move(cell));
        break;
      case CellKind::Shell:
        if (nodes.size() != 4) continue;
        cell.vtkType = kVtkQuad;
        cell.responses = {element->setResponse({"stresses"})};
        shells.push_back(std::move(cell));
        break;
      case CellKind::Beam:
      case CellKind::Truss:
        if (nodes.size() < 2) continue;
        cell.vtkType = kVtkLine;
        cell.responses = {element->setResponse({"localForce"})};
        lines.push_back(std::move(cell));
        break;
      case CellKind::Contact: {
        if (vertexOf(*element) >= nodes.size()) continue;
        cell.vtkType = kVtkVertex;
        // The friction on the soil node where the beam contacts name it apart
        // (soilFrictionForce); a node-to-node contact has one friction force.
        Response friction = element->setResponse({"soilfrictionforce"});
        if (!friction) friction = element->setResponse({"frictionforce"});
        cell.responses = {element->setResponse({"status"}), element->setResponse({"gap"}),
                          element->setResponse({"forcescalar"}), std::move(friction),
                          element->setResponse({"normal"})};
        contacts.push_back(std::move(cell));
        break;
      }
    }
  }
  for (auto* group : {&solids, &quads, &shells, &lines, &contacts})
    for (Cell& c : *group) cells_.push_back(std::move(c));

  // Points: the nodes the cells use, by tag.
  auto cellNodes = [](const Cell& c) {
    const auto& nodes = c.element->nodes();
    switch (c.kind) {
      case CellKind::Solid:
      case CellKind::Quad:
      case CellKind::Shell: return std::vector<const Node*>(nodes.begin(), nodes.end());
      case CellKind::Beam:
      case CellKind::Truss: return std::vector<const Node*>{nodes[0], nodes[1]};
      case CellKind::Contact: return std::vector<const Node*>{nodes[vertexOf(*c.element)]};
    }
    return std::vector<const Node*>{};
  };
  std::map<int, const Node*> used;
  for (const Cell& c : cells_)
    for (const Node* n : cellNodes(c)) used.emplace(n->tag(), n);
  std::map<int, int> pointOf;
  for (const auto& [tag, node] : used) {
    pointOf.emplace(tag, static_cast<int>(points_.size()));
    points_.push_back(node);
  }
  for (Cell& c : cells_) {
    haveKind_[static_cast<std::size_t>(c.kind)] = true;
    for (const Node* n : cellNodes(c)) c.points.push_back(pointOf.at(n->tag()));
  }
}

void PVDRecorder::writeGrid(Domain& domain, double time, const std::string& path) {
  const int digits = spec_.precision;
  if (wants(NodeQuantity::Reaction)) domain.calculateReactions();
  std::string& out = buffer_;
  out.clear();
  out += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
  out += byteOrder();
  out += "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <FieldData>\n";
  out += "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">\n        ";
  appendReal(out, time, kTimeDigits);
  out += "\n      </DataArray>\n    </FieldData>\n    <Piece NumberOfPoints=\"";
  appendInt(out, static_cast<long long>(points_.size()));
  out += "\" NumberOfCells=\"";
  appendInt(out, static_cast<long long>(cells_.size()));
  out += "\">\n";

  // --- point data ---------------------------------------------------------------
  out += "      <PointData Vectors=\"displacement\">\n";
  openArray(out, "Int32", "nodeTag", 1);
  for (const Node* n : points_) {
    out += "          ";
    appendInt(out, n->tag());
    out += '\n';
  }
  closeArray(out);
  openArray(out, "Float64", "displacement", 3);
  for (const Node* n : points_) appendTuple(out, translational(n->trialDisp(), n->ndm()), digits);
  closeArray(out);
  openArray(out, "Float64", "rotation", 3);
  for (const Node* n : points_) appendTuple(out, rotational(n->trialDisp(), *n), digits);
  closeArray(out);
  Vector scratch;
  for (const Spec::Extra& extra : spec_.extras) {
    auto value = [&](const Node& n) -> const Vector& {
      switch (extra.quantity) {
        case NodeQuantity::Vel: return n.trialVel();
        case NodeQuantity::Accel: return n.trialAccel();
        case NodeQuantity::Reaction: return n.reaction();
        case NodeQuantity::Unbalance: return n.unbalancedLoad();
        case NodeQuantity::IncrDisp: {
          auto it = previousDisp_.find(n.tag());
          scratch = n.trialDisp();
          if (it != previousDisp_.end() && it->second.size() == scratch.size()) scratch -= it->second;
          return scratch;
        }
        case NodeQuantity::Eigen: {
          const Matrix& phi = n.eigenvectors();
          if (extra.mode <= phi.cols()) scratch = phi.col(extra.mode - 1);
          else scratch = Vector::Zero(n.ndf());
          return scratch;
        }
      }
      return scratch;
    };
    const auto [translationName, rotationName] = extraNames(extra);
    openArray(out, "Float64", translationName, 3);
    for (const Node* n : points_) appendTuple(out, translational(value(*n), n->ndm()), digits);
    closeArray(out);
    openArray(out, "Float64", rotationName, 3);
    for (const Node* n : points_) appendTuple(out, rotational(value(*n), *n), digits);
    closeArray(out);
  }
  out += "      </PointData>\n";

  // --- cell data ------------------------------------------------------------------
  out += "      <CellData>\n";
  openArray(out, "Int32", "elementTag", 1);
  for (const Cell& c : cells_) {
    out += "          ";
    appendInt(out, c.element->tag());
    out += '\n';
  }
  closeArray(out);
  openArray(out, "Int32", "elementKind", 1);
  for (const Cell& c : cells_) {
    out += "          ";
    appendInt(out, static_cast<int>(c.kind));
    out += '\n';
  }
  closeArray(out);
  const auto has = [&](CellKind k) { return haveKind_[static_cast<std::size_t>(k)]; };
  if (has(CellKind::Solid) || has(CellKind::Quad)) {
    // Plain mean over the Gauss points, in OpenSees' component order
    // xx yy zz xy yz xz (ParaView's order for a symmetric tensor); a quad's
    // 11 22 12 fill xx yy xy (the out-of-plane components are left 0, but
    // for bbarQuad's 33).
    const Eigen::Matrix<double, 6, 1> zero6 = Eigen::Matrix<double, 6, 1>::Zero();
    for (int which = 0; which < 2; ++which) {
      openArray(out, "Float64", which == 0 ? "stress" : "strain", 6);
      for (const Cell& c : cells_) {
        if (c.kind == CellKind::Solid) appendTuple(out, gaussPointMean(c.responses[which]), digits);
        else if (c.kind == CellKind::Quad) appendTuple(out, planeMean(c.responses[which]), digits);
        else appendTuple(out, zero6, digits);
      }
      closeArray(out);
    }
    // Plastic materials (J2Plasticity, DruckerPrager): the Gauss-point mean of
    // the plastic strain (6 components, engineering shears; a quad's too) and
    // of the equivalent plastic strain; 0 for cells without a plastic state.
    bool plastic = false;
    for (const Cell& c : cells_)
      if ((c.kind == CellKind::Solid || c.kind == CellKind::Quad) && c.responses.size() > 3 && c.responses[2])
        plastic = true;
    if (plastic) {
      openArray(out, "Float64", "plasticStrain", 6);
      for (const Cell& c : cells_) {
        const bool cellHas = (c.kind == CellKind::Solid || c.kind == CellKind::Quad) && c.responses.size() > 3;
        appendTuple(out, cellHas ? gaussPointMean(c.responses[2]) : zero6, digits);
      }
      closeArray(out);
      openArray(out, "Float64", "equivalentPlasticStrain", 1);
      for (const Cell& c : cells_) {
        Eigen::Matrix<double, 1, 1> mean = Eigen::Matrix<double, 1, 1>::Zero();
        if ((c.kind == CellKind::Solid || c.kind == CellKind::Quad) && c.responses.size() > 3 && c.responses[3]) {
          const Vector v = c.responses[3].value();
          if (v.size() > 0) mean(0) = v.mean();
        }
        appendTuple(out, mean, digits);
      }
      closeArray(out);
    }
  }
  if (has(CellKind::Shell)) {
    // Shells: the mean over the Gauss points of the section forces per unit
    // length in the element's frame (membrane, moments, shears).
    static const std::vector<std::string> names = {"p11", "p22", "p12", "m11", "m22", "m12", "q1", "q2"};
    openArray(out, "Float64", "shellForce", 8, names);
    for (const Cell& c : cells_) {
      Eigen::Matrix<double, 8, 1> mean = Eigen::Matrix<double, 8, 1>::Zero();
      if (c.kind == CellKind::Shell && c.responses[0]) {
        const Vector v = c.responses[0].value();
        for (Eigen::Index p = 0; p + 8 <= v.size(); p += 8) mean += v.segment<8>(p) / (v.size() / 8);
      }
      appendTuple(out, mean, digits);
    }
    closeArray(out);
  }
  if (has(CellKind::Beam) || has(CellKind::Truss)) {
    static const std::vector<std::string> names = {"N_1", "Vy_1", "Vz_1", "T_1", "My_1", "Mz_1",
                                                   "N_2", "Vy_2", "Vz_2", "T_2", "My_2", "Mz_2"};
    const Eigen::Matrix<double, 12, 1> zero12 = Eigen::Matrix<double, 12, 1>::Zero();
    openArray(out, "Float64", "localForce", 12, names);
    for (const Cell& c : cells_) {
      const bool line = c.kind == CellKind::Beam || c.kind == CellKind::Truss;
      const bool planar = line && c.element->nodes()[0]->ndm() == 2;
      appendTuple(out, line ? localEndForces(c.responses[0], planar) : zero12, digits);
    }
    closeArray(out);
  }
  if (has(CellKind::Contact)) {
    const Eigen::Matrix<double, 1, 1> zero1 = Eigen::Matrix<double, 1, 1>::Zero();
    openArray(out, "Int32", "contactStatus", 1);
    for (const Cell& c : cells_) {
      out += "          ";
      appendInt(out, c.kind == CellKind::Contact ? std::lround(firstValue(c.responses[0])) : 0);
      out += '\n';
    }
    closeArray(out);
    // gap (response 1) and the normal force, forcescalar[0] (response 2).
    for (int which : {1, 2}) {
      openArray(out, "Float64", which == 1 ? "contactGap" : "contactNormalForce", 1);
      for (const Cell& c : cells_) {
        Eigen::Matrix<double, 1, 1> v = zero1;
        if (c.kind == CellKind::Contact) v[0] = firstValue(c.responses[which]);
        appendTuple(out, v, digits);
      }
      closeArray(out);
    }
    // friction force (response 3) and the outward normal (response 4).
    for (int which : {3, 4}) {
      openArray(out, "Float64", which == 3 ? "contactFrictionForce" : "contactNormal", 3);
      for (const Cell& c : cells_)
        appendTuple(out, c.kind == CellKind::Contact ? firstThree(c.responses[which]) : Vector3::Zero().eval(),
                    digits);
      closeArray(out);
    }
  }
  out += "      </CellData>\n";

  // --- geometry: reference coordinates (warp by 'displacement' to deform) ------------
  out += "      <Points>\n";
  openArray(out, "Float64", "coordinates", 3);
  for (const Node* n : points_) appendTuple(out, n->crd(), digits);
  closeArray(out);
  out += "      </Points>\n      <Cells>\n";
  out += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const Cell& c : cells_) {
    out += "          ";
    for (std::size_t i = 0; i < c.points.size(); ++i) {
      if (i) out += ' ';
      appendInt(out, c.points[i]);
    }
    out += '\n';
  }
  out += "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  long long offset = 0;
  for (const Cell& c : cells_) {
    offset += static_cast<long long>(c.points.size());
    out += "          ";
    appendInt(out, offset);
    out += '\n';
  }
  out += "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (const Cell& c : cells_) {
    out += "          ";
    appendInt(out, c.vtkType);
    out += '\n';
  }
  out += "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";

  // Written beside and renamed, so that a reader never sees half a file.
  const std::string partial = path + ".part";
  {
    std::ofstream file(partial, std::ios::out | std::ios::trunc | std::ios::binary);
    if (!file) throw OpenSeesError(spec_.context + ": cannot open file '" + partial + "' for writing");
    file.write(out.data(), static_cast<std::streamsize>(out.size()));
    file.close();
    if (!file) throw OpenSeesError(spec_.context + ": writing file '" + partial + "' failed");
  }
  std::error_code ec;
  fs::rename(partial, path, ec);
  if (ec) throw OpenSeesError(spec_.context + ": cannot rename '" + partial + "' to '" + path + "': " + ec.message());
}

void PVDRecorder::appendToCollection(double time, const std::string& fileName) {
  // The DataSet line goes where the trailer was, and the trailer after it:
  // the collection is a complete document after every record.
  collection_.seekp(trailerAt_);
  std::string line = "    <DataSet timestep=\"";
  appendReal(line, time, kTimeDigits);
  line += "\" group=\"\" part=\"0\" file=\"";
  line += xmlEscape(fileName);
  line += "\"/>\n";
  collection_ << line;
  trailerAt_ = collection_.tellp();
  collection_ << kCollectionTrailer;
  collection_.flush();
  if (!collection_) throw OpenSeesError(spec_.context + ": writing file '" + spec_.collectionPath + "' failed");
}

void PVDRecorder::flush() {
  if (closed_ || !collection_.is_open()) return;
  collection_.flush();
  if (!collection_) throw OpenSeesError(spec_.context + ": flushing file '" + spec_.collectionPath + "' failed");
}

void PVDRecorder::close() {
  if (closed_) return;
  closed_ = true;
  bool ok = true;
  if (collection_.is_open()) {
    collection_.flush();
    ok = static_cast<bool>(collection_);
    collection_.close();
  }
  claim_.release();  // closed, this recorder writes no more
  if (!ok) throw OpenSeesError(spec_.context + ": writing file '" + spec_.collectionPath + "' failed");
}

namespace {

void registerPVDRecorder(Registry& r) {
  // 'vtk' is OpenSees' older name for the same output.
  for (const char* name : {"PVD", "pvd", "vtk", "VTK"})
    r.recorders.add(name, [type = std::string(name)](CommandArgs& args, Domain& domain) -> std::unique_ptr<Recorder> {
      return std::make_unique<PVDRecorder>(domain, PVDRecorder::Spec::parse(args, type));
    });
}

}  // namespace
BEAMSOLID_REGISTER(registerPVDRecorder);

}  // namespace beamsolid
