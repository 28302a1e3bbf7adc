// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The goal library's examples on the real meshes [Gebreiter 2012, §10, §11;
// issue 18], in this process (ReadSpec + RunSpec, no output files), with the
// figures docs/results.md quotes:
//
//   conical.yaml   on libigl_inspired_mesh_quads_Smooth.off (acceptance:
//                  conical residual and δ_PQ,n ≤ 1e-3, no non-convex quad,
//                  max displacement ≤ 3% of the diagonal, face-offset miss ≤
//                  1e-3 of the mean edge length — exit 1 otherwise), on the
//                  Conjugate mesh (no acceptance: a conjugate, non-principal
//                  net; the table shows what it costs — the validity check
//                  refuses the collapsed result, exit 3) and on a noisy torus
//                  principal net (`archgeo generate --surface torus --noise
//                  0.05`, the same acceptance);
//   even_boundary.yaml  on the botanic-garden bubble (acceptance: boundary
//                  edges within 1% of their mean, boundary vertices on the
//                  perimeter to 1e-9 of the diagonal);
//   hanging_net.yaml    (acceptance: force balance ≤ 1e-6 of the load).
//
//   goal_examples [--set KEY=VALUE ...]   (added to every run)
#include <cstdio>
#include <string>
#include <vector>

#include "benchmarks/bench_util.h"
#include "problems/commands/generate.h"
#include "benchmarks/program.h"

