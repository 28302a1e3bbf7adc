// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `wave_quads`: a standing wave on a surface whose iso-lines follow
// a guidance field and a size field, and the quad base complex its
// Morse–Smale complex gives [Gebreiter 2012, §8.3; Zhang et al. 2010].
//
// Variables: per vertex the 4-vector f_i = (cos θ cos φ, cos θ sin φ,
// sin θ cos φ, sin θ sin φ) (block wave_f, output). The thesis' energy
//   E = Σ_ij |P_ij f_j − C_ij f_i|² + w1 Σ_i (|f_i|² − 1)² + w2 Σ_i (f_iᵀ H f_i)²
// is wave_transfer + wave_norm + wave_product (w1 = w2 = 0.15), with the
// feature constraints of §8.3.2 (wave_feature, boundary vertices) as a
// strong penalty. The edge terms are linear in f, the penalties quartic: a
// Levenberg–Marquardt solve over f is well conditioned where a solve over the
// angles θ, φ would be periodic and non-convex in every residual.
//
// Guidance field: the principal curvature directions (X along k1), smoothed
// (wave.field_smoothing sweeps; problems/declarations/wave_field.h). Size
// fields μ (along X) and η (along Y): wave.wavelength (file units), constant
// or times the distance to the file's z axis (wave.size_field,
// wave.size_field_y). ω = 2π / μ: cos θ has period μ, so the extrema of
// cos θ cos φ lie μ/2 apart along X. With wave.curl_correction (§8.1.4) a
// stage `curl` first solves the log sizes (block wave_size) for the least
// curl of X/μ and Y/η (size_curl, size_target, size_smoothing;
// problems/declarations/wave_size_curl.h), and those sizes scale the
// transfer.
//
// Starts: the stage `restart` runs wave.restarts rounds, each from a new
// start (seed wave.seed + round): the fields integrated along a spanning
// tree from a random vertex with random angles there (wave.start
// integrated, problems/declarations/wave_start.h) or random angles at every
// vertex. After each round the Morse–Smale complex of cos θ cos φ
// (problems/declarations/surface_complex.h), pairs of persistence ≤
// wave.persistence cancelled, and its quasi-dual; the round kept is the one
// whose complex is a valid quad complex with the lowest E (none valid: the
// lowest E, measure wave_energy, and exit 4). The report counts the valid
// starts, critical points, cells and irregular vertices. Outputs:
// output.complex (OBJ lines), output.quasi_dual (OBJ), wave_f in the
// output PLY, and output.quads: the quasi-dual as a base complex (of a
// surface with boundary, its half on the surface, HalfBaseComplex) →
// charts → the all-quad mesh (the step of base_complex_quads,
// problems/declarations/base_complex_input.h; its figures in
// details.charts; a step that fails or gives an invalid mesh is a missed
// goal, exit 4).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "core/problem.h"
#include "energies/size_elements.h"
#include "energies/wave_elements.h"
#include "energies/wave_feature.h"
#include "energies/wave_norm.h"
#include "energies/wave_product.h"
#include "energies/wave_transfer.h"
#include "io/output_files.h"
#include "mesh/eigen_point.h"
#include "io/io.h"
#include "problems/declarations/base_complex_input.h"
#include "problems/declarations/surface_complex.h"
#include "problems/declarations/wave_field.h"
#include "problems/declarations/wave_size_curl.h"
#include "problems/declarations/wave_start.h"
#include "problems/runtime/model.h"

