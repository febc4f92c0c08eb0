#include "elements/ElasticBeam2d.h"

#include "elements/BeamRelease.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/BeamMass.h"
#include "sections/ElasticSection2d.h"

namespace beamsolid {

ElasticBeam2d::ElasticBeam2d(int tag, int nodeI, int nodeJ, const Properties& properties,
                             std::unique_ptr<CrdTransf2d> transf)
    : Element(tag, {nodeI, nodeJ}), properties_(properties), transf_(std::move(transf)) {}

void ElasticBeam2d::setDomain(Domain&) {
  for (const Node* n : nodes())
    if (n->ndf() != 3)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs, the 2D elasticBeamColumn needs 3 (create its nodes after "
                          "model('basic', '-ndm', 2, '-ndf', 3))");
  try {
    transf_->initialize(*nodes()[0], *nodes()[1]);
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
  length_ = transf_->initialLength();

  const auto& p = properties_;
  const double L = length_;
  const double k = p.E * p.Iz / L;
  // Shear flexibility phi = 12 EI / (G Av L^2) turns 4, 2 into (4 + phi), (2 - phi) over (1 + phi).
  const double phi = p.Avy > 0.0 ? 12.0 * p.E * p.Iz / (p.G * p.Avy * L * L) : 0.0;
  const double kii = k * (4.0 + phi) / (1.0 + phi), kij = k * (2.0 - phi) / (1.0 + phi);
  kb_.setZero();
  kb_(0, 0) = p.E * p.A / L;
  kb_(1, 1) = kb_(2, 2) = kii;
  kb_(1, 2) = kb_(2, 1) = kij;
  BeamRelease::condense(kb_, 1, 2, p.release);
  initialStiff_ = transf_->initialGlobalStiffMatrix(kb_);

  // The 3D beam's mass restricted to the plane (ux, uy, rz at each end).
  Matrix3 axes = Matrix3::Identity();
  const Eigen::Vector2d x = transf_->axis();
  axes.row(0) << x.x(), x.y(), 0.0;
  axes.row(1) << -x.y(), x.x(), 0.0;
  const CrdTransf::Matrix12 m12 = beamMass(p.massPerLength, L, p.consistentMass, 0.0, axes, phi, 0.0, p.Avy > 0.0 ? p.Iz / p.A : 0.0);
  static constexpr int inPlane[6] = {0, 1, 5, 6, 7, 11};
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) mass_(a, b) = m12(inPlane[a], inPlane[b]);
}

MatrixView ElasticBeam2d::tangentStiff() {
  stiff_ = transf_->globalStiffMatrix(kb_, basicForce());
  return viewOf(stiff_);
}

MatrixView ElasticBeam2d::initialStiff() { return viewOf(initialStiff_); }

VectorView ElasticBeam2d::resistingForce() {
  force_ = transf_->globalResistingForce(basicForce(), p0_);
  return viewOf(force_);
}

MatrixView ElasticBeam2d::massMatrix() { return viewOf(mass_); }

void ElasticBeam2d::zeroLoad() {
  q0_.setZero();
  p0_.setZero();
}

bool ElasticBeam2d::acceptsLoad(ElementLoad::Type type) const {
  return type == ElementLoad::Type::BeamUniform || type == ElementLoad::Type::BeamPoint;
}

void ElasticBeam2d::addFixedEndForces(const BeamFixedEndForces& f) {
  p0_[0] += f.axialReactionI;
  q0_[0] += f.basicAxial;
  p0_[1] += f.shearI;
  p0_[4] += f.shearJ;
  // A released end's fixed-end moment is carried over to the other end
  // (half of it, the carry-over factor) or, with both released, dropped.
  double mi = f.momentI, mj = f.momentJ;
  BeamRelease::carryOver(mi, mj, properties_.release);
  // With a released end the simple-support shears change: (Mi + Mj)/L
  // in basicToLocal accounts for it, since q0 holds the condensed moments.
  q0_[1] += mi;
  q0_[2] += mj;
}

void ElasticBeam2d::addLoad(const ElementLoad& load, double factor) {
  // ElementLoad keeps the 3D layout; in 2D Wz and Pz are zero.
  const std::vector<double>& v = load.values;
  switch (load.type) {
    case ElementLoad::Type::BeamUniform:
      if (v.size() != 3) throw OpenSeesError(context() + ": -beamUniform needs Wy and optionally Wx");
      addFixedEndForces(BeamFixedEndForces::uniform(factor * v[0], factor * v[2], length_));
      return;
    case ElementLoad::Type::BeamPoint:
      if (v.size() != 4) throw OpenSeesError(context() + ": -beamPoint needs Py, xL and optionally Px");
      if (!(v[2] >= 0.0 && v[2] <= 1.0))
        throw OpenSeesError(context() + ": -beamPoint xL must lie in [0, 1] (a fraction of the length), got " +
                            std::to_string(v[2]));
      addFixedEndForces(BeamFixedEndForces::point(factor * v[0], factor * v[3], v[2], length_));
      return;
    default:
      Element::addLoad(load, factor);
  }
}

Response ElasticBeam2d::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "force" || what == "forces" || what == "globalForce" || what == "globalForces")
    return Response::named({"Px_1", "Py_1", "Mz_1", "Px_2", "Py_2", "Mz_2"},
                           [this] { return Vector(transf_->globalResistingForce(basicForce(), p0_)); });
  if (what == "localForce" || what == "localForces")
    return Response::named({"N_1", "Vy_1", "Mz_1", "N_2", "Vy_2", "Mz_2"}, [this] { return Vector(localForce()); });
  if (what == "basicForce" || what == "basicForces")
    return Response::named({"N", "M_1", "M_2"}, [this] { return Vector(basicForce()); });
  if (what == "basicDeformation" || what == "basicDeformations")
    return Response::named({"eps", "theta_1", "theta_2"}, [this] { return Vector(transf_->basicTrialDisp()); });
  if (what == "basicStiffness")
    return {Response::numberedNames("kb", 9), [this] {
              const Matrix3 rowMajor = kb_.transpose();
              return Vector(Eigen::Map<const Vector>(rowMajor.data(), 9));
            }};
  // Local axes in global coordinates: x along the chord, y = Z x x, z = Z.
  for (int axis = 0; axis < 3; ++axis) {
    const std::string name(1, "xyz"[axis]);
    if (what == name + "axis" || what == name + "local")
      return {{name + "_X", name + "_Y", name + "_Z"}, [this, axis] {
                const Eigen::Vector2d x = transf_->axis();
                Vector v = Vector::Zero(3);
                if (axis == 0) v << x.x(), x.y(), 0.0;
                else if (axis == 1) v << -x.y(), x.x(), 0.0;
                else v[2] = 1.0;
                return v;
              }};
  }
  return {};
}

