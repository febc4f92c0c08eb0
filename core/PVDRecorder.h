#pragma once
#include <array>
#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "core/OutputFileClaim.h"
#include "core/Recorder.h"
#include "core/Response.h"
#include "core/Types.h"

namespace beamsolid {

class CommandArgs;
class Element;
class Node;

// recorder('PVD', name, <'-precision', p>, <'-dT', dt>, <'-time'>, *responses)
// (also 'pvd', 'vtk', 'VTK'): the model for ParaView. Every record writes one
// VTK XML UnstructuredGrid file (ASCII) name/name_NNNNNN.vtu, and name.pvd
// lists them with their times; the .pvd is complete on disk after every
// record. Soil bricks (stdBrick, bbarBrick, SSPbrick) are hexahedra, quads
// (quad, bbarQuad, SSPquad) quadrilaterals, beams and trusses lines, beam-solid
// contacts vertices at their soil node; elements of other types (zeroLength
// included) are left out, and so are nodes that no written cell uses.
// docs/paraview.md lists the fields.
class PVDRecorder : public Recorder {
 public:
  // Node quantities beyond the displacement and rotation written always.
  enum class NodeQuantity { Vel, Accel, IncrDisp, Reaction, Unbalance, Eigen };

  struct Spec {
    std::string collectionPath;  // name.pvd
    std::string directory;       // name/ (the .vtu files)
    std::string stem;            // name's last component: the .vtu prefix
    int precision = 10;          // significant digits of every real value
    double deltaT = 0.0;         // -dT: record only when t >= last recorded + dT
    double relDeltaTTol = 1e-5;  // -rTolDt, relative to dT
    struct Extra {
      NodeQuantity quantity;
      int mode = 0;  // eigen: 1-based mode number
    };
    std::vector<Extra> extras;
    std::string context;  // "recorder PVD"

    static Spec parse(CommandArgs& args, const std::string& recorderType);
  };

  // Claims name.pvd (refused while another recorder writes it), creates the
  // directory and an empty collection; `domain` gives the starting
  // displacements for incrDisp.
  PVDRecorder(const Domain& domain, Spec spec);
  ~PVDRecorder() override;

  std::string className() const override { return "PVDRecorder"; }
  void record(Domain& domain, double time) override;
  void flush() override;
  void close() override;

  const Spec& spec() const { return spec_; }
  // Number of .vtu files written so far.
  int recordCount() const { return recordCount_; }

  // What a written cell is; the cell array 'elementKind'.
  enum class CellKind : int { Solid = 1, Beam = 2, Truss = 3, Contact = 4, Quad = 5, Shell = 6 };
  // How elements of a class are drawn, or false for a class left out.
  static bool cellKindOf(const std::string& className, CellKind& kind);

 private:
  // One written cell and the responses its cell data come from.
  struct Cell {
    Element* element = nullptr;
    CellKind kind = CellKind::Solid;
    std::uint8_t vtkType = 0;
    std::vector<int> points;  // indices into points_
    // Solid, Quad: stresses, strains, plasticStrains, equivalentPlasticStrains
    // (the last two empty for materials without a plastic state); Beam/Truss: localForce; Contact: status,
    // gap, forcescalar, frictionforce, normal.
    std::vector<Response> responses;
  };

  // Rebuilds cells and points when the model has changed (Domain::modelStamp).
  void updateTopology(Domain& domain);
  void writeGrid(Domain& domain, double time, const std::string& path);
  void appendToCollection(double time, const std::string& fileName);
  bool due(double time) const;
  bool wants(NodeQuantity q) const;
  void rememberDisplacements(const Domain& domain);

  Spec spec_;
  OutputFileClaim claim_;  // before collection_: claimed before it is opened
  std::ofstream collection_;
  std::streampos trailerAt_ = 0;  // where the next DataSet line goes
  bool closed_ = false;
  int recordCount_ = 0;
  bool anyRecord_ = false;
  double lastRecordTime_ = 0.0;

  long topologyStamp_ = -1;
  bool anyTopology_ = false;
  std::vector<const Node*> points_;  // ascending node tag
  std::vector<Cell> cells_;          // solids, quads, lines, contacts; each by element tag
  std::array<bool, 7> haveKind_{};   // by CellKind
  // incrDisp: each node's displacement at the previous record() call.
  std::map<int, Vector> previousDisp_;

  std::string buffer_;  // the .vtu being formatted
};

}  // namespace beamsolid
