// The hnet builder: A-net optimisation, H-net extension and the alternation
// of Shi, Wang, Pottmann 2014, §3.2 (Fig. 4); keys documented in problems/hnet.h.
#include "problems/hnet.h"

#include <ceres/problem.h>
#include <ceres/solver.h>
#include <ceres/sphere_manifold.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>

#include "energies/anet_planarity.h"
#include "energies/fairness.h"
#include "energies/frame_coplanarity.h"
#include "mesh/input_error.h"
#include "mesh/patchwork_io.h"
#include "mesh/metrics.h"
#include "mesh/reference.h"
#include "mesh/topology.h"
#include "problems/builders.h"
#include "problems/common_terms.h"
#include "problems/hnet_net.h"

namespace archgeo {
namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

constexpr double kStillMove = 1e-6;  // a round at rest (no tolerance), mean edge lengths
constexpr double kKinkRedDegrees = 1.0;  // face colour: red at this kink angle
// Eq. 7 mismatch on an edge the W propagation did not cross above which the
// net is reported as not closing (a hole or non-planar stars).
constexpr double kClosingMismatch = 1e-6;
// Frame terms only between patches with kShapeMin < W < 1/kShapeMin: beyond,
// the patch is nearly degenerate and its frame points sit on its corners.
constexpr double kShapeMin = 1e-3;

Eigen::Vector3d E(const Point& p) { return {p.x(), p.y(), p.z()}; }

// A vertex star: the centre and its neighbours in order around it (cyclic
// for interior vertices; from one boundary neighbour to the other otherwise).
struct Star {
  VertexIndex v;
  std::vector<VertexIndex> neighbours;
  double inv_length = 1;  // 1 / mean edge length of the star at set-up
};

Star MakeStar(const Mesh& mesh, VertexIndex v) {
  Star star;
  star.v = v;
  std::vector<HalfedgeIndex> in;
  for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) in.push_back(h);
  // Consecutive incoming halfedges h, opposite(next(h)) have face(h) between
  // their sources; a border h is the gap of an open star: put it last.
  for (size_t k = 0; k < in.size(); ++k) {
    if (mesh.is_border(in[k])) {
      std::rotate(in.begin(), in.begin() + (k + 1) % in.size(), in.end());
      break;
    }
  }
  double length = 0;
  for (HalfedgeIndex h : in) {
    star.neighbours.push_back(mesh.source(h));
    length += (E(mesh.point(mesh.source(h))) - E(mesh.point(v))).norm();
  }
  length /= double(std::max<size_t>(1, in.size()));
  star.inv_length = length > 0 ? 1.0 / length : 1.0;
  return star;
}

// Unit normal of the least-squares plane of a star (start of variant (i)).
Vec3 StarNormal(const Mesh& mesh, const Star& star) {
  Eigen::Vector3d c = E(mesh.point(star.v));
  for (VertexIndex w : star.neighbours) c += E(mesh.point(w));
  c /= double(star.neighbours.size() + 1);
  Eigen::Matrix3d cov = (E(mesh.point(star.v)) - c) * (E(mesh.point(star.v)) - c).transpose();
  for (VertexIndex w : star.neighbours) cov += (E(mesh.point(w)) - c) * (E(mesh.point(w)) - c).transpose();
  const Eigen::Vector3d n = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0);
  return {n[0], n[1], n[2]};
}

// An interior edge b0b3 in the layout of Shi Fig. 2: left face (b0, b1, b2, b3)
// runs b3 → b0, right face (b0, b3, b4, b5) runs b0 → b3.
struct EdgeQuad {
  EdgeIndex edge;
  int left = -1, right = -1;
  std::array<VertexIndex, 6> b;
};

struct Setup {
  std::vector<Star> stars;  // valence ≥ 3
  std::vector<Vec3> original;
  std::vector<bool> boundary, fixed;
  std::vector<std::vector<VertexIndex>> fair;  // triples or quadruples
  std::vector<Vec3> fair_target;
  std::vector<EdgeQuad> edges;
  Mesh::Property_map<VertexIndex, Block<3>> normal;
};

