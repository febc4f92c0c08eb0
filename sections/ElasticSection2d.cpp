#include "sections/ElasticSection2d.h"

#include "core/CommandArgs.h"

namespace beamsolid {

ElasticSection2d::ElasticSection2d(int tag, const Properties& p) : SectionForceDeformation2d(tag), properties_(p) {
  codes_ = {SectionCode::P, SectionCode::Mz};
  if (p.G > 0.0) codes_.push_back(SectionCode::Vy);
  const int n = order();
  stiffness_ = Matrix::Zero(n, n);
  stiffness_(0, 0) = p.E * p.A;
  stiffness_(1, 1) = p.E * p.Iz;
  if (n == 3) stiffness_(2, 2) = p.alphaY * p.G * p.A;
  deformation_ = force_ = committedDeformation_ = Vector::Zero(n);
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
