#include "sections/SectionForceDeformation.h"

#include "core/OpenSeesError.h"
#include "sections/PlateSection.h"

namespace beamsolid {

const SectionForceDeformation& SectionForceDeformation::of(const BeamSection& section, const std::string& context) {
  const auto* s = dynamic_cast<const SectionForceDeformation*>(&section);
  if (!s && dynamic_cast<const PlateSection*>(&section))
    throw OpenSeesError(context + ": " + section.context() + " is a plate section (for shells); a beam needs a beam section");
  if (!s)
    throw OpenSeesError(context + ": " + section.context() + " is a " + std::to_string(section.ndm()) +
                        "D section; a 3D element needs a section made in a 3D model (-ndm 3)");
  return *s;
}

SectionCode SectionForceDeformation::shearCode(int k) const {
  throw OpenSeesError(context() + ": no shear component " + std::to_string(k + 1) + " (the section has " +
                      std::to_string(numShear()) + ")");
}

void SectionForceDeformation::setTrialShear(const ShearVector& gamma) {
  if (gamma.size() != 0)
    throw OpenSeesError(context() + ": shear strains given to a section without shear components");
}

std::vector<SectionCode> SectionForceDeformation::responseCodes() const {
  std::vector<SectionCode> codes{SectionCode::P, SectionCode::Mz, SectionCode::My, SectionCode::T};
  for (int k = 0; k < numShear(); ++k) codes.push_back(shearCode(k));
  return codes;
}

std::vector<int> SectionForceDeformation::responsePositions() const {
  const std::vector<SectionCode> codes = responseCodes();
  std::vector<int> at(codes.size());
  for (std::size_t r = 0; r < codes.size(); ++r) {
    at[r] = index3d(codes[r]);
    for (int k = 0; at[r] < 0 && k < numShear(); ++k)
      if (shearCode(k) == codes[r]) at[r] = 4 + k;
  }
  return at;
}

Vector SectionForceDeformation::responseValues(bool forces) const {
  const std::vector<int> at = responsePositions();
  const Vector4& main = forces ? force() : deformation();
  const ShearVector shear = forces ? shearForce() : shearDeformation();
  Vector out(at.size());
  for (std::size_t r = 0; r < at.size(); ++r) out[r] = at[r] < 4 ? main[at[r]] : shear[at[r] - 4];
  return out;
}

Matrix SectionForceDeformation::responseTangent(bool initial) const {
  const std::vector<int> at = responsePositions();
  const int n = static_cast<int>(at.size());
  const Matrix4& k4 = initial ? initialTangent() : tangent();
  const ShearVector kv = initial ? shearInitialTangent() : shearTangent();
  Matrix out = Matrix::Zero(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      if (at[r] < 4 && at[c] < 4) out(r, c) = k4(at[r], at[c]);
      else if (at[r] == at[c]) out(r, c) = kv[at[r] - 4];
    }
  return out;
}

void SectionForceDeformation::setTrialResponseDeformation(const Vector& e) {
  const std::vector<int> at = responsePositions();
  Vector4 main = deformation();
  ShearVector shear = shearDeformation();
  for (std::size_t r = 0; r < at.size(); ++r) {
    if (at[r] < 4) main[at[r]] = e[Eigen::Index(r)];
    else shear[at[r] - 4] = e[Eigen::Index(r)];
  }
  setTrialDeformation(main);
  setTrialShear(shear);
}

Response SectionForceDeformation::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (numShear() == 0) {
    if (what == "force" || what == "forces")
      return Response::named({"P", "Mz", "My", "T"}, [this] { return Vector(force()); });
    if (what == "deformation" || what == "deformations")
      return Response::named({"eps", "kappaZ", "kappaY", "theta"}, [this] { return Vector(deformation()); });
    if (what == "forceAndDeformation" || what == "forceDeformation")
      return Response::named({"eps", "kappaZ", "kappaY", "theta", "P", "Mz", "My", "T"}, [this] {
        Vector out(8);
        out << deformation(), force();
        return out;
      });
    if (what == "stiffness" || what == "tangent") {
      static const char* const names[4] = {"P", "Mz", "My", "T"};
      static const char* const deformations[4] = {"eps", "kappaZ", "kappaY", "theta"};
      std::vector<std::string> componentNames;
      for (const char* row : names)
        for (const char* col : deformations) componentNames.push_back(std::string("d") + row + "_d" + col);
      return Response::named(std::move(componentNames), [this] {
        Vector out(16);
        const Matrix4& k = tangent();
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c) out[4 * r + c] = k(r, c);
        return out;
      });
    }
    return {};
  }
  // A shear section: every component in responseCodes() order.
  const std::vector<SectionCode> codes = responseCodes();
  const int n = static_cast<int>(codes.size());
  std::vector<std::string> forceNames, deformationNames;
  for (SectionCode c : codes) {
    forceNames.push_back(sectionCodeName(c));
    deformationNames.push_back(sectionDeformationName(c));
  }
  if (what == "force" || what == "forces")
    return Response::named(forceNames, [this] { return responseValues(true); });
  if (what == "deformation" || what == "deformations")
    return Response::named(deformationNames, [this] { return responseValues(false); });
  if (what == "forceAndDeformation" || what == "forceDeformation") {
    std::vector<std::string> names = deformationNames;
    names.insert(names.end(), forceNames.begin(), forceNames.end());
    return Response::named(std::move(names), [this, n] {
      Vector out(2 * n);
      out << responseValues(false), responseValues(true);
      return out;
    });
  }
  if (what == "stiffness" || what == "tangent") {
    std::vector<std::string> names;
    for (const auto& row : forceNames)
      for (const auto& col : deformationNames) names.push_back("d" + row + "_d" + col);
    return Response::named(std::move(names), [this, n] {
      const Matrix k = responseTangent(false);
      Vector out(n * n);
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) out[n * r + c] = k(r, c);
      return out;
    });
  }
  return {};
}

}  // namespace beamsolid