Setup MakeSetup(Mesh& mesh, const HNetPipelineSettings& s) {
  Setup setup;
  setup.boundary = BoundaryVertices(mesh);
  setup.fixed = s.fixed.empty() ? std::vector<bool>(mesh.number_of_vertices(), false) : s.fixed;
  setup.original = Positions(mesh);
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v) || mesh.degree(v) < 3) continue;
    setup.stars.push_back(MakeStar(mesh, v));
  }
  if (s.terms.anet_normals) {
    setup.normal = AddBlocks<VertexIndex, 3>(mesh, "v:anet_normal");
    for (const Star& star : setup.stars) setup.normal[star.v] = StarNormal(mesh, star);
  }
  if (s.terms.fairness > 0) {
    setup.fair = PolylineTuples(MeshPolylines(mesh), s.terms.fairness_order == 3 ? 4 : 3);
    setup.fair_target = FairnessTargets(setup.fair, setup.original, s.terms.fairness_relative);
  }
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) continue;
    const HalfedgeIndex h = mesh.halfedge(e, 0);  // b3 → b0 in the left face
    const HalfedgeIndex g = mesh.opposite(h);     // b0 → b3 in the right face
    EdgeQuad q;
    q.edge = e;
    q.left = int(mesh.face(h).idx());
    q.right = int(mesh.face(g).idx());
    q.b = {mesh.target(h), mesh.target(mesh.next(h)), mesh.target(mesh.next(mesh.next(h))),
           mesh.source(h), mesh.target(mesh.next(g)), mesh.target(mesh.next(mesh.next(g)))};
    setup.edges.push_back(q);
  }
  return setup;
}

// The face's shape parameter for its diagonal through vertex v (eq. 4).
double ShapeThrough(const HNet& hnet, int face, VertexIndex v) {
  const auto& c = hnet.patch_vertices[face];
  const bool on = c[0] == int(v.idx()) || c[2] == int(v.idx());
  return on ? hnet.W[face] : 1.0 / hnet.W[face];
}

struct Built {
  std::unique_ptr<ceres::Problem> problem;
  TermBlocks terms;
};

