#include "sections/UniaxialSection2d.h"

#include <vector>

namespace beamsolid {

namespace {

std::vector<std::unique_ptr<UniaxialMaterial>> one(std::unique_ptr<UniaxialMaterial> material) {
  std::vector<std::unique_ptr<UniaxialMaterial>> v;
  v.push_back(std::move(material));
  return v;
}

}  // namespace

UniaxialSection2d::UniaxialSection2d(int tag, std::unique_ptr<UniaxialMaterial> material, SectionCode code)
    : SectionAggregator2d(tag, nullptr, one(std::move(material)), {code}) {}

std::unique_ptr<SectionForceDeformation2d> UniaxialSection2d::clone() const {
  return std::make_unique<UniaxialSection2d>(*this);
}

}  // namespace beamsolid
