#include "problems/builders.h"

#include <functional>
#include <utility>

namespace archgeo {
namespace {

using Factory = std::unique_ptr<Builder> (*)();

const std::vector<std::pair<std::string, Factory>>& Table() {
  static const std::vector<std::pair<std::string, Factory>> table = {
      {"planar_quads", &MakePlanarQuadsBuilder},
      {"hnet", &MakeHNetBuilder},
      {"total_absolute_curvature", &MakeTotalAbsoluteCurvatureBuilder},
      {"smooth_mesh", &MakeSmoothMeshBuilder},
      {"principal_symmetric", &MakePrincipalSymmetricBuilder},
  };
  return table;
}

}  // namespace

std::vector<std::string> BuilderNames() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : Table()) names.push_back(name);
  return names;
}

std::unique_ptr<Builder> MakeBuilder(const std::string& name) {
  for (const auto& [n, factory] : Table()) {
    if (n == name) return factory();
  }
  return nullptr;
}

}  // namespace archgeo
