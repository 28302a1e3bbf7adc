// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `spectral_quads`: spectral quadrangulation of a surface mesh
// (polygons triangulated; with boundary, through the surface doubled across
// it, problems/declarations/surface_complex.h: HalfBaseComplex is the base
// complex) [Gebreiter 2012, §6, §7, §4.1; Dong et al. 2006]:
//   cotangent (or normalised) Laplacian eigenpairs (spectral/laplacian.h,
//   spectral/eigenpairs.h) → eigenfunction K (spectral.eigenfunction) or the
//   automatic choice → its Morse–Smale complex with saddle–extremum pairs
//   of persistence ≤ spectral.persistence cancelled (spectral/morse_smale.h;
//   on the mesh refined where its arcs cannot all be placed apart,
//   problems/declarations/surface_complex.h)
//   → the quasi-dual as a base complex (nodes: the extrema's vertices) →
//   charts → parameterisation → extraction (the step base_complex_quads
//   uses, problems/declarations/base_complex_input.h) → the all-quad mesh,
//   the net the run measures and writes (output.mesh). No solve follows.
//
// Automatic choice (spectral.eigenfunction 0): eigenfunctions 1 …
// spectral.count − 1 are the candidates, ordered by how far their predicted
// chart count (one per saddle, `archgeo spectral --list`) is from the target
// (spectral.charts, or the surface's area / spectral.chart_edge_length²),
// ties to the lower k; the first of the kSqTries nearest whose complex is a
// valid quad complex, whose charts are discs and whose quad mesh passes the
// validity checks (validity.*, without the design surface) is taken; when
// only the last fail, the first such quad mesh is the result. None: exit 4
// naming each one's reason (HookContext::missed), the input written as
// output.mesh. Outputs besides: output.function (PLY, φ_K per vertex),
// output.complex (OBJ polylines), output.quasi_dual (OBJ quads).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>

#include "core/input_error.h"
#include "core/magnitude.h"
#include "core/problem.h"
#include "geometry/reference.h"
#include "io/io.h"
#include "io/output_files.h"
#include "problems/commands/spectral.h"
#include "analysis/validity.h"
#include "problems/declarations/base_complex_input.h"
#include "problems/declarations/surface_complex.h"
#include "problems/runtime/model.h"
#include "spectral/eigenpairs.h"