namespace archgeo::problems {
namespace {

namespace wd = wave_data;
namespace sd = size_data;

struct WaveState : ProblemState {
  ElementSet edges, vertices, features;
  int restart = 0;
  std::shared_ptr<const SurfaceComplex> complex;
  // Per start (round): whether its complex was valid; the valid start of
  // lowest E, its wave and its complex.
  std::vector<bool> valid_starts;
  std::vector<double> start_energies;
  int best_valid = 0;  // 1-based start, 0 = none
  std::vector<double> best_valid_f;
  std::shared_ptr<const SurfaceComplex> best_valid_complex;
  double seconds_field = 0, seconds_start = 0, seconds_complex = 0;
  // The size fields: the guidance field, the designated sizes (canonical),
  // the sizes the wave uses (corrected with wave.curl_correction) and the
  // curl of the phase gradient with each.
  WaveFrames frames;
  std::vector<double> mu, eta, mu_used, eta_used;
  WaveSizeCurl curl_target, curl_used;
  double seconds_curl = 0;
  Mesh quads;  // output.quads: the kept complex's quasi-dual through the charts
};

double WaveSecondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

WaveState& WaveSt(HookContext& c) { return c.State<WaveState>(); }

// The start of restart `restart` (seed wave.seed + restart): uniformly
// random angles θ, φ per vertex (wave.start random), or the fields
// integrated from a random root vertex with random angles there
// (integrated, problems/declarations/wave_start.h).
void WaveRandomise(HookContext& c, int restart) {
  const auto t0 = std::chrono::steady_clock::now();
  std::mt19937 rng(unsigned(c.settings->Integer("wave.seed") + restart));
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI);
  const int n = int(c.store->mesh().number_of_vertices());
  std::vector<double> f;
  if (c.settings->String("wave.start") == "integrated") {
    const int root = std::uniform_int_distribution<int>(0, n - 1)(rng);
    const double t = angle(rng), p = angle(rng);
    f = IntegratedWave(WaveSt(c).edges, n, root, t, p);
  } else {
    for (int v = 0; v < n; ++v) {
      const double t = angle(rng), p = angle(rng);
      f.insert(f.end(), {std::cos(t) * std::cos(p), std::cos(t) * std::sin(p),
                         std::sin(t) * std::cos(p), std::sin(t) * std::sin(p)});
    }
  }
  for (int v = 0; v < n; ++v) {
    for (int k = 0; k < 4; ++k) c.store->At("wave_f", v)[k] = f[4 * size_t(v) + size_t(k)];
  }
  WaveSt(c).seconds_start += WaveSecondsSince(t0);
}

// The size field of `key` per vertex (canonical lengths).
std::vector<double> WaveSizes(HookContext& c, const std::string& key, double wavelength) {
  const Settings& s = *c.settings;
  const Mesh& file = *c.input;
  std::vector<double> out(file.number_of_vertices(), wavelength);
  if (s.String(key) == "axis_distance") {
    for (VertexIndex v : file.vertices()) {
      const Eigen::Vector3d p = EigenPoint(file, v);
      out[v.idx()] = wavelength * std::hypot(p.x(), p.y());
    }
  }
  for (double& x : out) {
    if (!(x > 0) || !std::isfinite(x)) {
      throw s.Error(key, "the size field must be > 0 at every vertex (a vertex on the z axis "
                         "has distance 0)");
    }
    x /= c.frame.scale;
  }
  return out;
}

// The curl correction's element sets (empty when wave.curl_correction is
// off) and the designated sizes' curl; the log sizes start at the
// designated ones (the solve's relative function tolerance would stop the
// nearly free constant mode short of them from another start).
void InitWaveSizes(HookContext& c) {
  WaveState& st = WaveSt(c);
  const auto t0 = std::chrono::steady_clock::now();
  const Mesh& mesh = c.store->mesh();
  WaveSizeSets sets;
  if (c.settings->String("wave.curl_correction") == "on") {
    sets = WaveSizeCurlSets(mesh, st.frames, st.mu, st.eta);
  }
  sets.triangles.site = Site::kFace;
  sets.triangles.data_width = sd::kTriangleWidth;
  sets.vertices.site = Site::kVertex;
  sets.vertices.data_width = sd::kVertexWidth;
  sets.edges.site = Site::kEdge;
  sets.edges.data_width = sd::kEdgeWidth;
  c.SetElements("size_triangles", sets.triangles);
  c.SetElements("size_vertices", sets.vertices);
  c.SetElements("size_edges", sets.edges);
  for (int v = 0; v < int(mesh.number_of_vertices()); ++v) {
    c.store->At("wave_size", v)[0] = std::log(st.mu[size_t(v)]);
    c.store->At("wave_size", v)[1] = std::log(st.eta[size_t(v)]);
  }
  st.curl_target = st.curl_used = MeasureWaveSizeCurl(mesh, st.frames, st.mu, st.eta);
  st.seconds_curl = WaveSecondsSince(t0);
}

// After the curl correction's stage: the sizes e^μ̃, e^η̃ scale the transfer
// (the wave_edges' α, β), their curl, and the first start.
void WaveSizesSolved(HookContext& c) {
  WaveState& st = WaveSt(c);
  const auto t0 = std::chrono::steady_clock::now();
  const Mesh& mesh = c.store->mesh();
  for (int v = 0; v < int(mesh.number_of_vertices()); ++v) {
    st.mu_used[size_t(v)] = std::exp(c.store->At("wave_size", v)[0]);
    st.eta_used[size_t(v)] = std::exp(c.store->At("wave_size", v)[1]);
  }
  st.edges = WaveEdges(mesh, st.frames, st.mu_used, st.eta_used);
  c.SetElements("wave_edges", st.edges);
  st.curl_used = MeasureWaveSizeCurl(mesh, st.frames, st.mu_used, st.eta_used);
  st.seconds_curl += WaveSecondsSince(t0);
  WaveRandomise(c, 0);
}

// The range of used / designated sizes.
std::pair<double, double> WaveSizeRatios(const std::vector<double>& used,
                                         const std::vector<double>& target) {
  if (used.empty()) return {1, 1};
  double lo = used[0] / target[0], hi = lo;
  for (size_t v = 1; v < used.size(); ++v) {
    lo = std::min(lo, used[v] / target[v]);
    hi = std::max(hi, used[v] / target[v]);
  }
  return {lo, hi};
}

nlohmann::json WaveCurlDetails(HookContext& c) {
  const WaveState& st = WaveSt(c);
  const auto mu = WaveSizeRatios(st.mu_used, st.mu), eta = WaveSizeRatios(st.eta_used, st.eta);
  return {{"correction", c.settings->String("wave.curl_correction") == "on"},
          {"curl_x_target", st.curl_target.x},
          {"curl_y_target", st.curl_target.y},
          {"curl_x", st.curl_used.x},
          {"curl_y", st.curl_used.y},
          {"mu_ratio_min", mu.first},
          {"mu_ratio_max", mu.second},
          {"eta_ratio_min", eta.first},
          {"eta_ratio_max", eta.second},
          {"seconds", st.seconds_curl}};
}

void InitWave(HookContext& c) {
  WaveState& st = WaveSt(c);
  st = WaveState{};
  const auto t0 = std::chrono::steady_clock::now();
  const Settings& s = *c.settings;
  const Mesh& mesh = c.store->mesh();
  double wavelength = s.Number("wave.wavelength");
  if (wavelength == 0) wavelength = 12 * c.frame.scale;  // 12 mean edge lengths
  double wavelength_y = s.Number("wave.wavelength_y");
  if (wavelength_y == 0) wavelength_y = wavelength;
  const std::vector<double> mu = WaveSizes(c, "wave.size_field", wavelength);
  const std::vector<double> eta = WaveSizes(c, "wave.size_field_y", wavelength_y);
  st.frames = PrincipalWaveFrames(mesh, int(s.Integer("wave.field_smoothing")));
  const WaveFrames& frames = st.frames;
  st.mu = st.mu_used = mu;
  st.eta = st.eta_used = eta;
  st.edges = WaveEdges(mesh, frames, mu, eta);
  st.vertices = WaveVertices(mesh);
  st.features = s.String("wave.features") == "boundary"
                    ? WaveFeatures(mesh, frames, s.Number("wave.corner_angle"))
                    : ElementSet{};
  st.features.site = Site::kVertex;
  st.features.data_width = wd::kFeatureWidth;
  c.SetElements("wave_edges", st.edges);
  c.SetElements("wave_vertices", st.vertices);
  c.SetElements("wave_features", st.features);
  st.seconds_field = WaveSecondsSince(t0);
  InitWaveSizes(c);
  // With the curl correction the start follows its stage (WaveSizesSolved).
  if (s.String("wave.curl_correction") == "off") WaveRandomise(c, 0);
}

void WaveNextRestart(HookContext& c) {
  WaveState& st = WaveSt(c);
  if (st.restart > 0) WaveRandomise(c, st.restart);
  ++st.restart;
}

double WaveSquares(const double* r, int n) {
  double sum = 0;
  for (int k = 0; k < n; ++k) sum += r[k] * r[k];
  return sum;
}

// E = Σ w_t |r|² over the four terms, at their weights (measure wave_energy).
double WaveEnergy(HookContext& c) {
  const WaveState& st = WaveSt(c);
  const Settings& s = *c.settings;
  double e = 0, r[4];
  auto f = [&](int v) { return c.store->At("wave_f", v); };
  const double wt = s.Number("terms.wave_transfer.weight");
  for (size_t k = 0; k < st.edges.size(); ++k) {
    const double* d = st.edges.Data(k);
    const int* v = st.edges.Vertices(k);
    WaveTransfer(d[wd::kAlpha], d[wd::kBeta], int(d[wd::kSourceTheta]), d[wd::kSignTheta],
                 int(d[wd::kSourcePhi]), d[wd::kSignPhi])(f(v[0]), f(v[1]), r);
    e += wt * WaveSquares(r, 4);
  }
  const double wn = s.Number("terms.wave_norm.weight"), wp = s.Number("terms.wave_product.weight");
  for (size_t k = 0; k < st.vertices.size(); ++k) {
    const double* x = f(st.vertices.Vertices(k)[0]);
    WaveNorm()(x, r);
    e += wn * r[0] * r[0];
    WaveProduct()(x, r);
    e += wp * r[0] * r[0];
  }
  const double wf = s.Number("terms.wave_feature.weight");
  for (size_t k = 0; k < st.features.size(); ++k) {
    WaveFeature(int(st.features.Data(k)[wd::kKind]))(f(st.features.Vertices(k)[0]), r);
    e += wf * WaveSquares(r, 3);
  }
  return e;
}

// max over feature vertices of |sin φ| (or |sin θ|; corners both).
double WaveFeatureMax(HookContext& c) {
  const WaveState& st = WaveSt(c);
  double worst = 0;
  for (size_t k = 0; k < st.features.size(); ++k) {
    const double* f = c.store->At("wave_f", st.features.Vertices(k)[0]);
    const double norm2 = std::max(WaveSquares(f, 4), 1e-300);
    const double sin_phi = std::sqrt((f[1] * f[1] + f[3] * f[3]) / norm2);
    const double sin_theta = std::sqrt((f[2] * f[2] + f[3] * f[3]) / norm2);
    const int kind = int(st.features.Data(k)[wd::kKind]);
    worst = std::max(worst, kind == wd::kSinPhi     ? sin_phi
                            : kind == wd::kSinTheta ? sin_theta
                                                    : std::max(sin_phi, sin_theta));
  }
  return worst;
}

// The Morse–Smale complex of the current wave's first component.
std::shared_ptr<const SurfaceComplex> WaveBuild(HookContext& c) {
  const auto t0 = std::chrono::steady_clock::now();
  const Mesh& mesh = *c.input;
  Eigen::VectorXd wave(Eigen::Index(mesh.number_of_vertices()));
  for (Eigen::Index v = 0; v < wave.size(); ++v) wave[v] = c.store->At("wave_f", int(v))[0];
  MorseSmaleOptions options;
  options.persistence = c.settings->Number("wave.persistence");
  auto complex = std::make_shared<SurfaceComplex>(BuildSurfaceComplex(mesh, wave, options));
  WaveSt(c).seconds_complex += WaveSecondsSince(t0);
  return complex;
}

// After each start: its complex; the valid start of lowest E is kept
// (KeptWaveStart).
void WaveAfterStart(HookContext& c) {
  WaveState& st = WaveSt(c);
  const std::shared_ptr<const SurfaceComplex> complex = WaveBuild(c);
  st.valid_starts.push_back(complex->built && complex->complex.valid);
  st.start_energies.push_back(WaveEnergy(c));
  const int kept = KeptWaveStart(st.valid_starts, st.start_energies);
  if (kept == st.best_valid) return;
  st.best_valid = kept;
  st.best_valid_complex = complex;
  const int n = int(c.store->mesh().number_of_vertices());
  st.best_valid_f.clear();
  for (int v = 0; v < n; ++v) {
    const double* f = c.store->At("wave_f", v);
    st.best_valid_f.insert(st.best_valid_f.end(), f, f + wd::kWidth);
  }
}

// 1 when the last start's complex was valid (measure wave_valid).
double WaveLastValid(HookContext& c) {
  const WaveState& st = WaveSt(c);
  return !st.valid_starts.empty() && st.valid_starts.back() ? 1 : 0;
}

// The result: the valid start of lowest E, or (none valid) the start of
// lowest E the stage kept.
void WaveKeepResult(HookContext& c) {
  WaveState& st = WaveSt(c);
  if (st.best_valid == 0) {
    st.complex = WaveBuild(c);
    return;
  }
  const int n = int(c.store->mesh().number_of_vertices());
  for (int v = 0; v < n; ++v) {
    for (int k = 0; k < wd::kWidth; ++k) {
      c.store->At("wave_f", v)[k] = st.best_valid_f[size_t(wd::kWidth * v + k)];
    }
  }
  st.complex = st.best_valid_complex;
}

// output.quads: the kept complex's quasi-dual as a base complex → charts →
// the all-quad mesh (the step of base_complex_quads); a step that fails or
// gives an invalid mesh is a missed goal.
void WaveQuads(HookContext& c) {
  WaveState& st = WaveSt(c);
  const SurfaceComplex& w = *st.complex;
  const QuadBaseComplex& q = w.quasi_dual;
  // A surface with boundary: its own base complex (HalfBaseComplex, which
  // judges its corners), charted on the surface.
  if (!w.doubled && (q.degenerate_quads > 0 || q.missing_saddles > 0)) {
    c.missed = "output.quads: the quasi-dual has " + std::to_string(q.degenerate_quads) +
               " quads with a repeated corner and " + std::to_string(q.missing_saddles) +
               " saddles without all their arcs";
    return;
  }
  ChartStep step;
  try {
    step = w.doubled ? RunChartStep(*c.settings, *c.input, w.half_points, w.half_triangles,
                                    HalfBaseComplex(w), true)
                     : RunChartStep(*c.settings, *c.input, w.points, w.triangles,
                                    QuasiDualBaseComplex(q), true);
  } catch (const std::exception& e) {  // BaseComplexError, a failed factorisation
    c.missed = std::string("output.quads: the charts of the quasi-dual fail: ") + e.what();
    return;
  }
  c.details["charts"] = std::move(step.details);
  c.headline += step.headline;
  if (!step.invalid.empty()) c.missed = "output.quads: " + step.invalid;
  st.quads = std::move(step.mesh);
}

void FinishWave(HookContext& c) {
  WaveState& st = WaveSt(c);
  WaveKeepResult(c);
  const std::shared_ptr<const SurfaceComplex> complex = st.complex;
  const MorseSmaleComplex& m = complex->complex;
  const QuadBaseComplex& q = complex->quasi_dual;
  int irregular_nodes = 0;  // extrema of the complex whose valence (arcs) is not 4
  {
    std::vector<int> valence(m.nodes.size(), 0);
    for (const MorseSmaleArc& a : m.arcs) ++valence[size_t(a.extremum)];
    for (size_t k = 0; k < m.nodes.size(); ++k) {
      if (m.nodes[k].kind != 0 && valence[k] != 4) ++irregular_nodes;
    }
  }
  c.details["wave"] = {
      {"energy", WaveEnergy(c)},
      {"feature_vertices", st.features.size()},
      {"feature_sin_max", WaveFeatureMax(c)},
      {"restarts", st.restart},
      {"curl", WaveCurlDetails(c)},
      {"valid_starts", std::count(st.valid_starts.begin(), st.valid_starts.end(), true)},
      {"kept_start", st.best_valid},
      {"seconds",
       {{"field", st.seconds_field}, {"start", st.seconds_start}, {"complex", st.seconds_complex}}},
      {"doubled", complex->doubled},
      {"complex_built", complex->built},
      {"complex_error", complex->error},
      {"maxima", m.maxima},
      {"minima", m.minima},
      {"saddles", m.saddles},
      {"cancelled", m.cancelled},
      {"arcs", m.arcs.size()},
      {"unresolved_arcs", m.unresolved},
      {"refinements", complex->refinements},
      {"cells", m.cells.size()},
      {"invalid_cells", m.invalid_cells},
      {"valid", complex->built && m.valid},
      {"irregular_vertices", irregular_nodes},
      {"quasi_dual",
       {{"vertices", q.points.size()},
        {"quads", q.quads.size()},
        {"degenerate_quads", q.degenerate_quads},
        {"irregular_vertices", q.irregular_vertices},
        {"euler", q.euler}}}};
  char line[512];
  std::snprintf(line, sizeof line,
                "wave: E %.6g, boundary |sin| max %.2e; complex%s: max %d min %d saddles %d, "
                "%zu cells (%d invalid), valid %s, irregular extrema %d; quasi-dual %zu quads, "
                "%d irregular vertices\n",
                WaveEnergy(c), WaveFeatureMax(c), complex->doubled ? " (doubled surface)" : "",
                m.maxima, m.minima, m.saddles, m.cells.size(), m.invalid_cells,
                complex->built && m.valid ? "yes" : "no", irregular_nodes, q.quads.size(),
                q.irregular_vertices);
  c.headline += line;
  if (!complex->built) c.headline += "wave: no complex: " + complex->error + "\n";
  if (!c.settings->String("output.quads").empty() && complex->built && m.valid) WaveQuads(c);
  // The quad base complex is this problem's result: without it the run
  // has not reached its goal (exit 4), whatever the wave's energy.
  if (!complex->built) {
    c.missed = "the wave's Morse–Smale complex could not be built: " + complex->error;
  } else if (!m.valid) {
    c.missed = "the wave's Morse–Smale complex is not a valid quad complex in any of the " +
               std::to_string(st.valid_starts.size()) + " starts (the kept one, of lowest E: " +
               std::to_string(m.invalid_cells) + " invalid cells, " +
               std::to_string(m.unresolved) + " arcs not placed); other seeds " +
               "(wave.seed) or more starts (wave.restarts) may give one";
  }
}

void WriteWave(HookContext& c) {
  const WaveState& st = WaveSt(c);
  const auto quads = c.temporaries.find("quads");
  // Empty when the goal was missed (exit 4 says why).
  if (quads != c.temporaries.end()) WriteMesh(quads->second, st.quads);
  for (const char* key : {"complex", "quasi_dual"}) {
    const auto it = c.temporaries.find(key);
    if (it == c.temporaries.end()) continue;
    if (!st.complex || !st.complex->built) {
      throw c.settings->Error(std::string("output.") + key,
                              "no complex to write: " + (st.complex ? st.complex->error : ""));
    }
    WriteTextFile(it->second,
                  std::string(key) == "complex"
                      ? SurfaceComplexArcsObj(*st.complex, "the standing wave cos(theta) cos(phi)")
                      : SurfaceQuasiDualObj(*st.complex),
                  std::string("output.") + key);
  }
}

std::vector<Key> WaveKeys() {
  return {
      NumberKey("wave.wavelength", 0, 0, 1e12,
                "wavelength μ of cos θ along the field's X (file units; with size_field "
                "axis_distance: per unit distance to the z axis); the extrema lie μ/2 apart; "
                "0 = 12 mean edge lengths"),
      NumberKey("wave.wavelength_y", 0, 0, 1e12,
                "wavelength η of cos φ along Y (as wave.wavelength); 0 = wave.wavelength"),
      ChoiceKey("wave.size_field", "constant", {"constant", "axis_distance"},
                "μ per vertex: constant, or wave.wavelength × the vertex's distance to the "
                "file's z axis (a torus about z: wave.wavelength = 2π/N gives N waves around)"),
      ChoiceKey("wave.size_field_y", "constant", {"constant", "axis_distance"},
                "η per vertex, as wave.size_field"),
      ChoiceKey("wave.curl_correction", "on", {"off", "on"},
                "curl correction of the size fields (Gebreiter 2012, §8.1.4): before the "
                "wave, log μ and log η per vertex minimise the curl of X/μ and Y/η "
                "(size_curl) held to the designated sizes (size_target) and smooth "
                "(size_smoothing); the corrected sizes scale the transfer. off: the "
                "designated sizes as they are (a known curl-free size field)"),
      IntegerKey("wave.curl_rounds", 1, 1, 100,
                 "solves of the curl correction (a linear least squares: one solves it)"),
      IntegerKey("wave.field_smoothing", 200, 0, 10000,
                 "sweeps of 4-RoSy smoothing of the principal field (each vertex's own "
                 "direction weighted by its anisotropy |k1 − k2|, its neighbours' transported "
                 "into its tangent plane): propagates the field into umbilic regions and "
                 "simplifies it"),
      ChoiceKey("wave.features", "boundary", {"boundary", "none"},
                "feature constraints: boundary vertices sin φ = 0 or sin θ = 0 (by the field "
                "direction closer to the boundary), corners both"),
      NumberKey("wave.corner_angle", 45, 0, 180,
                "a boundary vertex where the boundary turns by more than this (degrees) is a "
                "corner"),
      ChoiceKey("wave.start", "integrated", {"integrated", "random"},
                "each start: the guidance and size fields integrated along a breadth-first "
                "spanning tree from a random vertex with random angles there (integrated), or "
                "independent random angles at every vertex (random)"),
      IntegerKey("wave.restarts", 1, 1, 1000,
                 "solves from independent random starts (wave.start); the one whose complex is "
                 "a valid quad complex with the lowest energy E is kept (none valid: the lowest "
                 "E)"),
      IntegerKey("wave.seed", 1, 0, 2147483647, "seed of the first random initialisation"),
      NumberKey("wave.persistence", 0.05, 0, 2,
                "saddle–extremum pairs of the complex with |Δ cos θ cos φ| ≤ this are "
                "cancelled")};
}

}  // namespace

