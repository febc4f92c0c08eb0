#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/Response.h"
#include "materials/nd/NDMaterial.h"

namespace beamsolid {

// One material response (e.g. 'plasticStrain', 'equivalentPlasticStrain')
// from every Gauss point of a solid element, concatenated in the element's
// point order with component names suffixed _1, _2, ...; empty when any
// point's material does not offer it.
template <class Materials>
Response gaussPointResponse(const Materials& materials, const std::vector<std::string>& materialArgs) {
  std::vector<Response> points;
  std::vector<std::string> names;
  int g = 0;
  for (const auto& m : materials) {
    Response r = m->setResponse(materialArgs);
    if (!r) return {};
    ++g;
    for (const std::string& n : r.componentNames) names.push_back(n + "_" + std::to_string(g));
    points.push_back(std::move(r));
  }
  const auto size = static_cast<Eigen::Index>(names.size());
  return {std::move(names), [points = std::move(points), size] {
            Vector out(size);
            Eigen::Index at = 0;
            for (const Response& r : points) {
              const Vector v = r.value();
              out.segment(at, v.size()) = v;
              at += v.size();
            }
            return out;
          }};
}

}  // namespace beamsolid
