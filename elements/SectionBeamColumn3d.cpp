#include "elements/SectionBeamColumn3d.h"

#include "elements/BeamMass.h"
#include "elements/BeamColumnCommand.h"

#include <variant>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

SectionBeamColumn3d::SectionBeamColumn3d(int tag, Definition&& d)
    : Element(tag, {d.nodeI, d.nodeJ}),
      transf_(std::move(d.transf)),
      integration_(std::move(d.integration)),
      sections_(std::move(d.sections)),
      options_(d.options) {}

void SectionBeamColumn3d::setDomain(Domain&) {
  for (const Node* n : nodes())
    if (n->ndf() != 6)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs, the 3D " + className() + " needs 6 (create its nodes after "
                          "model('basic', '-ndm', 3, '-ndf', 6))");
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
  formMass();
  initializeState();
  initialStiff_ = transf_->initialGlobalStiffMatrix(initialBasicStiffness_);
}

void SectionBeamColumn3d::formMass() {
  const double m = options_.massPerLength;
  // No torsional inertia: the section does not say what its polar moment of mass is.
  // The mass sits on the flexible length between offset ends, rotated only.
  mass_ = beamMass(m, length_, options_.consistentMass, 0.0, transf_->localAxes());
}

MatrixView SectionBeamColumn3d::tangentStiff() {
  const Matrix6& kb = basicStiffness();
  stiff_ = transf_->globalStiffMatrix(kb, basicForce());
  return viewOf(stiff_);
}

MatrixView SectionBeamColumn3d::initialStiff() { return viewOf(initialStiff_); }

VectorView SectionBeamColumn3d::resistingForce() {
  force_ = transf_->globalResistingForce(basicForce(), p0_);
  return viewOf(force_);
}

MatrixView SectionBeamColumn3d::massMatrix() { return viewOf(mass_); }

SectionBeamColumn3d::Vector6 SectionBeamColumn3d::plasticDeformation() {
  return basicDeformation() - initialBasicStiffness_.ldlt().solve(basicForce());
}

bool SectionBeamColumn3d::acceptsLoad(ElementLoad::Type type) const {
  return type == ElementLoad::Type::BeamUniform || type == ElementLoad::Type::BeamPoint;
}

SectionBeamColumn3d::BeamLoad SectionBeamColumn3d::readLoad(const ElementLoad& load, double factor) const {
  const std::vector<double>& v = load.values;
  BeamLoad out;
  switch (load.type) {
    case ElementLoad::Type::BeamUniform:
      if (v.size() < 2 || v.size() > 3)
        throw OpenSeesError(context() + ": -beamUniform needs Wy, Wz and optionally Wx, got " +
                            std::to_string(v.size()) + " value(s)");
      out.uniform = true;
      out.wy = factor * v[0];
      out.wz = factor * v[1];
      out.wx = v.size() > 2 ? factor * v[2] : 0.0;
      return out;
    case ElementLoad::Type::BeamPoint:
      if (v.size() < 3 || v.size() > 4)
        throw OpenSeesError(context() + ": -beamPoint needs Py, Pz, xL and optionally Px, got " +
                            std::to_string(v.size()) + " value(s)");
      if (!(v[2] >= 0.0 && v[2] <= 1.0))
        throw OpenSeesError(context() + ": -beamPoint xL must lie in [0, 1] (a fraction of the length), got " +
                            std::to_string(v[2]));
      out.uniform = false;
      out.py = factor * v[0];
      out.pz = factor * v[1];
      out.a = v[2] * length_;
      out.px = v.size() > 3 ? factor * v[3] : 0.0;
      return out;
    default:
      throw OpenSeesError(context() + ": does not accept element load " + ElementLoad::typeName(load.type));
  }
}

void SectionBeamColumn3d::addLoadReactions(const BeamLoad& load) {
  const double L = length_;
  if (load.uniform) {
    // Axial all at I, transverse half at each end.
    p0_[0] -= load.wx * L;
    p0_[1] -= 0.5 * load.wy * L;
    p0_[7] -= 0.5 * load.wy * L;
    p0_[2] -= 0.5 * load.wz * L;
    p0_[8] -= 0.5 * load.wz * L;
  } else {
    const double a = load.a, b = L - load.a;
    p0_[0] -= load.px;
    p0_[1] -= load.py * b / L;
    p0_[7] -= load.py * a / L;
    p0_[2] -= load.pz * b / L;
    p0_[8] -= load.pz * a / L;
  }
}