namespace archgeo::problems {
namespace {

constexpr int kSqTries = 16;  // candidates tried by the automatic choice at most

struct SqState : ProblemState {
  Mesh design;              // the input, for output.function
  std::vector<double> phi;  // the chosen (or last tried) eigenfunction, max |φ| = 1
  MorseSmaleComplex complex;
  int refinements = 0;      // the mesh the complex lies on: the input refined so often
  bool doubled = false;     // the input has a boundary: the complex is its double's
  QuadBaseComplex dual;
  QuadBaseComplex base;     // the base complex charted: the quasi-dual, or the complex itself
  bool primal = false;      // base is the complex itself (its quasi-dual repeats a corner)
  bool quads = false;       // the chart step ran on it
  std::string invalid;      // the chart step's failed checks
};

double SqSecondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Why the complex cannot be a base complex, or "".
std::string SqComplexFault(const MorseSmaleComplex& c, const QuadBaseComplex& q) {
  if (!c.valid) {
    return "not a valid quad complex (" + std::to_string(c.invalid_cells) + " invalid cells, " +
           std::to_string(c.unresolved) + " arcs not placed, " + std::to_string(c.shared_vertices) +
           " vertices shared by arcs)";
  }
  if (q.degenerate_quads > 0 || q.missing_saddles > 0) {
    return "its quasi-dual has " + std::to_string(q.degenerate_quads) +
           " quads with a repeated corner and " + std::to_string(q.missing_saddles) +
           " saddles without all their arcs";
  }
  return "";
}

nlohmann::json SqComplexDetails(const MorseSmaleComplex& c, const QuadBaseComplex& q) {
  std::map<std::string, int> multiplicity;  // saddles per multiplicity
  for (const MorseSmaleNode& n : c.nodes) {
    if (n.kind == 0) ++multiplicity[std::to_string(n.multiplicity)];
  }
  return {{"maxima", c.maxima},
          {"minima", c.minima},
          {"saddles", c.saddles},
          {"saddle_multiplicities", multiplicity},
          {"euler_sum", c.maxima + c.minima - c.saddles},
          {"cancelled", c.cancelled},
          {"arcs", c.arcs.size()},
          {"rerouted_arcs", c.rerouted},
          {"unresolved_arcs", c.unresolved},
          {"cells", c.cells.size()},
          {"invalid_cells", c.invalid_cells},
          {"valid", c.valid},
          {"quasi_dual",
           {{"vertices", q.points.size()},
            {"quads", q.quads.size()},
            {"degenerate_quads", q.degenerate_quads},
            {"irregular_vertices", q.irregular_vertices},
            {"euler", q.euler}}}};
}

// The eigenpairs asked for; bad counts and solver failures name their key.
Eigenpairs SqEigenpairs(const Settings& s, const SpectralMesh& m, int eigenfunction) {
  const int vertices = int(m.points.size());
  if (eigenfunction >= vertices - 1) {
    throw s.Error("spectral.eigenfunction",
                  std::to_string(eigenfunction) + " is beyond the mesh's " +
                      std::to_string(vertices) + " vertices (eigenfunctions 1 … " +
                      std::to_string(vertices - 2) + " can be computed)");
  }
  const int count = eigenfunction > 0 ? eigenfunction + 1 : int(s.Integer("spectral.count"));
  if (count >= vertices) {
    throw s.Error("spectral.count", "must be below the mesh's " + std::to_string(vertices) +
                                        " vertices");
  }
  const std::string key = eigenfunction > 0 ? "spectral.eigenfunction" : "spectral.count";
  try {
    const Laplacian l = BuildLaplacian(m.points, m.triangles,
                                       s.String("spectral.laplacian") == "normalised"
                                           ? LaplacianKind::kNormalised
                                           : LaplacianKind::kCotangent);
    return LowestEigenpairs(l.stiffness, l.mass, count);
  } catch (const std::invalid_argument& e) {
    throw s.Error("spectral.laplacian", e.what());
  } catch (const std::runtime_error& e) {
    throw s.Error(key, e.what());
  }
}

void SqNet(HookContext& c) {
  const auto t0 = std::chrono::steady_clock::now();
  const Settings& s = *c.settings;
  const Mesh design = TriangulatedCopy(*c.input);  // polygons triangulated
  const SpectralMesh m = SpectralArrays(design);
  const int given = int(s.Integer("spectral.eigenfunction"));
  const Eigenpairs pairs = SqEigenpairs(s, m, given);
  const double seconds_eigen = SqSecondsSince(t0);
  const std::vector<SpectralCandidate> candidates = SpectralCandidatesOf(m, pairs);
  const int target = SpectralTarget(m.area, int(s.Integer("spectral.charts")),
                                    s.Number("spectral.chart_edge_length"));
  std::vector<int> order = given > 0 ? std::vector<int>{given - 1}
                                     : SpectralByTarget(candidates, target);
  if (int(order.size()) > kSqTries) order.resize(kSqTries);
  MorseSmaleOptions options;
  options.persistence = s.Number("spectral.persistence");
  SqState& st = c.State<SqState>();
  st.design = design;
  nlohmann::json tried = nlohmann::json::array();
  std::string reasons;
  const SpectralCandidate* chosen = nullptr;
  ChartStep step;
  const ValidityLimits limits = LimitsOf(s);
  // The first candidate whose quad mesh the validity checks failed, kept
  // as it was: the result when no candidate's quad mesh passes.
  struct Unbuildable {
    std::vector<double> phi;
    MorseSmaleComplex complex;
    int refinements = 0;
    bool doubled = false, primal = false;
    QuadBaseComplex dual, base;
    ChartStep step;
    const SpectralCandidate* candidate = nullptr;
  };
  std::optional<Unbuildable> unbuildable;
  // One candidate; with the automatic choice its quad mesh must also be
  // buildable (no panel the validity checks fail), or the choice goes on.
  auto attempt = [&](int i) {
    const SpectralCandidate& cand = candidates[size_t(i)];
    Eigen::VectorXd f = pairs.vectors.col(cand.k);
    f /= std::max(f.cwiseAbs().maxCoeff(), 1e-300);
    st.phi.assign(f.data(), f.data() + f.size());
    // The whole mesh refined for a given eigenfunction only: the automatic
    // choice moves on to the next candidate instead.
    const SurfaceComplex sc = BuildSurfaceComplex(design, f, options, given > 0 ? 2 : 0);
    st.complex = sc.complex;
    st.refinements = sc.refinements;
    st.doubled = sc.doubled;
    st.dual = sc.quasi_dual;
    st.base = st.dual;
    st.primal = false;
    st.quads = false;
    chosen = &cand;
    // A surface with boundary: its own base complex (HalfBaseComplex)
    // judges the quasi-dual's corners, not the double's.
    std::string fault = !sc.built ? "its complex cannot be built: " + sc.error
                        : sc.doubled && st.complex.valid ? ""
                                                         : SqComplexFault(st.complex, st.dual);
    if (!fault.empty() && st.complex.valid && !sc.doubled) {
      // The quasi-dual repeats a corner (a saddle with two arcs to one
      // extremum, a wave round the tube); the complex's own cells are
      // quads with four distinct corners (§7.1.2): chart those.
      QuadBaseComplex primal = PrimalQuads(st.complex, sc.points);
      if (primal.degenerate_quads == 0) {
        st.base = std::move(primal);
        st.primal = true;
        fault.clear();
      }
    }
    if (fault.empty()) {
      try {
        // A surface with boundary: the half of the double's quasi-dual on
        // the input, charted on the input.
        step = sc.doubled ? RunChartStep(s, design, sc.half_points, sc.half_triangles,
                                         HalfBaseComplex(sc), true)
                          : RunChartStep(s, design, sc.points, sc.triangles,
                                         QuasiDualBaseComplex(st.base), true);
        st.quads = true;
      } catch (const std::exception& e) {  // BaseComplexError, a failed factorisation
        fault = std::string("its charts fail: ") + e.what();
      }
    }
    if (st.quads && given == 0) {
      const Validity v = CheckValidity(step.mesh, nullptr, limits, true);
      if (!v.valid()) {
        st.quads = false;
        if (!unbuildable) {
          unbuildable = Unbuildable{st.phi,    st.complex, st.refinements, st.doubled, st.primal,
                                    st.dual,   st.base,    step,           &cand};
        }
        const std::string reason = v.Reason();
        fault = "its quad mesh has panels that cannot be built: " + reason.substr(0, reason.find('\n'));
      }
    }
    tried.push_back({{"k", cand.k},
                     {"charts", SpectralCharts(cand.critical)},
                     {"base", st.primal ? "complex" : "quasi_dual"},
                     {"fault", fault}});
    if (!st.quads) {
      reasons += (reasons.empty() ? "" : "; ") + std::string("eigenfunction ") +
                 std::to_string(cand.k) + ": " + fault;
    }
  };
  for (int i : order) {
    attempt(i);
    if (st.quads) break;
  }
  if (!st.quads && unbuildable) {
    // None buildable: the first quad mesh, for the run to judge and report.
    Unbuildable& u = *unbuildable;
    st.phi = std::move(u.phi);
    st.complex = std::move(u.complex);
    st.refinements = u.refinements;
    st.doubled = u.doubled;
    st.primal = u.primal;
    st.dual = std::move(u.dual);
    st.base = std::move(u.base);
    step = std::move(u.step);
    chosen = u.candidate;
    st.quads = true;
  }
  const CriticalPoints& cp = chosen->critical;
  c.details["spectral"] = {
      {"laplacian", s.String("spectral.laplacian")},
      {"euler_characteristic", m.euler},
      {"selection", given > 0 ? "given" : "target"},
      {"target_charts", given > 0 ? 0 : target},
      {"candidates", given > 0 ? 1 : int(candidates.size())},
      {"tried", tried},
      {"eigenfunction", chosen->k},
      {"eigenvalue", chosen->eigenvalue},
      {"predicted_charts", SpectralCharts(cp)},
      {"critical",
       {{"maxima", cp.maxima},
        {"minima", cp.minima},
        {"saddles", cp.saddles},
        {"multi_saddles", cp.multi_saddles},
        {"euler_sum", cp.EulerSum()}}},
      {"complex", SqComplexDetails(st.complex, st.dual)},
      {"refinements", st.refinements},
      {"doubled", st.doubled},
      {"base", st.primal ? "complex" : "quasi_dual"},
      {"base_quads", st.base.quads.size()},
      {"base_irregular_vertices", st.base.irregular_vertices},
      {"seconds", {{"eigenpairs", seconds_eigen}, {"total", SqSecondsSince(t0)}}}};
  char line[512];
  std::snprintf(line, sizeof line,
                "spectral: eigenfunction %d (eigenvalue %.6g, %s), critical points max %d min %d "
                "saddles %d (%d multi); complex after cancellation: max %d min %d saddles %d, "
                "%zu cells, valid %s; quasi-dual %zu quads, %d irregular vertices%s\n",
                chosen->k, chosen->eigenvalue, given > 0 ? "given" : "chosen for the target",
                cp.maxima, cp.minima, cp.saddles, cp.multi_saddles, st.complex.maxima,
                st.complex.minima, st.complex.saddles, st.complex.cells.size(),
                st.complex.valid ? "yes" : "no", st.dual.quads.size(), st.dual.irregular_vertices,
                st.primal ? " (it repeats a corner: the complex's cells charted instead)" : "");
  c.net.headline = line;
  if (!st.quads) {
    c.missed = "no quad mesh: " + reasons +
               (given > 0 ? "" : " (another spectral.charts or spectral.persistence may give one)");
    return;
  }
  st.invalid = step.invalid;
  if (!st.doubled && int(step.result.irregular.size()) != st.base.irregular_vertices) {
    st.invalid += "the output has " + std::to_string(step.result.irregular.size()) +
                  " irregular vertices, the base complex " +
                  std::to_string(st.base.irregular_vertices) + "\n";
  }
  c.details["charts"] = std::move(step.details);
  c.net.headline += step.headline;
  c.net.derived = true;
  c.net.mesh = std::move(step.mesh);
  c.net.source.clear();  // output vertices are not input vertices
}

std::string SqInvalid(HookContext& c) { return c.State<SqState>().invalid; }

void SqWrite(HookContext& c) {
  const SqState& st = c.State<SqState>();
  for (const auto& [key, path] : c.temporaries) {
    const std::string name = "output." + key;
    if (key == "complex") {
      WriteTextFile(path, MorseSmaleArcsObj(st.complex), name);
    } else if (key == "quasi_dual") {
      WriteTextFile(path, QuasiDualObj(st.base), name);
    } else if (key == "function") {
      const std::vector<PlyValues> values = {{"phi", st.phi}};
      WriteMesh(path, st.design, nullptr, false, nullptr, &values);
    }
  }
}

void SqCheck(const Settings& s) {
  CheckQuadComplexChartKeys(s);
  if (s.Integer("spectral.eigenfunction") > 0 &&
      (s.Given("spectral.charts") || s.Number("spectral.chart_edge_length") > 0)) {
    throw s.Error("spectral.eigenfunction",
                  "give spectral.eigenfunction or a target (spectral.charts, "
                  "spectral.chart_edge_length), not both");
  }
  if (s.Given("spectral.charts") && s.Number("spectral.chart_edge_length") > 0) {
    throw s.Error("spectral.chart_edge_length",
                  "give spectral.charts or spectral.chart_edge_length, not both");
  }
  const std::string& function = s.String("output.function");
  const bool ply = function.size() >= 4 && function.substr(function.size() - 4) == ".ply";
  if (!function.empty() && !ply) {
    throw s.Error("output.function", "must be a .ply file (φ is a vertex property)");
  }
}

}  // namespace

ProblemDecl spectral_quads() {
  ProblemDecl d;
  d.name = "spectral_quads";
  d.summary = "Laplacian eigenfunction → Morse–Smale complex → quasi-dual → charts → all-quad mesh";
  d.paper = "[Gebreiter 2012, §6, §7, §4.1; Dong et al. 2006]";
  d.keys = {
      IntegerKey("spectral.eigenfunction", 0, 0, 100000000,
                 "K ≥ 1: eigenfunction K of the Laplacian (0 is the constant); 0: chosen "
                 "automatically for spectral.charts or spectral.chart_edge_length"),
      IntegerKey("spectral.charts", 24, 1, 100000000,
                 "automatic choice: the target number of charts (quads of the base complex, one "
                 "per saddle); the candidate nearest it whose complex is valid is taken"),
      NumberKey("spectral.chart_edge_length", 0, 0, kMaxCoordinate,
                "or the target chart edge in file units: charts = area / this²; 0 = "
                "spectral.charts"),
      IntegerKey("spectral.count", 50, 2, 100000000,
                 "automatic choice: eigenpairs computed, eigenfunctions 1 … count − 1 the "
                 "candidates (below the vertex count)"),
      ChoiceKey("spectral.laplacian", "cotangent", {"cotangent", "normalised"},
                "cotangent (B = vertex areas: the Laplace–Beltrami spectrum) or normalised "
                "(B_ii = Σ_k D_ik, Gebreiter §6.1.3)"),
      NumberKey("spectral.persistence", 0.02, 0, 2,
                "saddle–extremum pairs with |Δφ| ≤ this (φ scaled to max |φ| = 1) are "
                "cancelled")};
  for (Key& k : ChartKeys()) d.keys.push_back(std::move(k));
  d.check = &SqCheck;
  d.net = &SqNet;
  d.stages = &NetIsTheResult;
  d.invalid = &SqInvalid;
  d.output_keys = {"function", "complex", "quasi_dual"};
  d.write = &SqWrite;
  d.colors = "none";
  return d;
}

}  // namespace archgeo::problems