ProblemDecl wave_quads() {
  ProblemDecl d;
  d.name = "wave_quads";
  d.summary = "standing wave along the principal field and size field, its Morse–Smale "
              "complex and quad base complex (quasi-dual)";
  d.paper = "[Gebreiter 2012, §8.3; Zhang et al. 2010]";
  d.terms = {{"wave_transfer", 1}, {"wave_norm", 0.15}, {"wave_product", 0.15},
             {"wave_feature", 1e8}, {"size_curl", 1}, {"size_target", 1e-3},
             {"size_smoothing", 1e-2}};
  // The complex needs the wave's shape, not its last digits: a solve ends
  // when an iteration lowers E by less than 1e-4 of it. Each step is one
  // CHOLMOD factorisation by LeanSolve (core/lean_solve.h): Ceres' own
  // step, to the same E, without its per-solve set-up.
  d.defaults = {{"solver.max_num_iterations", 100LL},
                {"solver.function_tolerance", 1e-4},
                {"solver.back_end", std::string("lean")},
                {"solver.ordering", std::string("metis")}};
  d.keys = WaveKeys();
  for (Key& k : ChartKeys()) d.keys.push_back(std::move(k));
  d.check = &CheckQuadComplexChartKeys;
  d.blocks = {{"wave_f", Site::kVertex, wd::kWidth, FrameMap::kInvariant, false,
               Carry::kReinitialise, true, false,
               "the standing wave's 4-vector (cos θ cos φ, cos θ sin φ, sin θ cos φ, "
               "sin θ sin φ) per vertex"},
              {"wave_size", Site::kVertex, sd::kWidth, FrameMap::kInvariant, false,
               Carry::kReinitialise, false, false,
               "the log sizes (log μ, log η) of the curl correction per vertex (canonical "
               "lengths)"}};
  d.init = &InitWave;
  d.stages = [](const Settings& s) {
    std::vector<Stage> stages;
    if (s.String("wave.curl_correction") == "on") {
      Stage sizes;
      sizes.name = "curl";
      sizes.terms = {"size_curl", "size_target", "size_smoothing"};
      sizes.rounds_key = "wave.curl_rounds";
      sizes.after_round = &WaveSizesSolved;
      stages.push_back(sizes);
    }
    Stage restart;
    restart.terms = {"wave_transfer", "wave_norm", "wave_product", "wave_feature"};
    restart.name = "restart";
    restart.rounds_key = "wave.restarts";
    restart.keep_best = "wave_energy";  // the result when no start is valid
    restart.before_round = &WaveNextRestart;
    restart.after_round = &WaveAfterStart;
    restart.logged = {"wave_energy", "wave_feature_max", "wave_valid"};
    stages.push_back(restart);
    return stages;
  };
  d.measures["wave_energy"] = &WaveEnergy;
  d.measures["wave_feature_max"] = &WaveFeatureMax;
  d.measures["wave_valid"] = &WaveLastValid;
  d.finish = &FinishWave;
  d.output_keys = {"complex", "quasi_dual", "quads"};
  d.write = &WriteWave;
  d.colors = "none";
  return d;
}

}  // namespace archgeo::problems
