// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/commands/generate.h"

#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "generators/asymptotic_nets.h"
#include "generators/generators.h"
#include "core/input_error.h"
#include "io/io.h"
#include "io/output_files.h"
#include "fields/triangle_surfaces.h"
#include "generators/smoothness_surfaces.h"

namespace archgeo {
namespace {

const std::map<std::string, AsymptoticTestNet>& Nets() {
  static const std::map<std::string, AsymptoticTestNet> nets = {
      {"hyperbolic_paraboloid", AsymptoticTestNet::kHyperbolicParaboloid},
      {"enneper_large", AsymptoticTestNet::kEnneperLarge},
      {"enneper_small", AsymptoticTestNet::kEnneperSmall},
      {"catenoid_band", AsymptoticTestNet::kCatenoidBand},
      {"scherk", AsymptoticTestNet::kScherk}};
  return nets;
}

void Scale(Mesh& mesh, double s) {
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    mesh.point(v) = Point(s * p.x(), s * p.y(), s * p.z());
  }
}


std::string NumberText(double x) {
  std::ostringstream text;
  text << x;
  return text.str();
}

// The option bounds of generate.h, checked before anything is built.
void CheckOptions(const GenerateOptions& o, bool is_net) {
  if (!(o.scale >= kMinGenerateScale && o.scale <= kMaxGenerateScale)) {
    throw InputError("--scale", 0, "scale",
                     "must be in [" + NumberText(kMinGenerateScale) + ", " +
                         NumberText(kMaxGenerateScale) + "], got " + NumberText(o.scale));
  }
  if (o.noise && !(*o.noise >= 0 && *o.noise <= kMaxGenerateNoise)) {
    throw InputError("--noise", 0, "noise",
                     "must be in [0, " + NumberText(kMaxGenerateNoise) +
                         "] (mean edge lengths), got " + NumberText(*o.noise));
  }
  if (o.noise && o.surface != "roof" && o.surface != "torus") {
    throw InputError("--noise", 0, "noise", "noise applies to roof and torus only");
  }
  if (is_net) {
    if (o.refinement < 1 || o.refinement > kMaxGenerateRefinement) {
      throw InputError("--refinement", 0, "refinement",
                       "must be in [1, " + std::to_string(kMaxGenerateRefinement) + "], got " +
                           std::to_string(o.refinement));
    }
    return;
  }
  if (o.surface == "sphere") {
    if (o.nu < 0 || o.nu > 7) {
      throw InputError("--nu", 0, "nu", "sphere: subdivisions must be in [0, 7], got " +
                                            std::to_string(o.nu));
    }
    return;
  }
  if (o.nu < 1 || o.nv < 1) {
    throw InputError("--nu/--nv", 0, "", "grid sizes must be >= 1, got " + std::to_string(o.nu) +
                                             " x " + std::to_string(o.nv));
  }
  const long long faces = (o.surface == "cone_start" ? 2LL : 1LL) * o.nu * o.nv;
  if (faces > kMaxGeneratedFaces) {
    throw InputError("--nu/--nv", 0, "",
                     std::to_string(o.nu) + " x " + std::to_string(o.nv) + " gives " +
                         std::to_string(faces) + " faces, more than the limit of " +
                         std::to_string(kMaxGeneratedFaces));
  }
}

// Last guard before writing: every coordinate finite (WriteMesh would refuse
// too, but naming the temporary file).
void CheckFinite(const Mesh& mesh, const std::string& path) {
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      throw InputError(path, 0, "",
                       "vertex " + std::to_string(v.idx()) +
                           " has a non-finite coordinate; nothing written");
    }
  }
}

}  // namespace

std::string GenerateSurfaceNames() {
  std::string text =
      "roof                   quad grid (--nu x --nv) on z = 0.3 sin 2x + 0.25 cos 2y with "
      "--noise (planar_quads demo)\n"
      "torus                  principal quad mesh of the torus R = 3, r = 1 (--nu x --nv; "
      "Pellis Fig. 7; conical: --noise for a noisy copy)\n"
      "cone_start             triangle mesh between circles r = 1 at z = 0 and 0.5 at z = 1, "
      "bulged by 0.2 (--nu around, --nv rings; Pellis §4)\n"
      "sphere                 unit icosphere: an icosahedron split --nu times (0-7), "
      "20 4^nu triangles (spectral_sphere, Gebreiter Fig. 8)\n";
  for (const auto& [name, which] : Nets()) {
    text += name + std::string(23 - name.size(), ' ') + "asymptotic quad net (--refinement): " +
            AsymptoticTestNetPaperRow(which) + "\n";
  }
  return text;
}

RunResult GenerateSurface(const std::string& path, const GenerateOptions& o) {
  Mesh mesh, reference;
  const auto net = Nets().find(o.surface);
  const bool is_net = net != Nets().end();
  if (!is_net && o.surface != "roof" && o.surface != "torus" && o.surface != "cone_start" &&
      o.surface != "sphere") {
    throw InputError("--surface", 0, "surface", "unknown surface '" + o.surface +
                                                    "'; one of:\n" + GenerateSurfaceNames());
  }
  if (!o.reference.empty() && !is_net) {
    throw InputError("--reference", 0, "reference",
                     "an analytic reference exists for the asymptotic nets only");
  }
  CheckOptions(o, is_net);
  if (o.surface == "roof") {
    mesh = QuadGrid(o.nu, o.nv, RoofSurface, o.noise.value_or(0.1), o.seed);
  } else if (o.surface == "torus") {
    mesh = TorusPrincipalQuads(3.0, 1.0, o.nu, o.nv);
    if (o.noise.value_or(0.0) > 0) AddNoise(mesh, *o.noise, o.seed);
  } else if (o.surface == "sphere") {
    mesh = TriangulatedEllipsoid(1, 1, 1, o.nu);
  } else if (o.surface == "cone_start") {
    mesh = RevolutionTriangles(RevolutionProfile{}, o.nu, o.nv);
  } else {
    mesh = MakeAsymptoticTestNet(net->second, o.refinement);
    if (!o.reference.empty()) reference = MakeAsymptoticTestReference(net->second, o.refinement);
  }
  Scale(mesh, o.scale);
  CheckFinite(mesh, path);
  if (!o.reference.empty()) {
    Scale(reference, o.scale);
    CheckFinite(reference, o.reference);
  }
  StagedOutputs staged;
  // Write() names `path`, never the temporary, in a writer's error.
  staged.Write(path, "", [&](const std::string& temporary) { WriteMesh(temporary, mesh); });
  RunResult run;
  run.summary = "wrote " + path + ": " + std::to_string(mesh.number_of_vertices()) +
                " vertices, " + std::to_string(mesh.number_of_faces()) + " faces\n";
  if (!o.reference.empty()) {
    staged.Write(o.reference, "--reference",
                 [&](const std::string& temporary) { WriteMesh(temporary, reference); });
    run.summary += "wrote " + o.reference + ": " + std::to_string(reference.number_of_faces()) +
                   " triangles (analytic reference)\n";
  }
  staged.Commit();
  return run;
}

}  // namespace archgeo
