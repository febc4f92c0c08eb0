#include "materials/uniaxial/SeriesMaterial.h"

#include <charconv>
#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

SeriesMaterial::SeriesMaterial(int tag, const std::vector<const UniaxialMaterial*>& materials, int maxIter,
                               double tol)
    : UniaxialMaterial(tag), maxIter_(maxIter), tol_(tol) {
  for (const UniaxialMaterial* m : materials) materials_.emplace_back(*m);
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> SeriesMaterial::clone() const { return std::make_unique<SeriesMaterial>(*this); }

double SeriesMaterial::initialTangent() const {
  double f = 0.0;
  for (const OwnedMaterial& m : materials_) f += 1.0 / m->initialTangent();
  return 1.0 / f;
}

void SeriesMaterial::setTrialStrain(double strain, double) {
  // Incremental from the last trial, like a force-based element's state
  // determination: the misfit a pass leaves is corrected by the next one.
  State& t = trial_;
  const double increment = strain - t.strain;
  t.strain = strain;
  t.stress += increment / t.flexibility;
  for (int pass = 0; pass < maxIter_; ++pass) {
    for (std::size_t i = 0; i < materials_.size(); ++i) {
      UniaxialMaterial& m = *materials_[i];
      t.strains[i] += (t.stress - m.stress()) / m.tangent();
      m.setTrialStrain(t.strains[i]);
    }
    // Strain misfit: the strain each material lacks to carry the stress.
    double misfit = 0.0, flexibility = 0.0;
    for (const OwnedMaterial& m : materials_) {
      misfit += (t.stress - m->stress()) / m->tangent();
      flexibility += 1.0 / m->tangent();
    }
    t.flexibility = flexibility;
    t.stress -= misfit / flexibility;
    if (std::abs(misfit) < tol_) break;
  }
}

void SeriesMaterial::commitState() {
  committed_ = trial_;
  for (OwnedMaterial& m : materials_) m->commitState();
}

void SeriesMaterial::revertToLastCommit() {
  trial_ = committed_;
  for (OwnedMaterial& m : materials_) m->revertToLastCommit();
}

void SeriesMaterial::revertToStart() {
  for (OwnedMaterial& m : materials_) m->revertToStart();
  committed_ = State{};
  committed_.strains.assign(materials_.size(), 0.0);
  committed_.flexibility = 1.0 / initialTangent();
  trial_ = committed_;
}

Response SeriesMaterial::setResponse(const std::vector<std::string>& args) {
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

void SeriesMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Series materials";
  for (const OwnedMaterial& m : materials_) os << ' ' << m->tag();
  os << " maxIter " << maxIter_ << " tol " << tol_ << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildSeries(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Series " + std::to_string(tag));
  const std::vector<int> tags = args.nextInts("matTags", 1);
  int maxIter = 1;
  double tol = 1e-10;
  if (!args.done()) {
    if (!args.nextFlag("-iter")) args.failAt(args.position(), "option", "'-iter' followed by maxIter and tol");
    maxIter = args.nextInt("maxIter");
    if (!args.done()) tol = args.nextDouble("tol");
  }
  args.expectEnd();
  if (maxIter < 1) args.fail("maxIter must be at least 1, got " + std::to_string(maxIter));
  if (!(tol > 0.0)) args.fail("tol must be positive, got " + std::to_string(tol));
  std::vector<const UniaxialMaterial*> materials;
  for (int t : tags) materials.push_back(&domain.uniaxialMaterials.get(t, args.context()));
  for (const UniaxialMaterial* m : materials)
    if (!(m->initialTangent() != 0.0))
      args.fail("material " + std::to_string(m->tag()) + " has a zero initial tangent (infinite flexibility)");
  return std::make_unique<SeriesMaterial>(tag, materials, maxIter, tol);
}

void registerSeries(Registry& r) { r.uniaxialMaterials.add("Series", &buildSeries); }

}  // namespace

BEAMSOLID_REGISTER(registerSeries);

}  // namespace beamsolid
