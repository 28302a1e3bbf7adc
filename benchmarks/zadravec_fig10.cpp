// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Reproduces the table of [Zadravec 2010, §6, Fig. 10] ("Details of PQ
// optimization") on the public quad meshes in ../shared/data, with
// examples/planar_quads.yaml (only the mesh and the outputs overridden), and
// times the whole `archgeo solve` command against the acceptance targets;
// libigl's planarize_quad_mesh is cited (not run here), with its source.
//
//   cmake --build <build> --target zadravec_fig10 archgeo   # runs the archgeo tool
//   <build>/benchmarks/zadravec_fig10 [--quick] [--set KEY=VALUE ...]
// Exit 1 if the acceptance (below, Fig10Table) fails.
//
// All lengths are relative to the bounding-box diagonal (= 1, as in the paper).
// Times are wall-clock on whatever machine runs this (the paper: a dual-core
// 2.4 GHz MacBook Pro, 2010).
#include "benchmarks/bench_util.h"
#include "benchmarks/program.h"

namespace ARCHGEO_UNITY_ID {

using bench::Fmt;
using bench::Get;

const char* const kMeshes[] = {"libigl_inspired_mesh_quads_Conjugate.off",
                               "libigl_inspired_mesh_quads_Smooth.off",
                               "dos_botanic-garden-bubble-0.obj",
                               "dos_M2_eq_quad2.obj",
                               "dos_pillow_1.obj",
                               "dos_free_negshell_marc_anet.obj"};

std::string Sci(double x) { return std::isnan(x) ? "-" : Fmt("%.1e", x); }
std::string Percent(double relative) {
  return std::isnan(relative) ? "-" : Fmt("%.2f%%", 100 * relative);
}

constexpr int kRepeats = 3;

// The paper's claim (§6): PQ optimisation makes a quad mesh laid out along
// conjugate directions planar with little movement. Acceptance on the three
// data meshes that were meshed so or are A-nets (Conjugate, bubble,
// negshell): tolerance met (δ_PQ,n ≤ 1e-3), a valid result, displacement
// ≤ 1.5% of the diagonal. `quick`: Conjugate and negshell, one run each.
bool Fig10Table(const std::string& spec, bool quick) {
  bool ok = true;
  std::cout << "Zadravec 2010, Fig. 10 — " << spec << " (in process, no output files)\n\n";
  bench::Table t({"Model", "#Var", "#Iter (Ceres/outer)", "sec", "δ_PQ", "δ_PQ,n", "δ_prox",
                  "δ∂_prox", "disp max", "dist max", "met", "δ_PQ,n before"});
  for (const char* mesh : kMeshes) {
    const std::string name = mesh;
    const bool accepted = name.find("Conjugate") != std::string::npos ||
                          name.find("bubble") != std::string::npos ||
                          name.find("negshell") != std::string::npos;
    if (quick && name.find("Conjugate") == std::string::npos &&
        name.find("negshell") == std::string::npos) {
      continue;
    }
    bench::Json r;  // best of kRepeats by total time (the machine is shared)
    for (int i = 0; i < (quick ? 1 : kRepeats); ++i) {
      bench::Json run = bench::Solve(spec, {"mesh=" + bench::Data(mesh)});
      if (i == 0 || Get(run, "/seconds/total") < Get(r, "/seconds/total")) r = std::move(run);
    }
    t.Add({mesh, Fmt("%d", r.value("variables", 0)),
           Fmt("%d / %d", r["iterations"].value("inner", 0), r["iterations"].value("outer", 0)),
           Fmt("%.2f", Get(r, "/seconds/total")), Sci(Get(r, "/after/pq_max_relative")),
           Sci(Get(r, "/after/pq_normalized_max")), Sci(Get(r, "/after/prox_max_relative")),
           Sci(Get(r, "/after/boundary_prox_max_relative")),
           Percent(Get(r, "/after/displacement_max_relative")),
           Percent(Get(r, "/after/surface_distance_max_relative")), bench::Met(r),
           Sci(Get(r, "/before/pq_normalized_max"))});
    if (accepted) {
      const bool pass = r.value("exit_code", 1) == 0 &&
                        Get(r, "/after/pq_normalized_max") <= 1e-3 &&
                        Get(r, "/after/displacement_max_relative") <= 0.015;
      if (!pass) std::cout << "acceptance FAILED on " << name << "\n";
      ok = ok && pass;
    }
  }
  t.Add({"", "", "", "", "", "", "", "", "", "", ""});
  t.Add({"paper (verbatim):", "", "", "", "", "", "", "", "", "", ""});
  t.Add({"Figure 1", "5373", "32", "18.1", ".0003", ".011", ".0003", ".0003"});
  t.Add({"Figure 6", "1302", "16", "3.0", ".0007", ".012", ".0003", ".0008"});
  t.Add({"Figure 8", "3462", "39", "15.1", ".0003", ".01", ".0003", ".0001"});
  t.Add({"Figure 9", "1539", "13", "2.7", ".0013", ".029", ".0004", ".0006"});
  t.Print();
  std::cout
      << "\nsec: whole RunSpec (read, reference, solve, metrics), best of 3, wall-clock on this\n"
         "machine (2 cores, shared: single runs vary up to 2x with other load); the paper's\n"
         "times are on a dual core 2.4 GHz MacBook Pro, 2010.\n"
         "δ_PQ: max diagonal distance; δ_PQ,n: that over the quad's mean diagonal; δ_prox,\n"
         "δ∂_prox: max distance to the reference's tangent plane / boundary tangent (inner /\n"
         "boundary vertices); disp max: max vertex displacement; dist max: max distance to\n"
         "the reference surface. Lengths relative to the bounding-box diagonal.\n"
         "The paper's meshes (Fig. 1 Yas Island Marina Hotel; Figs. 6, 8 British Museum great\n"
         "court roof; Fig. 9 Neumünster courtyard roof) are not public. Stand-ins of similar\n"
         "size (1-2.5k vertices; the paper's #Var = 3 x #vertices): the Conjugate mesh (a\n"
         "freeform roof quad-meshed along a conjugate field, as in the paper's pipeline)\n"
         "and its Smooth-field twin; DOS's botanic-garden bubble roof, M2 funicular shell,\n"
         "pillow roof (geodesic net) and negatively curved shell (A-net), which were not\n"
         "meshed along conjugate directions (see their δ_PQ,n before).\n"
         "Acceptance (Conjugate, bubble, negshell): exit 0 (valid, δ_PQ,n ≤ 1e-3), displacement\n"
         "≤ 1.5% of the diagonal: "
      << (ok ? "pass" : "FAIL") << "\n\n";
  return ok;
}

struct Target {
  const char* label;
  const char* spec;
  double seconds, pq_n, displacement;  // upper bounds (displacement relative; 0: none)
};

void CommandTable() {
  const std::string mesh = "mesh=" + bench::Data(kMeshes[0]);
  std::cout << "Whole command: archgeo solve SPEC --quiet --set "
            << "mesh=.../" << kMeshes[0]
            << "\n(subprocess, writes the PLY mesh and JSON report to a temp dir; best of 3)\n\n";
  bench::Table t({"Run", "wall s", "δ_PQ,n max", "disp max", "target", "pass"});
  const Target targets[] = {
      {"planar_quads_gentle.yaml", "examples/planar_quads_gentle.yaml", 1.0, 5e-3, 0.0032},
      {"planar_quads.yaml", "examples/planar_quads.yaml", 2.0, 1e-3, 0}};
  for (const Target& target : targets) {
    double best = 1e30;
    bench::Json report;
    for (int i = 0; i < 3; ++i) {
      bench::Json r;
      const bench::ProcessResult p =
          bench::SolveCommand(bench::Source(target.spec), {mesh}, &r, /*write_mesh=*/true);
      if (p.exit_code != 0) {
        std::cout << target.label << ": exit code " << p.exit_code << "\n";
        break;
      }
      if (p.seconds < best) best = p.seconds;
      report = r;
    }
    const double pq = Get(report, "/after/pq_normalized_max");
    const double disp = Get(report, "/after/displacement_max_relative");
    const bool pass = best < target.seconds && pq <= target.pq_n &&
                      (target.displacement <= 0 || disp <= target.displacement);
    std::string goal = Fmt("< %g s, δ_PQ,n ≤ %g", target.seconds, target.pq_n);
    if (target.displacement > 0) goal += Fmt(", disp ≤ %.2f%%", 100 * target.displacement);
    t.Add({target.label, Fmt("%.2f", best), Sci(pq), Percent(disp), goal, pass ? "yes" : "NO"});
  }
  t.Print();
  std::cout << "\nWall-clock on this machine (2 cores, shared).\n"
               "Cited, not measured by this repository (libigl is not a Debian package, so it\n"
               "cannot run here): libigl's planarize_quad_mesh on Conjugate, 3.2 s, δ_PQ,n\n"
               "4.98e-3, displacement 0.32%; it never reaches δ_PQ,n ≤ 5e-3 on Smooth, botanic,\n"
               "M2 and pillow (M2 ends at 2.2e-2 after moving 4.5%, pillow at 4.0e-2 after\n"
               "moving 3.6%). Source: the project's issue tracker (the CEO's measurement on\n"
               "this kind of machine).\n";
}


int Main(int argc, char** argv) {
  const std::vector<std::string> args = bench::Init(argc, argv, {{"--quick"}});
  const bool quick = !args.empty();  // --quick, the only flag
  std::cout << "BLAS: " << archgeo::BlasLibrary() << "\n\n";
  const bool ok = Fig10Table(bench::Source("examples/planar_quads.yaml"), quick);
  if (!quick) CommandTable();  // timed: not an acceptance
  return ok ? 0 : 1;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(zadravec_fig10, ARCHGEO_UNITY_ID::Main);
