#include "problems/generate.h"

#include <cmath>
#include <map>
#include <random>

#include "mesh/asymptotic_nets.h"
#include "mesh/generators.h"
#include "mesh/input_error.h"
#include "mesh/io.h"
#include "mesh/output_files.h"
#include "mesh/smoothness_surfaces.h"

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

// Moves every vertex along a uniformly random direction by up to `noise`
// times the mean edge length (QuadGrid's noise, mesh/generators.h).
void AddNoise(Mesh& mesh, double noise, unsigned seed) {
  double length_sum = 0.0;
  for (EdgeIndex e : mesh.edges()) {
    length_sum += std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)),
                                                   mesh.point(mesh.vertex(e, 1))));
  }
  const double max_offset = noise * length_sum / double(mesh.number_of_edges());
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, max_offset);
  for (VertexIndex v : mesh.vertices()) {
    Vector direction;
    do {  // a normalised isotropic Gaussian is uniform on the unit sphere
      direction = Vector(gaussian(rng), gaussian(rng), gaussian(rng));
    } while (direction.squared_length() < 1e-12);
    direction = direction / std::sqrt(direction.squared_length());
    mesh.point(v) = mesh.point(v) + uniform(rng) * direction;
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
      "bulged by 0.2 (--nu around, --nv rings; Pellis §4)\n";
  for (const auto& [name, which] : Nets()) {
    text += name + std::string(23 - name.size(), ' ') + "asymptotic quad net (--refinement): " +
            AsymptoticTestNetPaperRow(which) + "\n";
  }
  return text;
}

RunResult GenerateSurface(const std::string& path, const GenerateOptions& o) {
  if (!(o.scale > 0)) throw InputError("--scale", 0, "scale", "must be > 0");
  Mesh mesh, reference;
  const auto net = Nets().find(o.surface);
  if (!std::isfinite(o.noise)) throw InputError("--noise", 0, "noise", "must be finite");
  if (o.noise >= 0 && o.surface != "roof" && o.surface != "torus") {
    throw InputError("--noise", 0, "noise", "noise applies to roof and torus only");
  }
  if (o.surface == "roof") {
    if (o.nu < 1 || o.nv < 1) throw InputError("--nu/--nv", 0, "", "grid sizes must be >= 1");
    mesh = QuadGrid(o.nu, o.nv, RoofSurface, o.noise < 0 ? 0.1 : o.noise, o.seed);
  } else if (o.surface == "torus") {
    mesh = TorusPrincipalQuads(3.0, 1.0, o.nu, o.nv);
    if (o.noise > 0) AddNoise(mesh, o.noise, o.seed);
  } else if (o.surface == "cone_start") {
    mesh = RevolutionTriangles(RevolutionProfile{}, o.nu, o.nv);
  } else if (net != Nets().end()) {
    mesh = MakeAsymptoticTestNet(net->second, o.refinement);
    if (!o.reference.empty()) reference = MakeAsymptoticTestReference(net->second, o.refinement);
  } else {
    throw InputError("--surface", 0, "surface", "unknown surface '" + o.surface +
                                                    "'; one of:\n" + GenerateSurfaceNames());
  }
  if (!o.reference.empty() && net == Nets().end()) {
    throw InputError("--reference", 0, "reference",
                     "an analytic reference exists for the asymptotic nets only");
  }
  Scale(mesh, o.scale);
  StagedOutputs staged;
  WriteMesh(staged.Stage(path), mesh);
  RunResult run;
  run.summary = "wrote " + path + ": " + std::to_string(mesh.number_of_vertices()) +
                " vertices, " + std::to_string(mesh.number_of_faces()) + " faces\n";
  if (!o.reference.empty()) {
    Scale(reference, o.scale);
    WriteMesh(staged.Stage(o.reference), reference);
    run.summary += "wrote " + o.reference + ": " + std::to_string(reference.number_of_faces()) +
                   " triangles (analytic reference)\n";
  }
  staged.Commit();
  return run;
}

}  // namespace archgeo