// One Ceres problem: F_anet (+ λ3 F_frame with the fixed weights of `hnet`).
Built Build(Mesh& mesh, Setup& setup, const Projection& proj, const HNetPipelineSettings& s,
            double scale, const HNet* hnet) {
  Built b;
  ceres::Problem::Options options;
  options.enable_fast_removal = false;
  b.problem = std::make_unique<ceres::Problem>(options);
  ceres::Problem& problem = *b.problem;
  const HNetTerms& w = s.terms;
  auto pos = [&](VertexIndex v) { return PositionBlock(mesh, v); };
  const double anet = w.anet_planarity * scale;
  if (anet > 0) {
    for (const Star& star : setup.stars) {
      if (w.anet_normals) {
        double* n = setup.normal[star.v].data();
        for (VertexIndex nb : star.neighbours) {
          b.terms["anet_planarity"].push_back(problem.AddResidualBlock(
              MakeAnetVertexNormal(star.inv_length), Weight(anet), n, pos(star.v), pos(nb)));
        }
        problem.SetManifold(n, new ceres::SphereManifold<3>());
      } else {
        for (const auto& t : AnetStarQuadNeighbours(int(star.neighbours.size()))) {
          b.terms["anet_planarity"].push_back(problem.AddResidualBlock(
              MakeAnetStarQuad(star.inv_length), Weight(anet), pos(star.v),
              pos(star.neighbours[t[0]]), pos(star.neighbours[t[1]]), pos(star.neighbours[t[2]])));
        }
      }
    }
  }
  AddProximityTerms(problem, mesh, &proj, setup.original, ProximityWeightsOf(w), b.terms);
  for (size_t i = 0; w.fairness > 0 && i < setup.fair.size(); ++i) {
    const auto& t = setup.fair[i];
    b.terms["fairness"].push_back(
        t.size() == 3
            ? problem.AddResidualBlock(MakeFairness(setup.fair_target[i].data(), 1.0),
                                       Weight(w.fairness), pos(t[0]), pos(t[1]), pos(t[2]))
            : problem.AddResidualBlock(MakeFairnessThird(setup.fair_target[i].data(), 1.0),
                                       Weight(w.fairness), pos(t[0]), pos(t[1]), pos(t[2]),
                                       pos(t[3])));
  }
  const double frame = w.frame_coplanarity * scale;
  if (hnet && frame > 0) {
    for (const EdgeQuad& q : setup.edges) {
      // No smooth join exists across a not-equitwist edge, and the W of two
      // components have no common scale: no frame term there.
      if (hnet->join[q.edge.idx()] != EdgeJoin::kEquitwist ||
          hnet->component[q.left] != hnet->component[q.right]) {
        continue;
      }
      const double Wl = ShapeThrough(*hnet, q.left, q.b[0]);   // diagonal b0b2
      const double Wr = ShapeThrough(*hnet, q.right, q.b[0]);  // diagonal b0b4
      const Eigen::Vector3d f1 = (E(mesh.point(q.b[1])) + Wl * E(mesh.point(q.b[2]))) / (1 + Wl);
      const Eigen::Vector3d f4 = (Wr * E(mesh.point(q.b[4])) + E(mesh.point(q.b[5]))) / (1 + Wr);
      const double length =
          0.5 * ((E(mesh.point(q.b[3])) - E(mesh.point(q.b[0]))).norm() + (f4 - f1).norm());
      if (!(length > 0) || !(Wl > kShapeMin && Wl < 1 / kShapeMin) ||
          !(Wr > kShapeMin && Wr < 1 / kShapeMin)) {
        continue;
      }
      b.terms["frame_coplanarity"].push_back(problem.AddResidualBlock(
          MakeFrameCoplanarity(1.0, Wl, Wr, 1.0, 1.0 / length), Weight(frame), pos(q.b[0]),
          pos(q.b[1]), pos(q.b[2]), pos(q.b[3]), pos(q.b[4]), pos(q.b[5])));
    }
  }
  FixVertices(problem, mesh, setup.fixed);
  return b;
}

}  // namespace

