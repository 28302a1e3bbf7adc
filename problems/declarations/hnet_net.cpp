// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — which net the hnet builder optimises (see hnet_net.h).
#include "problems/declarations/hnet_net.h"

#include <cstdio>
#include <optional>

#include "geometry/diagonal_net.h"
#include "geometry/hnet.h"
#include "core/input_error.h"

namespace archgeo {
namespace {

nlohmann::json ToJson(const StarPlanarities& f) {
  return {{"star_planarity_max", f.max}, {"star_planarity_mean", f.mean}};
}

std::string Sci(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%.3e", x);
  return s;
}

}  // namespace

double DiagonalNetStarPlanarityMean(const Mesh& mesh) {
  double best = -1;
  for (int colour = 0; colour < 2; ++colour) {
    try {
      const double mean = InteriorStarPlanarity(MakeDiagonalNet(mesh, colour).mesh).mean;
      if (mean >= 0 && (best < 0 || mean < best)) best = mean;
    } catch (const InputError&) {
      // no such net
    }
  }
  return best;
}

WorkingNet ChooseHNetNet(const Mesh& input, const std::string& path, const std::string& choice,
                         const std::string& spec_file, int spec_line) {
  WorkingNet result;
  if (choice == "mesh") return result;
  nlohmann::json& d = result.details;
  d["setting"] = choice;
  const StarPlanarities mesh_flat = InteriorStarPlanarity(input);
  d["candidates"]["mesh"] = ToJson(mesh_flat);
  std::optional<DiagonalNet> nets[2];
  StarPlanarities flat[2];
  for (int colour = 0; colour < 2; ++colour) {
    const std::string name = "diagonal_" + std::to_string(colour);
    if (choice != "auto" && choice != name) continue;
    try {
      nets[colour] = MakeDiagonalNet(input, colour);
      flat[colour] = InteriorStarPlanarity(nets[colour]->mesh);
      d["candidates"][name] = ToJson(flat[colour]);
      d["candidates"][name]["holes"] = nets[colour]->holes;
    } catch (const InputError& e) {
      if (choice != "auto") {
        throw InputError(spec_file, spec_line, "hnet.net", path + ": " + e.message());
      }
      d["candidates"][name] = {{"unusable", e.message()}};
    }
  }
  int chosen = -1;
  if (choice == "auto") {
    for (int colour = 0; colour < 2; ++colour) {
      if (!nets[colour] || flat[colour].mean < 0) continue;
      if (!(flat[colour].mean * kDiagonalGain < mesh_flat.mean)) continue;
      if (chosen < 0 || flat[colour].mean < flat[chosen].mean) chosen = colour;
    }
  } else {
    chosen = choice == "diagonal_0" ? 0 : 1;
  }
  if (chosen < 0) {
    d["net"] = "mesh";
    result.headline = "net: the input mesh (mean interior star planarity " + Sci(mesh_flat.mean) +
                      "; no diagonal net is " + std::to_string(int(kDiagonalGain)) +
                      "x flatter)\n";
    return result;
  }
  DiagonalNet& net = *nets[chosen];
  const std::string name = "diagonal_" + std::to_string(chosen);
  d["net"] = name;
  d["vertices"] = net.mesh.number_of_vertices();
  d["faces"] = net.mesh.number_of_faces();
  d["holes"] = net.holes;
  result.derived = true;
  result.source = net.source;
  result.mesh = std::move(net.mesh);
  result.headline =
      "net: the colour-" + std::to_string(chosen) + " diagonal net of " + path + " (" +
      std::to_string(result.mesh.number_of_vertices()) + " vertices, " +
      std::to_string(result.mesh.number_of_faces()) + " quads, " + std::to_string(net.holes) +
      " holes)" + (choice == "auto" ? ", chosen by hnet.net: auto" : "") +
      ": interior star planarity max " + Sci(flat[chosen].max) + ", mean " +
      Sci(flat[chosen].mean) + " (the input's: max " + Sci(mesh_flat.max) + ", mean " +
      Sci(mesh_flat.mean) + ")\n";
  return result;
}

HNetOptions HNetOptionsOf(const Settings& s) {
  HNetOptions o;
  if (s.schema().Find("hnet.start_face") == nullptr) return o;
  o.start_face = int(s.Integer("hnet.start_face"));
  o.kink_samples = int(s.Integer("hnet.kink_samples"));
  o.shape = s.String("hnet.shape_parameters") == "propagated" ? HNetShape::kPropagated
                                                               : HNetShape::kLeastSquares;
  return o;
}

}  // namespace archgeo
