#include "elements/SectionBeamColumn2d.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/BeamMass.h"
#include "elements/transforms/CrdTransf.h"

namespace beamsolid {

SectionBeamColumn2d::SectionBeamColumn2d(int tag, Definition&& d)
    : Element(tag, {d.nodeI, d.nodeJ}),
      transf_(std::move(d.transf)),
      integration_(std::move(d.integration)),
      sections_(std::move(d.sections)),
      options_(d.options) {}

void SectionBeamColumn2d::setDomain(Domain&) {
  for (const Node* n : nodes())
    if (n->ndf() != 3)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs, the 2D " + className() + " needs 3 (create its nodes after "
                          "model('basic', '-ndm', 2, '-ndf', 3))");
  try {
    transf_->initialize(*nodes()[0], *nodes()[1]);
    length_ = transf_->initialLength();
    integration_->pointsAndWeights(length_, xi_, weights_);
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
  if (static_cast<int>(xi_.size()) != numSections())
    throw OpenSeesError(context() + ": the integration rule has " + std::to_string(xi_.size()) +
                        " points but the element has " + std::to_string(numSections()) + " sections");

  // The 3D beam's mass restricted to the plane (ux, uy, rz at each end).
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  const Eigen::Vector2d x = transf_->axis();
  axes.row(0) << x.x(), x.y(), 0.0;
  axes.row(1) << -x.y(), x.x(), 0.0;
  const CrdTransf::Matrix12 m12 = beamMass(options_.massPerLength, length_, options_.consistentMass, 0.0, axes);
  static constexpr int inPlane[6] = {0, 1, 5, 6, 7, 11};
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) mass_(a, b) = m12(inPlane[a], inPlane[b]);

  initializeState();
  initialStiff_ = transf_->initialGlobalStiffMatrix(initialBasicStiffness_);
}

MatrixView SectionBeamColumn2d::tangentStiff() {
  const Matrix3& kb = basicStiffness();
  stiff_ = transf_->globalStiffMatrix(kb, basicForce());
  return viewOf(stiff_);
}

MatrixView SectionBeamColumn2d::initialStiff() { return viewOf(initialStiff_); }

VectorView SectionBeamColumn2d::resistingForce() {
  force_ = transf_->globalResistingForce(basicForce(), p0_);
  return viewOf(force_);
}

MatrixView SectionBeamColumn2d::massMatrix() { return viewOf(mass_); }

SectionBeamColumn2d::Vector3 SectionBeamColumn2d::plasticDeformation() {
  return basicDeformation() - initialBasicStiffness_.ldlt().solve(basicForce());
}

bool SectionBeamColumn2d::acceptsLoad(ElementLoad::Type type) const {
  return type == ElementLoad::Type::BeamUniform || type == ElementLoad::Type::BeamPoint;
}

SectionBeamColumn2d::BeamLoad SectionBeamColumn2d::readLoad(const ElementLoad& load, double factor) const {
  // eleLoad keeps 2D loads in the 3D layout: (Wy, 0, Wx) and (Py, 0, xL, Px).
  const std::vector<double>& v = load.values;
  BeamLoad out;
  switch (load.type) {
    case ElementLoad::Type::BeamUniform:
      if (v.size() != 3) throw OpenSeesError(context() + ": -beamUniform needs Wy and optionally Wx");
      out.uniform = true;
      out.wy = factor * v[0];
      out.wx = factor * v[2];
      return out;
    case ElementLoad::Type::BeamPoint:
      if (v.size() != 4) throw OpenSeesError(context() + ": -beamPoint needs Py, xL and optionally Px");
      if (!(v[2] >= 0.0 && v[2] <= 1.0))
        throw OpenSeesError(context() + ": -beamPoint xL must lie in [0, 1] (a fraction of the length), got " +
                            std::to_string(v[2]));
      out.uniform = false;
      out.py = factor * v[0];
      out.a = v[2] * length_;
      out.px = factor * v[3];
      return out;
    default:
      throw OpenSeesError(context() + ": does not accept element load " + ElementLoad::typeName(load.type));
  }
}

void SectionBeamColumn2d::addLoadReactions(const BeamLoad& load) {
  const double L = length_;
  if (load.uniform) {
    // Axial all at I, transverse half at each end.
    p0_[0] -= load.wx * L;
    p0_[1] -= 0.5 * load.wy * L;
    p0_[4] -= 0.5 * load.wy * L;
  } else {
    const double a = load.a, b = L - load.a;
    p0_[0] -= load.px;
    p0_[1] -= load.py * b / L;
    p0_[4] -= load.py * a / L;
  }
}

Response SectionBeamColumn2d::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "force" || what == "forces" || what == "globalForce" || what == "globalForces")
    return Response::named({"Px_1", "Py_1", "Mz_1", "Px_2", "Py_2", "Mz_2"},
                           [this] { return beamsolid::Vector(resistingForce()); });
  if (what == "localForce" || what == "localForces")
    return Response::named({"N_1", "V_1", "M_1", "N_2", "V_2", "M_2"},
                           [this] { return beamsolid::Vector(localForce()); });
  if (what == "basicForce" || what == "basicForces")
    return Response::named({"N", "M_1", "M_2"}, [this] { return beamsolid::Vector(basicForce()); });
  if (what == "basicDeformation" || what == "basicDeformations" || what == "deformation" ||
      what == "deformations")
    return Response::named({"eps", "theta_1", "theta_2"}, [this] { return beamsolid::Vector(basicDeformation()); });
  if (what == "plasticDeformation" || what == "plasticDeformations")
    return Response::named({"eps", "theta_1", "theta_2"},
                           [this] { return beamsolid::Vector(plasticDeformation()); });
  if (what == "basicStiffness") {
    std::vector<std::string> names;
    for (const char* row : {"N", "M_1", "M_2"})
      for (const char* col : {"eps", "theta_1", "theta_2"}) names.push_back(std::string("d") + row + "_d" + col);
    return Response::named(std::move(names), [this] {
      const Matrix3& kb = basicStiffness();
      beamsolid::Vector out(9);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out[3 * r + c] = kb(r, c);
      return out;
    });
  }
  if (what == "integrationPoints")
    return Response::named(Response::numberedNames("x", numSections()), [this] {
      beamsolid::Vector out(numSections());
      for (int i = 0; i < numSections(); ++i) out[i] = xi_[i] * length_;
      return out;
    });
  if (what == "integrationWeights")
    return Response::named(Response::numberedNames("w", numSections()), [this] {
      beamsolid::Vector out(numSections());
      for (int i = 0; i < numSections(); ++i) out[i] = weights_[i] * length_;
      return out;
    });
  if (what == "section" && args.size() >= 3) {
    int number = 0;
    try {
      std::size_t used = 0;
      number = std::stoi(args[1], &used);
      if (used != args[1].size()) return {};
    } catch (const std::exception&) {
      return {};
    }
    if (number < 1 || number > numSections()) return {};
    return sections_[number - 1]->setResponse(std::vector<std::string>(args.begin() + 2, args.end()));
  }
  return {};
}

