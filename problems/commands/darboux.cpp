// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/commands/darboux.h"

#include <Eigen/LU>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "geometry/hnet.h"
#include "core/input_error.h"
#include "io/io.h"
#include "io/output_files.h"
#include "geometry/patchwork_io.h"

namespace archgeo {
namespace {

bool IsFinite(const Vec3& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

std::string Number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

}  // namespace

RunResult RunDarboux(const std::string& net_path, const std::string& out_path,
                     const DarbouxOptions& options) {
  if (std::filesystem::path(out_path).extension() != ".ply") {
    throw InputError(out_path, 0, "", "the patchwork is written as PLY: use a .ply name");
  }
  if (!options.rulings.empty() &&
      std::filesystem::path(options.rulings).extension() != ".obj") {
    throw InputError(options.rulings, 0, "--rulings", "rulings are written as OBJ polylines");
  }
  if (!std::isfinite(options.c) || options.c == 1.0) {
    throw InputError("--c", 0, "c", "c must be finite and different from 1 (eq. 12)");
  }
  if (options.samples < 1 || options.samples > 200) {
    throw InputError("--samples", 0, "samples", "must be in [1, 200]");
  }
  DarbouxTransform transform;
  transform.c = options.c;
  transform.branch = options.minus_branch ? DarbouxBranch::kMinus : DarbouxBranch::kPlus;
  if (!options.projective.empty()) {
    if (options.projective.size() != 16) {
      throw InputError("--projective", 0, "projective",
                       "expected 16 numbers (the 4x4 matrix, row by row), got " +
                           std::to_string(options.projective.size()));
    }
    for (int i = 0; i < 16; ++i) {
      if (!std::isfinite(options.projective[i])) {
        throw InputError("--projective", 0, "projective", "entries must be finite numbers");
      }
      transform.projective(i / 4, i % 4) = options.projective[i];
    }
    if (std::abs(transform.projective.determinant()) < 1e-12 * transform.projective.norm()) {
      throw InputError("--projective", 0, "projective", "the 4x4 matrix is singular");
    }
  }
  StagedOutputs staged({net_path});
  const std::string temporary = staged.Stage(out_path);
  const std::string rulings_temporary =
      options.rulings.empty() ? std::string() : staged.Stage(options.rulings);

  const Mesh net = ReadMesh(net_path);
  for (FaceIndex f : net.faces()) {
    if (net.degree(f) != 4) {
      throw InputError(net_path, 0, "mesh",
                       "the Darboux patchwork needs a quad net (an H-net); face " +
                           std::to_string(f.idx()) + " has " + std::to_string(net.degree(f)) +
                           " sides");
    }
  }
  const HNet hnet = BuildHNet(net);
  const SampledPatchwork sampled = SamplePatchwork(net, hnet, options.samples);
  std::vector<int> failed;
  const SampledPatchwork mapped = DarbouxMapPatchwork(sampled, transform, &failed);
  if (mapped.triangles.empty()) {
    throw InputError("--c", 0, "c",
                     "every sample maps to infinity or to a non-real point for this c and "
                     "projective map; nothing to write");
  }
  // Eq. 12 involves c² and |y|²: for a large |c| (or points far from the
  // origin) it overflows double precision, and ApplyDarboux reports success
  // with an infinite or NaN image. Such a patchwork cannot be read back:
  // refuse the run rather than write it (or count it as left out, which would
  // hide that the whole map broke down).
  for (const auto& triangle : mapped.triangles) {
    for (const int v : triangle) {
      if (!IsFinite(mapped.positions[v]) || !IsFinite(mapped.normals[v])) {
        throw InputError("--c", 0, "c",
                         "the Darboux map overflows double precision for c = " + Number(options.c) +
                             " (sample vertex " + std::to_string(v) +
                             " maps to a non-finite point); use a smaller |c| or scale the net "
                             "down (images grow like |c| times the distance from the origin)");
      }
    }
  }
  std::vector<std::array<unsigned char, 3>> colors;
  if (options.isophote_band > 0) {
    const Vec3 d{options.isophote_direction[0], options.isophote_direction[1],
                 options.isophote_direction[2]};
    colors = IsophoteColors(IsophoteAngles(mapped.normals, d), options.isophote_band);
  }
  WritePatchworkPly(temporary, mapped, colors, options.ascii);
  int failed_rulings = 0;
  if (!options.rulings.empty()) {
    Polylines rulings = PatchRulings(net, hnet, 3, 4 * options.samples + 1);
    std::vector<std::vector<Vec3>> lines;
    for (const auto& line : rulings.lines) {
      std::vector<Vec3> image;
      for (const Vec3& p : line) {
        const DarbouxResult r = ApplyDarboux(transform, Eigen::Vector3d(p[0], p[1], p[2]));
        if (r.status == DarbouxStatus::kOk && !r.point.allFinite()) {
          throw InputError("--c", 0, "c",
                           "the Darboux map overflows double precision for c = " +
                               Number(options.c) + " on a ruling; use a smaller |c|");
        }
        if (r.status != DarbouxStatus::kOk) {
          ++failed_rulings;
          image.clear();
          break;
        }
        image.push_back({r.point.x(), r.point.y(), r.point.z()});
      }
      if (image.size() >= 2) lines.push_back(image);
    }
    WritePolylinesObj(rulings_temporary, lines);
  }
  staged.Commit();

  RunResult run;
  run.report = {{"archgeo", "darboux"},
                {"net", net_path},
                {"output", out_path},
                {"c", options.c},
                {"branch", options.minus_branch ? "minus" : "plus"},
                {"samples_per_patch", options.samples},
                {"patches", net.number_of_faces()},
                {"vertices_written", mapped.positions.size() - failed.size()},
                {"failed_vertices", failed.size()},
                {"source_alpha_max", hnet.kink_max},
                {"source_alpha_mean", hnet.kink_mean}};
  char text[512];
  std::snprintf(text, sizeof text,
                "H-net of %s: %zu patches, kinks α_max %.4g°, α_mean %.4g° (the Darboux map "
                "keeps smooth joins smooth)\nwrote %s: %zu triangles; %zu samples mapped to "
                "infinity or non-real points were left out%s\n",
                net_path.c_str(), size_t(net.number_of_faces()), hnet.kink_max, hnet.kink_mean,
                out_path.c_str(), mapped.triangles.size(), failed.size(),
                options.rulings.empty() ? "" : ("\nwrote " + options.rulings).c_str());
  run.summary = text;
  if (failed_rulings > 0) {
    run.summary += std::to_string(failed_rulings) + " rulings crossed a singular point and were "
                   "left out\n";
  }
  return run;
}

}  // namespace archgeo
