#include "materials/uniaxial/ParallelMaterial.h"

#include <charconv>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

ParallelMaterial::ParallelMaterial(int tag, const std::vector<const UniaxialMaterial*>& materials,
                                   std::vector<double> factors)
    : UniaxialMaterial(tag), factors_(std::move(factors)) {
  for (const UniaxialMaterial* m : materials) materials_.emplace_back(*m);
  factors_.resize(materials_.size(), 1.0);
}

std::unique_ptr<UniaxialMaterial> ParallelMaterial::clone() const {
  return std::make_unique<ParallelMaterial>(*this);
}

void ParallelMaterial::setTrialStrain(double strain, double strainRate) {
  strain_ = strain;
  for (OwnedMaterial& m : materials_) m->setTrialStrain(strain, strainRate);
}

double ParallelMaterial::stress() const {
  double s = 0.0;
  for (std::size_t i = 0; i < materials_.size(); ++i) s += factors_[i] * materials_[i]->stress();
  return s;
}

double ParallelMaterial::tangent() const {
  double k = 0.0;
  for (std::size_t i = 0; i < materials_.size(); ++i) k += factors_[i] * materials_[i]->tangent();
  return k;
}

double ParallelMaterial::initialTangent() const {
  double k = 0.0;
  for (std::size_t i = 0; i < materials_.size(); ++i) k += factors_[i] * materials_[i]->initialTangent();
  return k;
}

void ParallelMaterial::commitState() {
  committedStrain_ = strain_;
  for (OwnedMaterial& m : materials_) m->commitState();
}

void ParallelMaterial::revertToLastCommit() {
  strain_ = committedStrain_;
  for (OwnedMaterial& m : materials_) m->revertToLastCommit();
}

void ParallelMaterial::revertToStart() {
  strain_ = committedStrain_ = 0.0;
  for (OwnedMaterial& m : materials_) m->revertToStart();
}

Response ParallelMaterial::setResponse(const std::vector<std::string>& args) {
  if (args.size() >= 2 && args[0] == "material") {
    int k = 0;
    const std::string& s = args[1];
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), k);
    if (ec != std::errc() || ptr != s.data() + s.size() || k < 1 || k > static_cast<int>(materials_.size()))
      return {};
    return materials_[k - 1]->setResponse(std::vector<std::string>(args.begin() + 2, args.end()));
  }
  return UniaxialMaterial::setResponse(args);
}

bool ParallelMaterial::setParameter(const std::vector<std::string>& args, double value) {
  bool accepted = false;
  for (OwnedMaterial& m : materials_) accepted = m->setParameter(args, value) || accepted;
  return accepted;
}

void ParallelMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Parallel materials";
  for (std::size_t i = 0; i < materials_.size(); ++i)
    os << " (" << materials_[i]->tag() << ", factor " << factors_[i] << ')';
  os << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildParallel(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Parallel " + std::to_string(tag));
  const std::vector<int> tags = args.nextInts("matTags", 1);
  std::vector<double> factors;
  if (!args.done()) {
    // OpenSees documents '-factors' and also reads '-factor'.
    if (!args.nextFlag("-factors") && !args.nextFlag("-factor"))
      args.failAt(args.position(), "option", "'-factors' followed by one factor per material");
    const std::size_t at = args.position();
    factors = args.nextDoubles("factors", 1);
    if (factors.size() != tags.size())
      args.failAt(at, "factors",
                  std::to_string(tags.size()) + " factors (one per material), got " + std::to_string(factors.size()));
  }
  args.expectEnd();
  std::vector<const UniaxialMaterial*> materials;
  for (int t : tags) materials.push_back(&domain.uniaxialMaterials.get(t, args.context()));
  return std::make_unique<ParallelMaterial>(tag, materials, std::move(factors));
}

void registerParallel(Registry& r) { r.uniaxialMaterials.add("Parallel", &buildParallel); }

}  // namespace

BEAMSOLID_REGISTER(registerParallel);

}  // namespace beamsolid