void SectionBeamColumn2d::print(std::ostream& os) const {
  os << className() << ' ' << tag() << " (2D): nodes " << nodeTags()[0] << ' ' << nodeTags()[1] << ", "
     << integration_->className() << " integration with " << numSections() << " sections (";
  for (int i = 0; i < numSections(); ++i)
    os << (i ? " " : "") << sections_[i]->className() << ' ' << sections_[i]->tag();
  os << "), geomTransf " << transf_->className() << ' ' << transf_->tag();
  if (options_.massPerLength != 0.0)
    os << ", mass/length " << options_.massPerLength << (options_.consistentMass ? " (consistent)" : " (lumped)");
  if (length_ > 0.0) os << ", L " << length_;
  os << '\n';
}

void SectionBeamColumn2d::printJSON(std::ostream& os) const {
  const auto precision = os.precision(12);
  os << "{\"name\": " << tag() << ", \"type\": \"" << className() << "\", \"nodes\": [" << nodeTags()[0] << ", "
     << nodeTags()[1] << "], \"sections\": [";
  for (int i = 0; i < numSections(); ++i) os << (i ? ", " : "") << sections_[i]->tag();
  os << "], \"integration\": \"" << integration_->className() << "\", \"massperlength\": " << options_.massPerLength
     << ", \"crdTransformation\": \"" << transf_->tag() << "\"}";
  os.precision(precision);
}

SectionBeamColumn2d::Definition SectionBeamColumn2d::parse(CommandArgs& args, Domain& domain, const std::string& type,
                                                           BeamIntegration::Rule defaultRule, bool forceBased) {
  BeamColumnCommand c = BeamColumnCommand::parse(args, domain, type, defaultRule, forceBased, true);
  Definition d;
  d.tag = c.tag;
  d.nodeI = c.nodeI;
  d.nodeJ = c.nodeJ;
  d.options = c.options;
  d.integration = std::move(c.integration);
  for (int s : d.integration->sectionTags())
    d.sections.push_back(SectionForceDeformation2d::of(domain.sections.get(s, args.context()), args.context()).clone());
  const CrdTransf& definition = domain.geomTransfs.get(c.transfTag, args.context());
  d.transf = definition.planar();
  if (!d.transf)
    args.fail("geomTransf " + definition.className() + " " + std::to_string(c.transfTag) +
              " has no 2D form yet (use 'Linear' or 'PDelta')");
  return d;
}

bool SectionBeamColumn2d::setParameter(const std::vector<std::string>& args, double value) {
  bool accepted = false;
  for (auto& s : sections_) accepted = s->setParameter(args, value) || accepted;
  if (accepted) {
    initializeState();  // the initial stiffness follows
    initialStiff_ = transf_->initialGlobalStiffMatrix(initialBasicStiffness_);
  }
  return accepted;
}

}  // namespace beamsolid
