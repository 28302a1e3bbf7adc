// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `hnet`: optimise a quad mesh towards an A-net and extend it to a
// smooth hyperbolic net (H-net) of rational bilinear patches [Shi, Wang,
// Pottmann 2014, §3.2, Fig. 4, Table 1].
//
// Pipeline (Fig. 4), in the canonical frame (unit mean edge length, so every
// weight is unit-free):
//  step 1 ("A-net" stage)  F_anet = Σ F_p + λ1 F_fairness + λ2 F_prox [eq. 10]:
//          anet_planarity, fairness (third differences along the mesh
//          polylines by default), boundary_proximity, proximity, anchor; rounds
//          until the star planarity (max distance of a neighbour from the
//          star's least-squares plane over the star's mean edge length) is ≤
//          hnet.star_planarity, at most schedule.outer_iterations; a round
//          above it multiplies the planarity weights by
//          hnet.continuation_factor;
//  step 2  the H-net of the current vertices (geometry/hnet.h BuildHNet): W by
//          eq. 7 (hnet.shape_parameters: least squares over every edge, or
//          the paper's propagation from hnet.start_face), the common scale λ
//          from the quartic of eq. 11, the kink angles α (hnet.kink_samples
//          points per edge);
//  step 3 ("frame" stage)  F_anet + λ3 Σ_edges F_quad(b0, f1, b3, f4) with the
//          shape parameters of step 2 FIXED (frame_coplanarity; the block
//          frame_weights holds them per edge, NaN where no smooth join exists:
//          not-equitwist edges, edges between W components);
//  steps 3 and 2 alternate at most hnet.alternations times, until α_max ≤
//  hnet.alpha_max and the star planarity ≤ hnet.star_planarity (no round at
//  all when step 1 already meets both). A step-3 round after which α_max is
//  larger than before it is undone and ends the alternation. On nets with
//  holes the paper's propagated W disagrees across the edges that close a
//  loop around a hole (by a factor of 2.3 on the negshell's A-net), and the
//  frame terms are then met only by degenerate patches; the least-squares W
//  spreads that holonomy over every edge around the hole (α_max 3.16° →
//  0.20° on the same net before step 3), and step 3 lowers it further.
//
// A-net planarity of boundary vertices: a boundary vertex of valence ≥ 3 gets
// its open star (its tangent plane is shared by the patches of the interior
// edges ending there); corners (valence 2) get none.
//
// hnet.net: auto | mesh | diagonal_0 | diagonal_1 — the net solved: the input
// or one of its diagonal nets (problems/declarations/hnet_net.h; ArchGeo and DOS store an
// A-net along the diagonals of a quad mesh). auto picks a diagonal net whose
// stars are 10× flatter on average. Inputs must be pure quad meshes. Odd
// interior valences, not-equitwist edges, a non-bipartite vertex graph and
// closing edges are optimised beyond the theory, as the paper does, and
// reported with their honest kinks.
//
// Outputs: output.mesh (faces coloured by their largest kink, red at 1°),
// output.patchwork (the patches sampled n × n with normals and isophote
// bands, PLY) and output.rulings (OBJ polylines), in file units.
//
// Weights were chosen by experiment on the test nets of generators/asymptotic_nets.h
// and the negshell A-net of ../shared/data (benchmarks/shi_table1.cpp). The
// paper's Table 1 uses λ1 ≈ 0.4–0.86, λ2 ≈ 0.02–0.12, λ3 ≈ 0.6 in its own
// (unstated) normalisation; here the planarity terms are normalised by the
// star's mean edge length and grow by continuation instead.
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/problem.h"
#include "geometry/hnet.h"
#include "geometry/patchwork_io.h"
#include "problems/declarations/design_band.h"
#include "problems/declarations/hnet_net.h"
#include "problems/runtime/model.h"
#include "problems/declarations/suitability.h"

