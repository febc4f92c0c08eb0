#include "elements/ElasticBeam3d.h"

#include "elements/BeamFixedEndForces.h"
#include "elements/BeamRelease.h"
#include "elements/ElasticBeam2d.h"
#include "elements/BeamMass.h"

#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "sections/ElasticSection3d.h"

namespace beamsolid {

ElasticBeam3d::ElasticBeam3d(int tag, int nodeI, int nodeJ, const Properties& properties,
                             std::unique_ptr<CrdTransf> transf)
    : Element(tag, {nodeI, nodeJ}), properties_(properties), transf_(std::move(transf)) {}

void ElasticBeam3d::setDomain(Domain&) {
  for (const Node* n : nodes())
    if (n->ndf() != 6)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs, the 3D elasticBeamColumn needs 6 (create its nodes after "
                          "model('basic', '-ndm', 3, '-ndf', 6))");
  try {
    transf_->initialize(*nodes()[0], *nodes()[1]);
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
  length_ = transf_->initialLength();

  const auto& p = properties_;
  const double L = length_;
  kb_.setZero();
  kb_(0, 0) = p.E * p.A / L;
  // Shear flexibility phi = 12 EI / (G Av L^2): bending about z shears along y (Avy), about y along z (Avz).
  const double phiY = p.Avy > 0.0 ? 12.0 * p.E * p.Iz / (p.G * p.Avy * L * L) : 0.0;
  const double phiZ = p.Avz > 0.0 ? 12.0 * p.E * p.Iy / (p.G * p.Avz * L * L) : 0.0;
  kb_(1, 1) = kb_(2, 2) = (4.0 + phiY) / (1.0 + phiY) * p.E * p.Iz / L;
  kb_(1, 2) = kb_(2, 1) = (2.0 - phiY) / (1.0 + phiY) * p.E * p.Iz / L;
  kb_(3, 3) = kb_(4, 4) = (4.0 + phiZ) / (1.0 + phiZ) * p.E * p.Iy / L;
  kb_(3, 4) = kb_(4, 3) = (2.0 - phiZ) / (1.0 + phiZ) * p.E * p.Iy / L;
  kb_(5, 5) = p.G * p.J / L;
  BeamRelease::condense(kb_, 1, 2, p.releaseZ);
  BeamRelease::condense(kb_, 3, 4, p.releaseY);

  initialStiff_ = transf_->initialGlobalStiffMatrix(kb_);
  formMass();
}

void ElasticBeam3d::formMass() {
  const double m = properties_.massPerLength;
  // Torsional inertia per length m*J/A: exact for circular sections (J = Ip).
  // The mass sits on the flexible length between offset ends, rotated only.
  const auto& p = properties_;
  const double torsion = p.torsionalInertia ? m * p.J / p.A : 0.0;
  const double L2 = length_ * length_;
  const double phiY = p.Avy > 0.0 ? 12.0 * p.E * p.Iz / (p.G * p.Avy * L2) : 0.0;
  const double phiZ = p.Avz > 0.0 ? 12.0 * p.E * p.Iy / (p.G * p.Avz * L2) : 0.0;
  const bool timoshenko = p.Avy > 0.0;
  mass_ = beamMass(m, length_, p.consistentMass, torsion, transf_->localAxes(), phiY, phiZ,
                   timoshenko ? p.Iz / p.A : 0.0, timoshenko ? p.Iy / p.A : 0.0);
}

void ElasticBeam3d::update() { transf_->update(); }

ElasticBeam3d::Vector6 ElasticBeam3d::basicForce() const {
  return kb_ * transf_->basicTrialDisp() + q0_;
}

ElasticBeam3d::Vector12 ElasticBeam3d::localForce() const {
  // The basic system's equilibrium, without any geometric term.
  return CrdTransf::basicToLocal(basicForce(), p0_, length_);
}

MatrixView ElasticBeam3d::tangentStiff() {
  stiff_ = transf_->globalStiffMatrix(kb_, basicForce());
  return viewOf(stiff_);
}

MatrixView ElasticBeam3d::initialStiff() { return viewOf(initialStiff_); }

VectorView ElasticBeam3d::resistingForce() {
  force_ = transf_->globalResistingForce(basicForce(), p0_);
  return viewOf(force_);
}

MatrixView ElasticBeam3d::massMatrix() { return viewOf(mass_); }

void ElasticBeam3d::commitState() { transf_->commitState(); }
void ElasticBeam3d::revertToLastCommit() { transf_->revertToLastCommit(); }
void ElasticBeam3d::revertToStart() { transf_->revertToStart(); }

void ElasticBeam3d::zeroLoad() {
  q0_.setZero();
  p0_.setZero();
}

void ElasticBeam3d::addPlaneLoads(const BeamFixedEndForces& xy, const BeamFixedEndForces& xz) {
  p0_[0] += xy.axialReactionI + xz.axialReactionI;
  q0_[0] += xy.basicAxial + xz.basicAxial;
  p0_[1] += xy.shearI;
  p0_[7] += xy.shearJ;
  double mzi = xy.momentI, mzj = xy.momentJ, myi = xz.momentI, myj = xz.momentJ;
  BeamRelease::carryOver(mzi, mzj, properties_.releaseZ);
  BeamRelease::carryOver(myi, myj, properties_.releaseY);
  q0_[1] += mzi;
  q0_[2] += mzj;
  p0_[2] += xz.shearI;
  p0_[8] += xz.shearJ;
  // theta_y = -w' flips the x-z plane's moments.
  q0_[3] -= myi;
  q0_[4] -= myj;
}

bool ElasticBeam3d::acceptsLoad(ElementLoad::Type type) const {
  return type == ElementLoad::Type::BeamUniform || type == ElementLoad::Type::BeamPoint;
}

void ElasticBeam3d::addLoad(const ElementLoad& load, double factor) {
  const std::vector<double>& v = load.values;
  const double L = length_;
  switch (load.type) {
    case ElementLoad::Type::BeamUniform: {
      if (v.size() < 2 || v.size() > 3)
        throw OpenSeesError(context() + ": -beamUniform needs Wy, Wz and optionally Wx, got " +
                            std::to_string(v.size()) + " value(s)");
      const double wx = v.size() > 2 ? factor * v[2] : 0.0;
      addPlaneLoads(BeamFixedEndForces::uniform(factor * v[0], wx, L),
                    BeamFixedEndForces::uniform(factor * v[1], 0.0, L));
      return;
    }
    case ElementLoad::Type::BeamPoint: {
      if (v.size() < 3 || v.size() > 4)
        throw OpenSeesError(context() + ": -beamPoint needs Py, Pz, xL and optionally Px, got " +
                            std::to_string(v.size()) + " value(s)");
      const double xL = v[2];
      if (!(xL >= 0.0 && xL <= 1.0))
        throw OpenSeesError(context() + ": -beamPoint xL must lie in [0, 1] (a fraction of the length), got " +
                            std::to_string(xL));
      const double px = v.size() > 3 ? factor * v[3] : 0.0;
      addPlaneLoads(BeamFixedEndForces::point(factor * v[0], px, xL, L),
                    BeamFixedEndForces::point(factor * v[1], 0.0, xL, L));
      return;
    }
    default:
      Element::addLoad(load, factor);
  }
}

namespace {

std::vector<std::string> endNames(const char* const (&names)[6]) {
  std::vector<std::string> out;
  for (int end = 1; end <= 2; ++end)
    for (const char* n : names) out.push_back(std::string(n) + "_" + std::to_string(end));
  return out;
}

}  // namespace

Response ElasticBeam3d::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "force" || what == "forces" || what == "globalForce" || what == "globalForces") {
    static const char* const names[6] = {"Px", "Py", "Pz", "Mx", "My", "Mz"};
    return Response::named(endNames(names),
                           [this] { return Vector(transf_->globalResistingForce(basicForce(), p0_)); });
  }
  if (what == "localForce" || what == "localForces") {
    static const char* const names[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
    return Response::named(endNames(names), [this] { return Vector(localForce()); });
  }
  if (what == "basicForce" || what == "basicForces")
    return Response::named({"N", "Mz_1", "Mz_2", "My_1", "My_2", "T"}, [this] { return Vector(basicForce()); });
  if (what == "basicDeformation" || what == "basicDeformations" || what == "deformation" ||
      what == "deformations")
    return Response::named({"eps", "theta11", "theta12", "theta21", "theta22", "phi"},
                           [this] { return Vector(transf_->basicTrialDisp()); });
  if (what == "basicStiffness") {
    // The 6x6 basic stiffness, row by row (OpenSees' layout).
    return {Response::numberedNames("kb", 36), [this] {
              const Matrix6 rowMajor = kb_.transpose();
              return Vector(Eigen::Map<const Vector>(rowMajor.data(), 36));
            }};
  }
  // Local axes in global coordinates, as OpenSees reports them.
  for (int axis = 0; axis < 3; ++axis) {
    const std::string name(1, "xyz"[axis]);
    if (what == name + "axis" || what == name + "local")
      return {{name + "_X", name + "_Y", name + "_Z"},
              [this, axis] { return Vector(transf_->localAxes().row(axis).transpose()); }};
  }
  return {};
}

void ElasticBeam3d::print(std::ostream& os) const {
  const auto& p = properties_;
  os << "ElasticBeam3d " << tag() << " (elasticBeamColumn): nodes " << nodeTags()[0] << ' ' << nodeTags()[1]
     << ", A " << p.A << ", E " << p.E << ", G " << p.G << ", J " << p.J << ", Iy " << p.Iy << ", Iz " << p.Iz;
  if (p.massPerLength != 0.0)
    os << ", mass/length " << p.massPerLength << (p.consistentMass ? " (consistent)" : " (lumped)");
  if (p.releaseZ) os << ", releasez " << p.releaseZ;
  if (p.releaseY) os << ", releasey " << p.releaseY;
  os << ", geomTransf " << transf_->className() << ' ' << transf_->tag();
  if (length_ > 0.0) os << ", L " << length_;
  os << '\n';
}

void ElasticBeam3d::printJSON(std::ostream& os) const {
  const auto& p = properties_;
  const auto precision = os.precision(12);
  os << "{\"name\": " << tag() << ", \"type\": \"ElasticBeam3d\", \"nodes\": [" << nodeTags()[0] << ", "
     << nodeTags()[1] << "], \"E\": " << p.E << ", \"G\": " << p.G << ", \"A\": " << p.A << ", \"Jx\": " << p.J
     << ", \"Iy\": " << p.Iy << ", \"Iz\": " << p.Iz << ", \"massperlength\": " << p.massPerLength
     << ", \"cMass\": " << (p.consistentMass ? "true" : "false") << ", \"crdTransformation\": \""
     << transf_->tag() << "\"}";
  os.precision(precision);
}

namespace {

std::unique_ptr<Element> buildElasticBeam3d(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element elasticBeamColumn " + std::to_string(tag));
  const int nodeI = args.nextInt("iNode");
  const int nodeJ = args.nextInt("jNode");
  // One command for both spaces, as in OpenSees: the model says which.
  if (domain.spaceDim() == 2) return ElasticBeam2d::build(args, domain, tag, nodeI, nodeJ);
  if (domain.spaceDim() != 3) args.fail("elasticBeamColumn needs a 2D or 3D model (-ndm 2 or 3)");

  // The number of numbers up to the first option tells the form apart.
  std::size_t numbers = 0;
  while (args.position() + numbers < args.size() &&
         !std::holds_alternative<std::string>(args.at(args.position() + numbers)))
    ++numbers;
  if (numbers == 4)
    args.fail("the 2D form (A, E, Iz, transfTag) needs a 2D model (-ndm 2); in 3D give "
              "A, E, G, J, Iy, Iz, transfTag");
  if (numbers != 7 && numbers != 2)
    args.fail("expected A, E, G, J, Iy, Iz, transfTag (7 numbers) or secTag, transfTag (2) after the nodes, got " +
              std::to_string(numbers));

  ElasticBeam3d::Properties p;
  if (numbers == 2) {
    // The section form: E, A, Iz, Iy, G, J of an Elastic section.
    const int secTag = args.nextInt("secTag");
    const BeamSection& section = domain.sections.get(secTag, args.context());
    const auto* elastic = dynamic_cast<const ElasticSection3d*>(&section);
    if (!elastic)
      args.fail("section " + std::to_string(secTag) + " is a " + (section.ndm() == 3 ? "" : "2D ") +
                section.className() + " section; the 3D elasticBeamColumn takes an Elastic section (E, A, Iz, Iy, "
                "G, J) made in a 3D model");
    const ElasticSection3d::Properties& s = elastic->properties();
    p.E = s.E;
    p.A = s.A;
    p.Iz = s.Iz;
    p.Iy = s.Iy;
    p.G = s.G;
    p.J = s.J;
  } else {
    struct Positive {
      double* value;
      const char* name;
    };
    for (const Positive& item : {Positive{&p.A, "A"}, Positive{&p.E, "E"}, Positive{&p.G, "G"},
                                 Positive{&p.J, "J"}, Positive{&p.Iy, "Iy"}, Positive{&p.Iz, "Iz"}}) {
      const std::size_t at = args.position();
      *item.value = args.nextDouble(item.name);
      if (!(*item.value > 0.0)) args.failAt(at, item.name, "a positive number");
    }
  }
  const int transfTag = args.nextInt("transfTag");

  while (!args.done()) {
    if (args.nextFlag("-mass")) {
      const std::size_t at = args.position();
      p.massPerLength = args.nextDouble("massPerLength");
      if (p.massPerLength < 0.0) args.failAt(at, "massPerLength", "a number >= 0");
    } else if (args.nextFlag("-cMass")) {
      p.consistentMass = true;
    } else if (args.nextFlag("-lMass")) {
      // Lumped is the default; OpenSees accepts the flag and '-cMass' wins whatever the order.
    } else if (args.nextIsString() && (*args.peekString() == "-releasez" || *args.peekString() == "-releasey")) {
      const bool aboutZ = args.nextString("option") == "-releasez";
      const std::size_t at = args.position();
      int& code = aboutZ ? p.releaseZ : p.releaseY;
      code = args.nextInt("releaseCode");
      if (code < 0 || code > 3) args.failAt(at, "releaseCode", "0, 1 (I), 2 (J) or 3 (both)");
    } else if (args.nextIsString()) {
      args.fail("unknown option '" + *args.peekString() +
                "' (expected '-mass', '-cMass', '-lMass', '-releasez' or '-releasey')");
    } else {
      args.expectEnd();
    }
  }

  auto transf = domain.geomTransfs.get(transfTag, args.context()).clone();
  return std::make_unique<ElasticBeam3d>(tag, nodeI, nodeJ, p, std::move(transf));
}

void registerElasticBeam3d(Registry& r) { r.elements.add("elasticBeamColumn", &buildElasticBeam3d); }

}  // namespace

BEAMSOLID_REGISTER(registerElasticBeam3d);

}  // namespace beamsolid