namespace ARCHGEO_UNITY_ID {

using bench::Fmt;
using bench::Get;

// Exit code, and for a result the validity check refused (exit 3) or that
// is an earlier round than the last (the last was invalid), the failed checks.
std::string Validity(const bench::Json& r) {
  std::string text = Fmt("%.0f", Get(r, "/exit_code"));
  if (r.contains("validity")) {
    std::string failed;
    for (const auto& check : r["validity"]["checks"]) {
      if (!check.value("passed", true) && check.value("hard", false)) {
        failed += (failed.empty() ? "" : ", ") + check.value("name", std::string());
      }
    }
    if (!failed.empty()) text += " (invalid: " + failed + ")";
    if (r["validity"].contains("restored_round") && !r["validity"]["restored_round"].is_null()) {
      text += " (output: round " + r["validity"]["restored_round"].dump() + ")";
    }
  }
  return text;
}

// Exit 0 with the last round's result (no round refused by the validity
// check) and the figures of issue 18.
bool conical_ok(const bench::Json& r) {
  return Get(r, "/exit_code") == 0 && r.contains("validity") &&
         r["validity"]["restored_round"].is_null() && Get(r, "/after/conical_max") <= 1e-3 && Get(r, "/after/pq_normalized_max") <= 1e-3 &&
         Get(r, "/after/non_convex_quads") == 0 &&
         Get(r, "/after/displacement_max_relative") <= 0.03 &&
         Get(r, "/after/face_offset_miss") <= 1e-3;
}


int Main(int argc, char** argv) {
  bench::Init(argc, argv);
  archgeo::ConfigureThreading();
  bool ok = true;

  const std::string torus = (bench::Scratch() / "noisy_torus.obj").string();
  archgeo::GenerateOptions g;
  g.surface = "torus";
  g.nu = 24;
  g.nv = 12;
  g.noise = 0.05;
  archgeo::GenerateSurface(torus, g);

  std::cout << "examples/conical.yaml\n";
  bench::Table conical({"mesh", "conical max (rad)", "δ_PQ,n max", "offset miss / edge",
                        "non-convex", "moved / diag", "Hausdorff / diag", "edges max/min",
                        "rounds", "T (s)", "exit", "acceptance"});
  struct Run {
    std::string name, mesh;
    bool accept;
  };
  for (const Run& run : std::vector<Run>{
           {"Smooth", bench::Data("libigl_inspired_mesh_quads_Smooth.off"), true},
           {"Conjugate", bench::Data("libigl_inspired_mesh_quads_Conjugate.off"), false},
           {"noisy torus", torus, true}}) {
    const bench::Json r = bench::Solve(bench::Source("examples/conical.yaml"), {"mesh=" + run.mesh});
    const bool pass = conical_ok(r);
    if (run.accept) ok = ok && pass;
    conical.Add({run.name,
                 Fmt("%.2e -> %.2e", Get(r, "/before/conical_max"), Get(r, "/after/conical_max")),
                 Fmt("%.2e -> %.2e", Get(r, "/before/pq_normalized_max"),
                     Get(r, "/after/pq_normalized_max")),
                 Fmt("%.2e -> %.2e", Get(r, "/before/face_offset_miss"),
                     Get(r, "/after/face_offset_miss")),
                 Fmt("%.0f", Get(r, "/after/non_convex_quads")),
                 Fmt("%.2e", Get(r, "/after/displacement_max_relative")),
                 Fmt("%.2e", Get(r, "/after/hausdorff_relative")),
                 Fmt("%.3g -> %.3g", Get(r, "/before/edge_length_ratio"),
                     Get(r, "/after/edge_length_ratio")),
                 Fmt("%.0f", Get(r, "/iterations/outer")), Fmt("%.1f", Get(r, "/wall_seconds")),
                 Validity(r), run.accept ? (pass ? "met" : "NOT met") : (pass ? "(met)" : "(not met)")});
  }
  conical.Print();

  std::cout << "\nexamples/even_boundary.yaml\n";
  bench::Table even({"mesh", "boundary max |ℓ/mean − 1|", "boundary max/min",
                     "off perimeter / diag", "Hausdorff / diag", "δ_PQ,n max", "rounds", "T (s)",
                     "exit", "acceptance"});
  {
    const bench::Json r = bench::Solve(bench::Source("examples/even_boundary.yaml"), {});
    const double spread = Get(r, "/after/boundary_spacing_spread");
    const double off = Get(r, "/details/on_curve/max_distance_relative");
    const bool pass = Get(r, "/exit_code") == 0 && spread <= 0.01 && off <= 1e-9;
    ok = ok && pass;
    even.Add({"botanic bubble",
              Fmt("%.2e -> %.2e", Get(r, "/before/boundary_spacing_spread"), spread),
              Fmt("%.3g -> %.4f", Get(r, "/before/boundary_length_ratio"),
                  Get(r, "/after/boundary_length_ratio")),
              Fmt("%.1e", off), Fmt("%.2e", Get(r, "/after/hausdorff_relative")),
              Fmt("%.2e -> %.2e", Get(r, "/before/pq_normalized_max"),
                  Get(r, "/after/pq_normalized_max")),
              Fmt("%.0f", Get(r, "/iterations/outer")), Fmt("%.1f", Get(r, "/wall_seconds")),
              Validity(r), pass ? "met" : "NOT met"});
  }
  even.Print();

  std::cout << "\nexamples/hanging_net.yaml\n";
  bench::Table net({"net", "force balance / load", "span", "rise", "span/rise", "T (s)", "exit",
                    "acceptance"});
  {
    const bench::Json r = bench::Solve(bench::Source("examples/hanging_net.yaml"), {});
    const double balance = Get(r, "/details/load/force_balance_max");
    const bool pass = Get(r, "/exit_code") == 0 && balance <= 1e-6;
    ok = ok && pass;
    net.Add({"24 x 24, 12 x 12 quads", Fmt("%.2e", balance),
             Fmt("%.4f", Get(r, "/details/load/span")), Fmt("%.4f", Get(r, "/details/load/rise")),
             Fmt("%.3f", Get(r, "/details/load/span_over_rise")),
             Fmt("%.2f", Get(r, "/wall_seconds")), Validity(r), pass ? "met" : "NOT met"});
  }
  net.Print();
  return ok ? 0 : 1;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(goal_examples, ARCHGEO_UNITY_ID::Main);