HNetPipelineResult SolveHNetPipeline(Mesh& mesh, const ReferenceSurface& reference,
                                     const HNetPipelineSettings& settings,
                                     const ProgressSink& progress) {
  HNetPipelineResult result;
  Setup setup = MakeSetup(mesh, settings);
  const ceres::Solver::Options options = ToCeresOptions(settings.solver);
  const double tol = settings.star_planarity;
  double scale = 1;
  Built built;
  auto hnet_now = [&] {
    const auto start = Clock::now();
    HNet h = BuildHNet(mesh, settings.hnet);
    result.seconds["hnet"] += Since(start);
    return h;
  };

  // One Ceres solve; false if it produced no usable solution.
  auto round = [&](int step, const HNet* hnet) {
    const auto start = Clock::now();
    // Without boundary proximity, boundary vertices stay near the surface
    // (for a reference larger than the net) rather than on its boundary curve.
    const Projection proj =
        Project(mesh, reference,
                settings.terms.boundary_proximity > 0
                    ? setup.boundary
                    : std::vector<bool>(mesh.number_of_vertices(), false));
    result.seconds["projection"] += Since(start);
    built = Build(mesh, setup, proj, settings, scale, hnet);
    const std::vector<Vec3> before = Positions(mesh);
    ceres::Solver::Summary summary;
    ceres::Solve(options, built.problem.get(), &summary);
    if (!RecordSolve(summary, *built.problem, mesh, result)) return false;
    ++result.outer_iterations;
    result.hnet = hnet_now();
    HNetRoundLog log;
    log.step = step;
    log.round = result.outer_iterations;
    log.iterations = std::max(0, int(summary.iterations.size()) - 1);
    log.cost = summary.final_cost;
    log.weight_scale = scale;
    log.star_planarity_max = result.hnet.star_planarity_max;
    log.kink_max = result.hnet.kink_max;
    log.kink_mean = result.hnet.kink_mean;
    log.max_move = MaxMove(before, Positions(mesh));
    log.seconds = Since(start);
    result.log.push_back(log);
    if (progress) {
      char line[256];
      std::snprintf(line, sizeof line,
                    "step %d round %2d: %3d iterations  cost %.4e  star planarity max %.3e  "
                    "α_max %.4f°  α_mean %.4f°  weight ×%.3g  max move %.2e",
                    step, log.round, log.iterations, log.cost, log.star_planarity_max,
                    log.kink_max, log.kink_mean, scale, log.max_move);
      progress(line);
    }
    return true;
  };
  auto met = [&] { return tol > 0 && result.hnet.star_planarity_max <= tol; };

  // Step 1: towards an A-net.
  for (int k = 0; k < settings.solver.outer_iterations; ++k) {
    if (!round(1, nullptr)) return result;
    if (met()) break;
    if (tol > 0) {
      scale *= settings.continuation_factor;
    } else if (result.log.back().max_move < kStillMove) {
      break;
    }
  }
  // Steps 2 and 3, alternating; result.hnet is step 2 on the current vertices.
  // A step-3 round that raises α_max is undone and ends the alternation: with
  // closing edges whose W do not agree (non-simply-connected nets, holes) the
  // frame terms can only be met by degenerating patches.
  for (int a = 0; a < settings.alternations; ++a) {
    const HNet fixed_weights = result.hnet;
    const std::vector<Vec3> before = Positions(mesh);
    if (!round(3, &fixed_weights)) return result;
    if (result.hnet.kink_max > fixed_weights.kink_max) {
      for (VertexIndex v : mesh.vertices()) mesh.point(v) = ToPoint(before[v.idx()]);
      result.hnet = fixed_weights;
      result.log.back().undone = true;
      if (progress) {
        char line[160];
        std::snprintf(line, sizeof line,
                      "step 3 round %2d undone: α_max %.4f° > %.4f° before it; alternation ends",
                      result.log.back().round, result.log.back().kink_max, fixed_weights.kink_max);
        progress(line);
      }
      break;
    }
    if (tol > 0 && !met()) scale *= settings.continuation_factor;
  }
  if (result.outer_iterations == 0) result.hnet = hnet_now();
  result.tolerance_met = tol <= 0 || result.hnet.star_planarity_max <= tol;
  if (built.problem) result.objective = TermObjective(*built.problem, built.terms);
  return result;
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

namespace {

class HNetBuilder : public Builder {
 public:
  std::set<std::string> Keys() const override { return {"terms", "hnet", "patchwork", "rulings"}; }
  std::set<std::string> OutputKeys() const override { return {"patchwork", "rulings"}; }

  void Read(const SpecReader& r, const YAML::Node& root) override {
    if (root["terms"]) ReadTerms(r, root["terms"]);
    if (const YAML::Node h = root["hnet"]) {
      r.CheckKeys(h, "hnet",
                  {"net", "alternations", "star_planarity", "continuation_factor", "start_face",
                   "kink_samples"});
      if (h["net"]) {
        net_ = r.String(h["net"], "hnet.net", {"auto", "mesh", "diagonal_0", "diagonal_1"});
        net_line_ = h["net"].Mark().line + 1;
      }
      if (h["alternations"]) s_.alternations = r.Integer(h["alternations"], "hnet.alternations", 0, 1000);
      if (h["star_planarity"]) {
        s_.star_planarity = r.Number(h["star_planarity"], "hnet.star_planarity", 0, 1);
      }
      if (h["continuation_factor"]) {
        s_.continuation_factor =
            r.Number(h["continuation_factor"], "hnet.continuation_factor", 1, 1e6);
      }
      if (h["start_face"]) {
        s_.hnet.start_face = r.Integer(h["start_face"], "hnet.start_face", 0, 1 << 30);
        start_face_line_ = h["start_face"].Mark().line + 1;
      }
      if (h["kink_samples"]) {
        s_.hnet.kink_samples = r.Integer(h["kink_samples"], "hnet.kink_samples", 5, 1000);
      }
    }
    if (const YAML::Node p = root["patchwork"]) {
      r.CheckKeys(p, "patchwork", {"samples", "isophotes", "ascii"});
      if (p["samples"]) samples_ = r.Integer(p["samples"], "patchwork.samples", 1, 256);
      if (p["ascii"]) ascii_ = r.Bool(p["ascii"], "patchwork.ascii");
      if (const YAML::Node iso = p["isophotes"]) {
        if (iso.IsScalar()) {
          isophotes_ = r.Bool(iso, "patchwork.isophotes");
        } else {
          r.CheckKeys(iso, "patchwork.isophotes", {"direction", "band_degrees"});
          isophotes_ = true;
          if (const YAML::Node d = iso["direction"]) {
            if (!d.IsSequence() || d.size() != 3) {
              r.Fail(d, "patchwork.isophotes.direction", "expected a list of 3 numbers");
            }
            for (int k = 0; k < 3; ++k) {
              direction_[k] = r.Number(d[k], "patchwork.isophotes.direction", -1e12, 1e12);
            }
            if (direction_[0] == 0 && direction_[1] == 0 && direction_[2] == 0) {
              r.Fail(d, "patchwork.isophotes.direction", "the direction must not be zero");
            }
          }
          if (iso["band_degrees"]) {
            band_degrees_ =
                r.Number(iso["band_degrees"], "patchwork.isophotes.band_degrees", 1e-3, 180);
          }
        }
      }
    }
    if (const YAML::Node l = root["rulings"]) {
      r.CheckKeys(l, "rulings", {"per_family"});
      if (l["per_family"]) per_family_ = r.Integer(l["per_family"], "rulings.per_family", 1, 64);
    }
    spec_file_ = r.file();
  }

  nlohmann::json SettingsJson() const override {
    const HNetTerms& w = s_.terms;
    return {{"terms",
             {{"anet_planarity",
               {{"weight", w.anet_planarity}, {"variant", w.anet_normals ? "normals" : "quads"}}},
              {"fairness",
               {{"weight", w.fairness},
                {"order", w.fairness_order},
                {"relative_to_original", w.fairness_relative}}},
              {"proximity", {{"weight", w.proximity}, {"point_weight", w.proximity_point}}},
              {"boundary_proximity", w.boundary_proximity},
              {"anchor", w.anchor},
              {"frame_coplanarity", w.frame_coplanarity}}},
            {"hnet",
             {{"net", net_},
              {"alternations", s_.alternations},
              {"star_planarity", s_.star_planarity},
              {"continuation_factor", s_.continuation_factor},
              {"start_face", s_.hnet.start_face},
              {"kink_samples", s_.hnet.kink_samples}}},
            {"patchwork",
             {{"samples", samples_},
              {"ascii", ascii_},
              {"isophotes",
               isophotes_ ? nlohmann::json{{"direction", direction_},
                                           {"band_degrees", band_degrees_}}
                          : nlohmann::json(false)}}},
            {"rulings", {{"per_family", per_family_}}}};
  }

  void CheckInput(const Mesh& input, const std::string& path) const override {
    if (input.number_of_faces() == 0) {
      throw InputError(path, 0, "mesh", "hnet needs a pure quad mesh; this mesh has no faces");
    }
    int others = 0;
    for (FaceIndex f : input.faces()) others += input.degree(f) != 4;
    if (others > 0) {
      throw InputError(path, 0, "mesh",
                       "hnet needs a pure quad mesh (an A-net candidate); " +
                           std::to_string(others) + " of " +
                           std::to_string(input.number_of_faces()) + " faces are not quads");
    }
    if (s_.hnet.start_face >= int(input.number_of_faces())) {
      throw InputError(spec_file_, start_face_line_, "hnet.start_face",
                       "face " + std::to_string(s_.hnet.start_face) + " does not exist: " + path +
                           " has " + std::to_string(input.number_of_faces()) + " faces");
    }
  }

  WorkingNet Net(const Mesh& input, const std::string& path) const override {
    WorkingNet net = ChooseHNetNet(input, path, net_, spec_file_, net_line_);
    if (net.derived && s_.hnet.start_face >= int(net.mesh.number_of_faces())) {
      throw InputError(spec_file_, start_face_line_, "hnet.start_face",
                       "face " + std::to_string(s_.hnet.start_face) + " does not exist: the " +
                           net.details.value("net", std::string()) + " net of " + path +
                           " has " + std::to_string(net.mesh.number_of_faces()) + " faces");
    }
    return net;
  }

  SolveOutcome Solve(Mesh& mesh, const SolveContext& context) const override {
    HNetPipelineSettings settings = s_;
    settings.fixed = context.fixed;
    settings.solver = context.solver;
    const HNetPipelineResult r =
        SolveHNetPipeline(mesh, *context.reference, settings, context.progress);
    SolveOutcome out = r;
    if (!r.usable) return out;
    const HNet& h = r.hnet;
    out.details = HNetJson(h);
    out.details["tolerance"] = {{"star_planarity", s_.star_planarity}, {"met", r.tolerance_met}};
    nlohmann::json log = nlohmann::json::array();
    for (const HNetRoundLog& l : r.log) {
      log.push_back({{"step", l.step}, {"round", l.round}, {"iterations", l.iterations},
                     {"cost", l.cost}, {"weight_scale", l.weight_scale},
                     {"star_planarity_max", l.star_planarity_max}, {"alpha_max", l.kink_max},
                     {"alpha_mean", l.kink_mean}, {"max_move_mean_edges", l.max_move},
                     {"undone", l.undone},
                     {"seconds", l.seconds}});
    }
    out.details["rounds"] = log;
    char line[512];
    std::snprintf(line, sizeof line,
                  "H-net: star planarity max %.3e (tolerance %g: %s), α_max %.4f°, α_mean "
                  "%.4f°, W in [%.4g, %.4g], λ %.4g\n",
                  h.star_planarity_max, s_.star_planarity, r.tolerance_met ? "met" : "NOT met",
                  h.kink_max, h.kink_mean, h.W_min, h.W_max, h.lambda);
    out.headline = line;
    if (!h.odd_valence_vertices.empty() || !h.not_equitwist_edges.empty() || !h.bipartite ||
        h.mismatch_max > kClosingMismatch || h.lambda_of_component.size() > 1) {
      std::snprintf(line, sizeof line,
                    "H-net beyond Theorem 4 (kinks above are honest): %zu odd interior "
                    "valences, %zu not-equitwist edges, %s, eq. 7 mismatch up to %.3e on the "
                    "%zu edges W was not propagated across, %zu W components\n",
                    h.odd_valence_vertices.size(), h.not_equitwist_edges.size(),
                    h.bipartite ? "bipartite" : "NOT bipartite", h.mismatch_max,
                    h.closing_edges.size(), h.lambda_of_component.size());
      out.headline += line;
    }
    return out;
  }

  std::set<std::string> Analyses() const override { return {"hnet"}; }

  FaceColors Colors(const Mesh& output, double) const override {
    const HNet h = BuildHNet(output, s_.hnet);
    PlanarityMeasure kink;  // reuses the green → red scale of the planarity colours
    kink.normalized.assign(output.number_of_faces(), 0.0);
    for (EdgeIndex e : output.edges()) {
      const double k = h.kink_degrees[e.idx()];
      if (k <= 0) continue;
      for (int i = 0; i < 2; ++i) {
        const FaceIndex f = output.face(output.halfedge(e, i));
        if (f != Mesh::null_face()) kink.normalized[f.idx()] = std::max(kink.normalized[f.idx()], k);
      }
    }
    return PlanarityColors(kink, kKinkRedDegrees);
  }

  void WriteOutputs(const Mesh& output, const std::map<std::string, std::string>& temporary,
                    nlohmann::json& report) const override {
    if (temporary.empty()) return;
    const HNet h = BuildHNet(output, s_.hnet);
    if (temporary.count("patchwork")) {
      const SampledPatchwork patchwork = SamplePatchwork(output, h, samples_);
      std::vector<std::array<unsigned char, 3>> colors;
      if (isophotes_) {
        colors = IsophoteColors(IsophoteAngles(patchwork.normals, direction_), band_degrees_);
      }
      WritePatchworkPly(temporary.at("patchwork"), patchwork, colors, ascii_);
      report["patchwork"] = {{"samples", samples_},
                             {"vertices", patchwork.positions.size()},
                             {"triangles", patchwork.triangles.size()},
                             {"isophotes", isophotes_}};
    }
    if (temporary.count("rulings")) {
      const Polylines rulings = PatchRulings(output, h, per_family_, 2);
      WritePolylinesObj(temporary.at("rulings"), rulings.lines);
      report["rulings"] = {{"per_family", per_family_}, {"lines", rulings.lines.size()}};
    }
  }

 private:
  void ReadTerms(const SpecReader& r, const YAML::Node& terms) {
    r.CheckKeys(terms, "terms",
                {"anet_planarity", "fairness", "proximity", "boundary_proximity", "anchor",
                 "frame_coplanarity"});
    HNetTerms& w = s_.terms;
    const HNetTerms defaults;
    w.anet_planarity = w.fairness = w.proximity = w.proximity_point = 0;
    w.boundary_proximity = w.anchor = w.frame_coplanarity = 0;
    if (const YAML::Node a = terms["anet_planarity"]) {
      const YAML::Node extra = r.Weight(a, "terms.anet_planarity", &w.anet_planarity, {"variant"});
      if (extra && extra["variant"]) {
        w.anet_normals = r.String(extra["variant"], "terms.anet_planarity.variant",
                                  {"quads", "normals"}) == "normals";
      }
    }
    if (const YAML::Node f = terms["fairness"]) {
      const YAML::Node extra =
          r.FairnessTerm(f, &w.fairness, &w.fairness_relative, {"order"});
      if (extra && extra["order"]) {
        w.fairness_order = r.Integer(extra["order"], "terms.fairness.order", 2, 3);
      }
    }
    if (const YAML::Node p = terms["proximity"]) {
      w.proximity_point = defaults.proximity_point;
      r.ProximityTerm(p, &w.proximity, &w.proximity_point);
    }
    if (terms["boundary_proximity"]) {
      r.Weight(terms["boundary_proximity"], "terms.boundary_proximity", &w.boundary_proximity);
    }
    if (terms["anchor"]) r.Weight(terms["anchor"], "terms.anchor", &w.anchor);
    if (terms["frame_coplanarity"]) {
      r.Weight(terms["frame_coplanarity"], "terms.frame_coplanarity", &w.frame_coplanarity);
    }
  }

  HNetPipelineSettings s_;
  std::string net_ = "auto";
  int net_line_ = 0;
  int samples_ = 8;
  bool ascii_ = false;
  bool isophotes_ = true;
  Vec3 direction_{0, 0, 1};
  double band_degrees_ = 5;
  int per_family_ = 1;
  std::string spec_file_;
  int start_face_line_ = 0;
};

}  // namespace

std::unique_ptr<Builder> MakeHNetBuilder() { return std::make_unique<HNetBuilder>(); }

}  // namespace archgeo