namespace {

std::vector<std::string> endNames(const char* const (&names)[6]) {
  std::vector<std::string> out;
  for (int end = 1; end <= 2; ++end)
    for (const char* n : names) out.push_back(std::string(n) + "_" + std::to_string(end));
  return out;
}

std::vector<std::string> basicNames() { return {"N", "Mz_1", "Mz_2", "My_1", "My_2", "T"}; }
std::vector<std::string> deformationNames() {
  return {"eps", "thetaZ_1", "thetaZ_2", "thetaY_1", "thetaY_2", "thetaX"};
}

}  // namespace

Response SectionBeamColumn3d::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "force" || what == "forces" || what == "globalForce" || what == "globalForces") {
    static const char* const names[6] = {"Px", "Py", "Pz", "Mx", "My", "Mz"};
    return Response::named(endNames(names), [this] { return Vector(resistingForce()); });
  }
  if (what == "localForce" || what == "localForces") {
    static const char* const names[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
    return Response::named(endNames(names),
                           [this] { return Vector(transf_->localResistingForce(basicForce(), p0_)); });
  }
  if (what == "basicForce" || what == "basicForces")
    return Response::named(basicNames(), [this] { return Vector(basicForce()); });
  if (what == "basicDeformation" || what == "basicDeformations" || what == "deformation" ||
      what == "deformations")
    return Response::named(deformationNames(), [this] { return Vector(basicDeformation()); });
  if (what == "plasticDeformation" || what == "plasticDeformations")
    return Response::named(deformationNames(), [this] { return Vector(plasticDeformation()); });
  if (what == "basicStiffness") {
    std::vector<std::string> names;
    for (const auto& row : basicNames())
      for (const auto& col : deformationNames()) names.push_back("d" + row + "_d" + col);
    return Response::named(std::move(names), [this] {
      const Matrix6& kb = basicStiffness();
      Vector out(36);
      for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) out[6 * r + c] = kb(r, c);
      return out;
    });
  }
  if (what == "integrationPoints")
    return Response::named(Response::numberedNames("x", numSections()), [this] {
      Vector out(numSections());
      for (int i = 0; i < numSections(); ++i) out[i] = xi_[i] * length_;
      return out;
    });
  if (what == "integrationWeights")
    return Response::named(Response::numberedNames("w", numSections()), [this] {
      Vector out(numSections());
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

void SectionBeamColumn3d::print(std::ostream& os) const {
  os << className() << ' ' << tag() << ": nodes " << nodeTags()[0] << ' ' << nodeTags()[1] << ", "
     << integration_->className() << " integration with " << numSections() << " sections (";
  for (int i = 0; i < numSections(); ++i) os << (i ? " " : "") << sections_[i]->className() << ' ' << sections_[i]->tag();
  os << "), geomTransf " << transf_->className() << ' ' << transf_->tag();
  if (options_.massPerLength != 0.0)
    os << ", mass/length " << options_.massPerLength << (options_.consistentMass ? " (consistent)" : " (lumped)");
  if (length_ > 0.0) os << ", L " << length_;
  os << '\n';
}

void SectionBeamColumn3d::printJSON(std::ostream& os) const {
  const auto precision = os.precision(12);
  os << "{\"name\": " << tag() << ", \"type\": \"" << className() << "\", \"nodes\": [" << nodeTags()[0] << ", "
     << nodeTags()[1] << "], \"sections\": [";
  for (int i = 0; i < numSections(); ++i) os << (i ? ", " : "") << sections_[i]->tag();
  os << "], \"integration\": \"" << integration_->className() << "\", \"massperlength\": " << options_.massPerLength
     << ", \"crdTransformation\": \"" << transf_->tag() << "\"}";
  os.precision(precision);
}

SectionBeamColumn3d::Definition SectionBeamColumn3d::parse(CommandArgs& args, Domain& domain, const std::string& type,
                                                           BeamIntegration::Rule defaultRule, bool forceBased) {
  BeamColumnCommand c = BeamColumnCommand::parse(args, domain, type, defaultRule, forceBased, true);
  Definition d;
  d.tag = c.tag;
  d.nodeI = c.nodeI;
  d.nodeJ = c.nodeJ;
  d.options = c.options;
  d.integration = std::move(c.integration);
  for (int s : d.integration->sectionTags())
    d.sections.push_back(SectionForceDeformation::of(domain.sections.get(s, args.context()), args.context()).clone());
  d.transf = domain.geomTransfs.get(c.transfTag, args.context()).clone();
  return d;
}

}  // namespace beamsolid