void ElasticBeam2d::print(std::ostream& os) const {
  const auto& p = properties_;
  os << "ElasticBeam2d " << tag() << " (elasticBeamColumn): nodes " << nodeTags()[0] << ' ' << nodeTags()[1]
     << ", A " << p.A << ", E " << p.E << ", Iz " << p.Iz;
  if (p.massPerLength != 0.0)
    os << ", mass/length " << p.massPerLength << (p.consistentMass ? " (consistent)" : " (lumped)");
  if (p.release) os << ", release " << p.release;
  os << ", geomTransf " << transf_->className() << ' ' << transf_->tag();
  if (length_ > 0.0) os << ", L " << length_;
  os << '\n';
}

std::unique_ptr<Element> ElasticBeam2d::build(CommandArgs& args, Domain& domain, int tag, int nodeI, int nodeJ) {
  std::size_t numbers = 0;
  while (args.position() + numbers < args.size() &&
         !std::holds_alternative<std::string>(args.at(args.position() + numbers)))
    ++numbers;
  if (numbers == 7)
    args.fail("the 3D form (A, E, G, J, Iy, Iz, transfTag) needs a 3D model (-ndm 3); in 2D give A, E, Iz, transfTag");
  if (numbers != 4 && numbers != 2)
    args.fail("expected A, E, Iz, transfTag (4 numbers) or secTag, transfTag (2) after the nodes in a 2D model, "
              "got " + std::to_string(numbers));
  Properties p;
  if (numbers == 2) {
    // The section form: E, A, Iz of an Elastic section.
    const int secTag = args.nextInt("secTag");
    const BeamSection& section = domain.sections.get(secTag, args.context());
    const auto* elastic = dynamic_cast<const ElasticSection2d*>(&section);
    if (!elastic)
      args.fail("section " + std::to_string(secTag) + " is a " + (section.ndm() == 2 ? "" : "3D ") +
                section.className() + " section; the 2D elasticBeamColumn takes an Elastic section (E, A, Iz) "
                "made in a 2D model");
    p.E = elastic->properties().E;
    p.A = elastic->properties().A;
    p.Iz = elastic->properties().Iz;
  } else {
    struct Positive {
      double* value;
      const char* name;
    };
    for (const Positive& item : {Positive{&p.A, "A"}, Positive{&p.E, "E"}, Positive{&p.Iz, "Iz"}}) {
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
    } else if (args.nextFlag("-release")) {
      const std::size_t at = args.position();
      p.release = args.nextInt("releaseCode");
      if (p.release < 0 || p.release > 3) args.failAt(at, "releaseCode", "0, 1 (I), 2 (J) or 3 (both)");
    } else if (args.nextIsString()) {
      args.fail("unknown option '" + *args.peekString() + "' (expected '-mass', '-cMass', '-lMass' or '-release')");
    } else {
      args.expectEnd();
    }
  }
  const CrdTransf& definition = domain.geomTransfs.get(transfTag, args.context());
  auto transf = definition.planar();
  if (!transf)
    args.fail("geomTransf " + definition.className() + " " + std::to_string(transfTag) +
              " has no 2D form (use 'Linear', 'PDelta' or 'Corotational')");
  return std::make_unique<ElasticBeam2d>(tag, nodeI, nodeJ, p, std::move(transf));
}

}  // namespace beamsolid