namespace archgeo::problems {
namespace {

// Eq. 7 mismatch on an edge the W propagation did not cross above which the
// net is reported as not closing (a hole or non-planar stars).
constexpr double kClosingMismatch = 1e-6;

struct Current : ProblemState {
  long version = -1;
  HNet hnet;
};

// The H-net of the current state (built once per state).
const HNet& CurrentHNet(HookContext& c) {
  Current& cur = c.State<Current>();
  if (cur.version != c.version) {
    cur.hnet = BuildHNet(c.store->mesh(), HNetOptionsOf(*c.settings));
    cur.version = c.version;
  }
  return cur.hnet;
}

// The face's shape parameter for its diagonal through vertex v (eq. 4).
double ShapeThrough(const HNet& hnet, int face, int v) {
  const auto& c = hnet.patch_vertices[face];
  const bool on = c[0] == v || c[2] == v;
  return on ? hnet.W[face] : 1.0 / hnet.W[face];
}

// Step 2 for the coming step-3 round: the frame weights of every edge.
void FrameWeights(HookContext& c) {
  const HNet hnet = CurrentHNet(c);
  Store& st = *c.store;
  const Mesh& mesh = st.mesh();
  const ElementSet& edges = c.model->Elements("edge_quads");
  for (size_t i = 0; i < edges.size(); ++i) {
    const int e = edges.edge[i];
    double* w = st.At("frame_weights", e);
    const int left = edges.face[i], right = edges.other_face[i];
    if (hnet.join[e] != EdgeJoin::kEquitwist || hnet.component[left] != hnet.component[right]) {
      w[0] = w[1] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    const int b0 = edges.Vertices(i)[0];
    w[0] = ShapeThrough(hnet, left, b0);   // diagonal b0b2
    w[1] = ShapeThrough(hnet, right, b0);  // diagonal b0b4
  }
  (void)mesh;
}

nlohmann::json HNetJson(const HNet& h) {
  return {{"star_planarity_max", h.star_planarity_max},
          {"star_planarity_mean", h.star_planarity_mean},
          {"alpha_max", h.kink_max},
          {"alpha_mean", h.kink_mean},
          {"W_min", h.W_min},
          {"W_max", h.W_max},
          {"lambda", h.lambda},
          {"odd_valence_vertices", h.odd_valence_vertices.size()},
          {"not_equitwist_edges", h.not_equitwist_edges.size()},
          {"closing_edges", h.closing_edges.size()},
          {"components", h.lambda_of_component.size()},
          {"bipartite", h.bipartite},
          {"mismatch_max", h.mismatch_max}};
}

void FinishHNet(HookContext& c) {
  const HNet& h = CurrentHNet(c);
  const nlohmann::json summary = HNetJson(h);
  for (const auto& [k, v] : summary.items()) c.details[k] = v;
  char line[512];
  std::snprintf(line, sizeof line,
                "H-net: star planarity max %.3e, α_max %.4f°, α_mean %.4f°, W in [%.4g, %.4g], "
                "λ %.4g\n",
                h.star_planarity_max, h.kink_max, h.kink_mean, h.W_min, h.W_max, h.lambda);
  c.headline += line;
  if (!h.odd_valence_vertices.empty() || !h.not_equitwist_edges.empty() || !h.bipartite ||
      h.mismatch_max > kClosingMismatch || h.lambda_of_component.size() > 1) {
    const bool propagated = HNetOptionsOf(*c.settings).shape == HNetShape::kPropagated;
    char where[96];
    std::snprintf(where, sizeof where, propagated ? "on the %zu edges W was not propagated across"
                                                  : "(W by least squares over every edge)",
                  h.closing_edges.size());
    std::snprintf(line, sizeof line,
                  "H-net beyond Theorem 4 (kinks above are honest): %zu odd interior "
                  "valences, %zu not-equitwist edges, %s, eq. 7 mismatch up to %.3e %s, "
                  "%zu W components\n",
                  h.odd_valence_vertices.size(), h.not_equitwist_edges.size(),
                  h.bipartite ? "bipartite" : "NOT bipartite", h.mismatch_max, where,
                  h.lambda_of_component.size());
    c.headline += line;
  }
}

void WriteHNet(HookContext& c) {
  const Settings& s = *c.settings;
  const Mesh& output = *c.output;
  const HNet h = BuildHNet(output, HNetOptionsOf(s));
  if (c.temporaries.count("patchwork")) {
    const int samples = int(s.Integer("patchwork.samples"));
    const SampledPatchwork patchwork = SamplePatchwork(output, h, samples);
    std::vector<std::array<unsigned char, 3>> colors;
    const double band = s.Number("patchwork.isophotes.band_degrees");
    if (band > 0) {
      const std::vector<double> d = s.Numbers("patchwork.isophotes.direction");
      colors = IsophoteColors(IsophoteAngles(patchwork.normals, Vec3{d[0], d[1], d[2]}), band);
    }
    WritePatchworkPly(c.temporaries.at("patchwork"), patchwork, colors, s.Bool("patchwork.ascii"));
    c.details["patchwork"] = {{"samples", samples},
                              {"vertices", patchwork.positions.size()},
                              {"triangles", patchwork.triangles.size()},
                              {"isophotes", band > 0}};
  }
  if (c.temporaries.count("rulings")) {
    const int per_family = int(s.Integer("rulings.per_family"));
    const Polylines rulings = PatchRulings(output, h, per_family, 2);
    WritePolylinesObj(c.temporaries.at("rulings"), rulings.lines);
    c.details["rulings"] = {{"per_family", per_family}, {"lines", rulings.lines.size()}};
  }
}

}  // namespace

ProblemDecl hnet() {
  ProblemDecl d;
  d.name = "hnet";
  d.summary = "A-net, then a smooth skin of ruled rational bilinear patches (H-net)";
  d.paper = "[Shi, Wang, Pottmann 2014, §3.2, Fig. 4, Table 1]";
  // Each step one CHOLMOD factorisation by LeanSolve (core/lean_solve.h): the
  // same rounds and objective as Ceres' steps, without their per-solve set-up.
  d.defaults = {{"solver.back_end", std::string("lean")}};
  d.input = InputKind::kQuads;
  d.terms = {{"anet_planarity", 10, {{"variant", std::string("normals")}}},
             {"boundary_proximity", 1},
             {"proximity", 1, {{"point_weight", 0.1}}},
             {"anchor", 0.1},
             {"fairness", 0.01, {{"relative_to_original", false}}, "polyline_quadruples"},
             {"frame_coplanarity", 10},
             {"min_edge_length", 1000, {}, "", true},
             {"convexity", 1000, {}, "", true}};
  d.blocks = {{"frame_weights", Site::kEdge, 2, FrameMap::kInvariant, false, Carry::kReinitialise,
               false, true, "the shape parameters (W_l, W_r) step 3 holds fixed at an edge"}};
  Key direction;
  direction.name = "patchwork.isophotes.direction";
  direction.type = Type::kNumbers;
  direction.size = 3;
  direction.fallback = std::vector<double>{0, 0, 1};
  direction.lo = -1e12;
  direction.hi = 1e12;
  direction.doc = "light direction of the isophote bands (not zero)";
  d.keys = {
      ChoiceKey("hnet.net", "auto", {"auto", "mesh", "diagonal_0", "diagonal_1"},
                "the net solved: the input, one of its diagonal nets, or auto (a diagonal net "
                "whose stars are 10× flatter)"),
      IntegerKey("hnet.alternations", 3, 0, 1000,
                 "step 3 + step 2 repetitions after step 1, at most"),
      NumberKey("hnet.alpha_max", 0.5, 0, 180,
                "the largest kink angle α_max (degrees) to reach: the step-3 rounds end (or "
                "do not start) once it and hnet.star_planarity hold; 0 = no bound, every "
                "alternation runs (Shi 2014, Table 1: 0.4–4.5° on real shells)"),
      ChoiceKey("hnet.shape_parameters", "least_squares", {"least_squares", "propagated"},
                "W from eq. 7 by least squares over every edge, or propagated over a "
                "spanning tree from hnet.start_face as in the paper (exact on a simply "
                "connected A-net, where both agree; around a hole the tree leaves the "
                "whole mismatch on one edge)"),
      NumberKey("hnet.star_planarity", 1e-6, 0, 1,
                "the star planarity that ends step 1 and stops the weight growth"),
      NumberKey("hnet.continuation_factor", 10, 1, 1e6,
                "planarity weight growth per round above it"),
      IntegerKey("hnet.start_face", 0, 0, 1 << 30, "the face with W = 1 (eq. 11)"),
      IntegerKey("hnet.kink_samples", 9, 5, 1000, "points per edge for the kink angles"),
      IntegerKey("patchwork.samples", 8, 1, 256, "n × n quads per patch in output.patchwork"),
      direction,
      NumberKey("patchwork.isophotes.band_degrees", 5, 0, 180,
                "width of the isophote bands (0: no colours) [Shi 2014, §3.3]"),
      BoolKey("patchwork.ascii", false, "ASCII instead of binary PLY"),
      IntegerKey("rulings.per_family", 1, 1, 64,
                 "lines per parameter family and patch (1: through the frame points)")};
  d.output_keys = {"patchwork", "rulings"};
  d.check = [](const Settings& s) {
    const std::vector<double> v = s.Numbers("patchwork.isophotes.direction");
    if (v[0] == 0 && v[1] == 0 && v[2] == 0) {
      throw s.Error("patchwork.isophotes.direction", "the direction must not be zero");
    }
  };
  d.net = [](HookContext& c) {
    const Settings& s = *c.settings;
    const Origin at = s.Where("hnet.net");
    c.net = ChooseHNetNet(*c.input, s.String("mesh"), s.String("hnet.net"),
                          at.file.empty() ? s.spec_file() : at.file, at.line);
    const Mesh& net = c.net.derived ? c.net.mesh : *c.input;
    CheckAsymptoticNet(c, net);
    if (s.Integer("hnet.start_face") >= (long long)net.number_of_faces()) {
      throw s.Error("hnet.start_face",
                    "face " + std::to_string(s.Integer("hnet.start_face")) +
                        " does not exist: the net solved has " +
                        std::to_string(net.number_of_faces()) + " faces");
    }
  };
  d.measures = {
      {"star_planarity_max", [](HookContext& c) { return CurrentHNet(c).star_planarity_max; }},
      {"alpha_max", [](HookContext& c) { return CurrentHNet(c).kink_max; }},
      {"alpha_mean", [](HookContext& c) { return CurrentHNet(c).kink_mean; }}};
  d.stages = [](const Settings&) {
    Stage anet;
    anet.name = "A-net";
    anet.terms = {"anet_planarity", "boundary_proximity", "proximity", "anchor", "fairness",
                  "min_edge_length", "convexity"};
    anet.rounds_key = "schedule.outer_iterations";
    anet.tolerances = {{"star_planarity_max", "hnet.star_planarity"}};
    anet.continued = {"anet_planarity", "frame_coplanarity", "min_edge_length", "convexity"};
    anet.factor_key = "hnet.continuation_factor";
    anet.rest_move = 1e-6;
    anet.logged = {"star_planarity_max", "alpha_max", "alpha_mean"};
    Stage frame = anet;
    frame.name = "frame";
    frame.terms.clear();
    frame.rounds_key = "hnet.alternations";
    frame.tolerances = {{"star_planarity_max", "hnet.star_planarity", false, false},
                        {"alpha_max", "hnet.alpha_max"}};
    frame.skip_if_met = true;
    frame.rest_move = 0;
    frame.undo_if_worse = "alpha_max";
    frame.before_round = &FrameWeights;
    return std::vector<Stage>{anet, frame};
  };
  d.finish = &FinishHNet;
  d.write = &WriteHNet;
  d.analyses = {"hnet"};
  d.colors = "kinks";
  // The deviation band (problems/declarations/design_band.h) only if set;
  // its examples state one.
  return WithDesignBand(std::move(d), 0);
}

}  // namespace archgeo::problems
