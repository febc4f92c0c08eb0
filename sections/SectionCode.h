#pragma once
#include <optional>
#include <string>

namespace beamsolid {

// What one component of a section's resultants is, with OpenSees' numbers
// (the codes of section('Aggregator', ...)): the force-based elements build
// their force interpolation, and zeroLengthSection its kinematics, from these.
enum class SectionCode : int { Mz = 1, P = 2, Vy = 3, My = 4, Vz = 5, T = 6 };

inline const char* sectionCodeName(SectionCode code) {
  switch (code) {
    case SectionCode::Mz: return "Mz";
    case SectionCode::P: return "P";
    case SectionCode::Vy: return "Vy";
    case SectionCode::My: return "My";
    case SectionCode::Vz: return "Vz";
    case SectionCode::T: return "T";
  }
  return "?";
}

// The deformation that goes with each resultant (section responses).
inline const char* sectionDeformationName(SectionCode code) {
  switch (code) {
    case SectionCode::Mz: return "kappaZ";
    case SectionCode::P: return "eps";
    case SectionCode::Vy: return "gammaY";
    case SectionCode::My: return "kappaY";
    case SectionCode::Vz: return "gammaZ";
    case SectionCode::T: return "theta";
  }
  return "?";
}

// Position of a code in the 3D section order [P, Mz, My, T]; -1 for shear.
inline int index3d(SectionCode code) {
  switch (code) {
    case SectionCode::P: return 0;
    case SectionCode::Mz: return 1;
    case SectionCode::My: return 2;
    case SectionCode::T: return 3;
    default: return -1;
  }
}

// 'P', 'Mz', 'My', 'Vy', 'Vz', 'T' as the Aggregator command spells them.
inline std::optional<SectionCode> parseSectionCode(const std::string& text) {
  if (text == "P") return SectionCode::P;
  if (text == "Mz") return SectionCode::Mz;
  if (text == "My") return SectionCode::My;
  if (text == "Vy") return SectionCode::Vy;
  if (text == "Vz") return SectionCode::Vz;
  if (text == "T") return SectionCode::T;
  return std::nullopt;
}

}  // namespace beamsolid
