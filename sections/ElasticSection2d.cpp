#include "sections/ElasticSection2d.h"

#include "core/CommandArgs.h"

namespace beamsolid {

ElasticSection2d::ElasticSection2d(int tag, const Properties& p) : SectionForceDeformation2d(tag), properties_(p) {
  codes_ = {SectionCode::P, SectionCode::Mz};
  if (p.G > 0.0) codes_.push_back(SectionCode::Vy);
  stiffness_ = stiffnessOf(p);
  deformation_ = force_ = committedDeformation_ = Vector::Zero(order());
}

ElasticSection2d::Matrix ElasticSection2d::stiffnessOf(const Properties& p) const {
  const int n = order();
  Matrix k = Matrix::Zero(n, n);
  k(0, 0) = p.E * p.A;
  k(1, 1) = p.E * p.Iz;
  if (n == 3) k(2, 2) = p.alphaY * p.G * p.A;
  return k;
}

int ElasticSection2d::sensitivityParameter(const std::vector<std::string>& args) {
  if (args.empty()) return 0;
  const std::string& n = args[0];
  if (n == "E") return 1;
  if (n == "A") return 2;
  if (n == "Iz" || n == "I") return 3;
  if (order() == 3 && n == "G") return 4;
  if (order() == 3 && n == "alphaY") return 5;
  return 0;
}

bool ElasticSection2d::setParameter(const std::vector<std::string>& args, double value) {
  Properties& p = properties_;
  switch (sensitivityParameter(args)) {
    case 1: p.E = value; break;
    case 2: p.A = value; break;
    case 3: p.Iz = value; break;
    case 4: p.G = value; break;
    case 5: p.alphaY = value; break;
    default: return false;
  }
  stiffness_ = stiffnessOf(p);
  setTrialDeformation(deformation_);
  return true;
}

// d s / d theta = (d k / d theta) e, k = diag(E A, E Iz, alphaY G A).
ElasticSection2d::Vector ElasticSection2d::forceSensitivity(int, int parameterId) {
  const Properties& p = properties_;
  Vector dk = Vector::Zero(order());
  switch (parameterId) {
    case 1: dk[0] = p.A; dk[1] = p.Iz; break;
    case 2:
      dk[0] = p.E;
      if (order() == 3) dk[2] = p.alphaY * p.G;
      break;
    case 3: dk[1] = p.E; break;
    case 4: dk[2] = p.alphaY * p.A; break;
    case 5: dk[2] = p.G * p.A; break;
    default: break;
  }
  return dk.cwiseProduct(deformation_);
}

std::unique_ptr<SectionForceDeformation2d> ElasticSection2d::clone() const {
  return std::make_unique<ElasticSection2d>(*this);
}

void ElasticSection2d::setTrialDeformation(const Vector& e) {
  deformation_ = e;
  force_ = stiffness_.diagonal().cwiseProduct(e);
}

void ElasticSection2d::revertToStart() {
  committedDeformation_.setZero();
  setTrialDeformation(committedDeformation_);
}

void ElasticSection2d::print(std::ostream& os) const {
  const Properties& p = properties_;
  os << "Section " << tag() << " type Elastic (2D) E " << p.E << " A " << p.A << " Iz " << p.Iz;
  if (p.G > 0.0) os << " G " << p.G << " alphaY " << p.alphaY;
  os << '\n';
}

std::unique_ptr<ElasticSection2d> ElasticSection2d::build(CommandArgs& args, int tag) {
  const std::size_t numbers = args.remaining();
  if (numbers != 3 && numbers != 5)
    args.fail("expected E, A, Iz (3 numbers) or E, A, Iz, G, alphaY (5) after the tag in a 2D model, got " +
              std::to_string(numbers) +
              (numbers == 6 || numbers == 8 ? " (the 3D form E, A, Iz, Iy, G, J needs a 3D model, -ndm 3)" : ""));
  Properties p;
  struct Positive {
    double* value;
    const char* name;
  };
  std::vector<Positive> items = {{&p.E, "E"}, {&p.A, "A"}, {&p.Iz, "Iz"}};
  if (numbers == 5) items.insert(items.end(), {{&p.G, "G"}, {&p.alphaY, "alphaY"}});
  for (const Positive& item : items) {
    const std::size_t at = args.position();
    *item.value = args.nextDouble(item.name);
    if (!(*item.value > 0.0)) args.failAt(at, item.name, "a positive number");
  }
  args.expectEnd();
  return std::make_unique<ElasticSection2d>(tag, p);
}

}  // namespace beamsolid
