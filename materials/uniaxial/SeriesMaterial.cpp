#include "materials/uniaxial/SeriesMaterial.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <numeric>

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

namespace {
// A component's tangent, kept off zero (a residual plateau) so that its
// flexibility stays finite; OpenSeesPy reports the same 1e-12 floor.
double tangentOf(const UniaxialMaterial& m) {
  const double e = m.tangent();
  return std::abs(e) < 1e-12 ? 1e-12 : e;
}
}  // namespace

void SeriesMaterial::setTrialStrain(double strain, double) {
  if (maxIter_ == 1) {
    onePass(strain);
    return;
  }
  const State start = trial_;
  if (solveSeries(strain)) return;
  // No converged series state on hardening branches (a component softens):
  // repeated one-pass updates from where the trial started, as OpenSees.
  trial_ = start;
  for (std::size_t i = 0; i < materials_.size(); ++i) materials_[i]->setTrialStrain(trial_.strains[i]);
  for (int pass = 0; pass < maxIter_; ++pass)
    if (std::abs(onePass(strain)) < tol_) break;
}

double SeriesMaterial::onePass(double strain) {
  // Incremental from the last trial like a force-based element's state
  // determination: the misfit it leaves is corrected by the next pass or
  // trial (OpenSees' default; checked against OpenSeesPy).
  State& t = trial_;
  const double increment = strain - t.strain;
  t.strain = strain;
  t.stress += increment / t.flexibility;
  for (std::size_t i = 0; i < materials_.size(); ++i) {
    UniaxialMaterial& m = *materials_[i];
    t.strains[i] += (t.stress - m.stress()) / tangentOf(m);
    m.setTrialStrain(t.strains[i]);
  }
  double misfit = 0.0, flexibility = 0.0;
  for (const OwnedMaterial& m : materials_) {
    misfit += (t.stress - m->stress()) / tangentOf(*m);
    flexibility += 1.0 / tangentOf(*m);
  }
  t.flexibility = flexibility;
  t.stress -= misfit / flexibility;
  return misfit;
}

double SeriesMaterial::strainAtStress(std::size_t i, double stress) {
  // Where sigma_i(eps) increases from the committed state (hardening or
  // perfectly plastic components): Newton from the last trial, kept inside a
  // bracket [low, high] that bisection falls back on whenever a Newton step
  // leaves it, and a walk outward while there is no bracket yet (a plateau).
  // On a softening branch (negative tangent) the plain Newton step.
  UniaxialMaterial& m = *materials_[i];
  const double scale = std::max(std::abs(stress), std::abs(m.initialTangent()) * 1e-12) + 1e-300;
  double e = trial_.strains[i];
  m.setTrialStrain(e);
  double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
  double step = std::abs(stress - m.stress()) / std::abs(m.initialTangent()) + 1e-12;
  int walks = 0;
  for (int k = 0; k < 200; ++k) {
    const double f = m.stress() - stress;
    if (std::abs(f) <= 1e-14 * scale) break;
    const double tangent = m.tangent();
    double next;
    if (tangent < 0.0) {
      next = e - f / tangent;
    } else {
      if (f < 0.0) low = std::max(low, e);
      else high = std::min(high, e);
      next = tangent > 0.0 ? e - f / tangent : std::numeric_limits<double>::quiet_NaN();
      if (!(next > low && next < high)) {
        if (std::isfinite(low) && std::isfinite(high)) next = 0.5 * (low + high);
        else {
          // No bracket yet: walk outward, doubling the step (a plateau below
          // the stress asked for has no answer: give up after 40 doublings).
          if (++walks > 40) break;
          next = f < 0.0 ? e + step : e - step;
          step *= 2.0;
        }
      }
    }
    if (next == e || !std::isfinite(next)) break;
    e = next;
    m.setTrialStrain(e);
  }
  trial_.strains[i] = e;
  return e;
}

bool SeriesMaterial::solveSeries(double strain) {
  // The stress every material carries such that their strains add up to the
  // given one: Newton on sigma with the series flexibility, each material's
  // strain found at that stress (strainAtStress); at most maxIter passes,
  // done when the strain misfit is below tol.
  State& t = trial_;
  t.strain = strain;
  double sigma = t.stress + (strain - std::accumulate(t.strains.begin(), t.strains.end(), 0.0)) / t.flexibility;
  double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
  for (int pass = 0; pass < maxIter_; ++pass) {
    double total = 0.0, flexibility = 0.0;
    for (std::size_t i = 0; i < materials_.size(); ++i) {
      total += strainAtStress(i, sigma);
      flexibility += 1.0 / tangentOf(*materials_[i]);
    }
    t.stress = sigma;
    t.flexibility = flexibility;
    const double misfit = strain - total;
    if (std::abs(misfit) < tol_) return true;
    double next = flexibility != 0.0 ? sigma + misfit / flexibility : std::numeric_limits<double>::quiet_NaN();
    if (flexibility > 0.0) {
      // The strains grow with the stress: keep sigma inside the bracket seen so far.
      if (misfit > 0.0) low = std::max(low, sigma);
      else high = std::min(high, sigma);
      if (!(next > low && next < high) && std::isfinite(low) && std::isfinite(high)) next = 0.5 * (low + high);
    }
    if (!std::isfinite(next) || next == sigma) return false;
    sigma = next;
  }
  return false;
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
