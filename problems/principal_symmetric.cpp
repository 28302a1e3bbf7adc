// The principal_symmetric optimisation and its builder adapter
// (problems/builder.h); problems/principal_symmetric.h documents both.
#include "problems/principal_symmetric.h"

#include <ceres/problem.h>
#include <ceres/solver.h>
#include <ceres/sphere_manifold.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <fstream>
#include <memory>
#include <random>
#include <set>
#include <sstream>

#include <glog/logging.h>

#include "energies/anchor.h"
#include "energies/dihedral_energy.h"
#include "energies/fairness.h"
#include "energies/principal_symmetric.h"
#include "mesh/input_error.h"
#include "mesh/output_files.h"
#include "mesh/reference.h"
#include "mesh/smoothness_metrics.h"
#include "mesh/topology.h"
#include "mesh/vec3.h"
#include "problems/builders.h"
#include "problems/common_terms.h"
#include "problems/smooth_mesh.h"

namespace archgeo {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kPi = 3.14159265358979323846;

VertexPair Pair(int a, int b) { return a < b ? VertexPair{a, b} : VertexPair{b, a}; }
Vec3 P(const Mesh& mesh, VertexIndex v) { return ToVec3(mesh.point(v)); }

std::vector<VertexIndex> Ring(const Mesh& mesh, VertexIndex v) {
  std::vector<VertexIndex> ring;
  for (VertexIndex w : CGAL::vertices_around_target(mesh.halfedge(v), mesh)) ring.push_back(w);
  return ring;
}

// A constrained vertex: its star split into principal and other neighbours.
struct Star {
  VertexIndex v;
  std::array<VertexIndex, 2> principal;
  std::array<VertexIndex, 4> other;
};

// Stars of the interior valence-6 vertices with principal edges; `problem`
// receives the first violation of the star rule (then the result is partial).
std::vector<Star> Stars(const Mesh& mesh, const std::set<VertexPair>& principal,
                        std::string* problem) {
  std::vector<Star> stars;
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v) || mesh.is_border(v, true)) continue;
    const std::vector<VertexIndex> ring = Ring(mesh, v);
    std::vector<int> marked;
    for (size_t j = 0; j < ring.size(); ++j) {
      if (principal.count(Pair(int(v.idx()), int(ring[j].idx())))) marked.push_back(int(j));
    }
    if (marked.empty() || ring.size() != 6) continue;
    if (marked.size() != 2 || marked[1] - marked[0] != 3) {
      if (problem && problem->empty()) {
        *problem = "vertex " + std::to_string(v.idx()) + " (valence 6) has " +
                   std::to_string(marked.size()) +
                   " principal edges; a principal-symmetric star has exactly two, opposite";
      }
      continue;
    }
    Star s;
    s.v = v;
    s.principal = {ring[marked[0]], ring[marked[1]]};
    int k = 0;
    for (size_t j = 0; j < 6; ++j) {
      if (int(j) != marked[0] && int(j) != marked[1]) s.other[k++] = ring[j];
    }
    stars.push_back(s);
  }
  return stars;
}

// Angle sum of the faces at v (triangle mesh).
double AngleSum(const Mesh& mesh, VertexIndex v) {
  double sum = 0;
  for (HalfedgeIndex h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
    if (mesh.is_border(h)) continue;
    const Vec3 a = Sub(P(mesh, mesh.source(h)), P(mesh, v));
    const Vec3 b = Sub(P(mesh, mesh.target(mesh.next(h))), P(mesh, v));
    sum += std::atan2(Norm(Cross(a, b)), Dot(a, b));
  }
  return sum;
}

struct Strip {
  VertexIndex v, w;
  int sphere_v, sphere_w;  // indices into the stars
};

struct State {
  std::vector<Star> stars;
  std::vector<int> sphere_of;  // per vertex index: star index or −1
  std::vector<Block<3>> n;     // sphere normals, per star
  std::vector<Block<1>> kappa;
  std::vector<Strip> strips;
  std::vector<Block<3>> n_e;
  std::vector<std::array<Block<1>, 2>> delta;  // per star, per principal neighbour
  std::vector<bool> saddle;                    // per star
};

void InitialiseSpheres(const Mesh& mesh, State& st) {
  const std::vector<Vec3> face_normals = FaceNormals(mesh);
  st.n.resize(st.stars.size());
  st.kappa.resize(st.stars.size());
  for (size_t i = 0; i < st.stars.size(); ++i) {
    const Star& s = st.stars[i];
    Vec3 n = VertexNormal(mesh, face_normals, s.v);
    if (Norm(n) == 0) n = {0, 0, 1};
    double ab = 0, aa = 0;
    for (VertexIndex w : s.other) {
      const Vec3 d = Sub(P(mesh, w), P(mesh, s.v));
      const double a = Dot(d, d), b = Dot(n, d);
      ab += a * b;
      aa += a * a;
    }
    st.n[i] = n;
    st.kappa[i] = {aa > 0 ? 2 * ab / aa : 0.0};
  }
  st.n_e.resize(st.strips.size());
  for (size_t i = 0; i < st.strips.size(); ++i) {
    const Strip& e = st.strips[i];
    const Vec3& nv = st.n[e.sphere_v];
    const Vec3& nw = st.n[e.sphere_w];
    Vec3 m = Cross(Sub(P(mesh, e.w), P(mesh, e.v)), Vec3{nv[0] + nw[0], nv[1] + nw[1], nv[2] + nw[2]});
    if (Norm(m) == 0) m = Cross(Sub(P(mesh, e.w), P(mesh, e.v)), Vec3{1, 0, 0});
    st.n_e[i] = Unit(m);
  }
  st.delta.assign(st.stars.size(), {});
  st.saddle.assign(st.stars.size(), false);
}

// `slack`: a principal neighbour counts as on the wrong side only if
// κ n·(w − v) exceeds it (the residual tolerance).
PrincipalSymmetricResiduals MeasureConditions(const Mesh& mesh, const State& st, double slack) {
  PrincipalSymmetricResiduals r;
  r.spheres = int(st.stars.size());
  r.strips = int(st.strips.size());
  for (size_t i = 0; i < st.stars.size(); ++i) {
    const Star& s = st.stars[i];
    const Vec3 n = Unit(st.n[i]);
    const double kappa = st.kappa[i][0];
    for (VertexIndex w : s.other) {
      const Vec3 d = Sub(P(mesh, w), P(mesh, s.v));
      r.co_spherical_max = std::max(r.co_spherical_max, std::abs(0.5 * kappa * Dot(d, d) - Dot(n, d)));
    }
    if (st.saddle[i]) {
      for (VertexIndex w : s.principal) {
        ++r.saddle_terms;
        const double side = kappa * Dot(n, Sub(P(mesh, w), P(mesh, s.v)));
        if (side > slack) {
          ++r.saddle_violations;
          r.saddle_violation_max = std::max(r.saddle_violation_max, side);
        }
      }
    }
  }
  for (const Strip& e : st.strips) {
    const Vec3 t = Unit(Sub(P(mesh, e.w), P(mesh, e.v)));
    const double det = Dot(t, Cross(Unit(st.n[e.sphere_v]), Unit(st.n[e.sphere_w])));
    r.strip_max = std::max(r.strip_max, std::abs(det));
  }
  return r;
}

// With `classify`, marks the saddles (angle sum > 2π); then starts the
// dummies of the saddles at δ = sqrt(max(0, −κ n·(w − v))).
void UpdateSaddles(const Mesh& mesh, State& st, bool classify) {
  for (size_t i = 0; i < st.stars.size(); ++i) {
    if (classify) st.saddle[i] = AngleSum(mesh, st.stars[i].v) > 2 * kPi;
    if (!st.saddle[i]) continue;
    const Vec3 n = Unit(st.n[i]);
    for (int k = 0; k < 2; ++k) {
      const double side = st.kappa[i][0] * Dot(n, Sub(P(mesh, st.stars[i].principal[k]), P(mesh, st.stars[i].v)));
      st.delta[i][k] = {std::sqrt(std::max(0.0, -side))};
    }
  }
}

nlohmann::json ResidualsJson(const PrincipalSymmetricResiduals& r) {
  return {{"spheres", r.spheres},
          {"strips", r.strips},
          {"saddle_terms", r.saddle_terms},
          {"co_spherical_max", r.co_spherical_max},
          {"strip_coplanarity_max", r.strip_max},
          {"saddle_violations", r.saddle_violations},
          {"saddle_violation_max", r.saddle_violation_max}};
}

}  // namespace

std::vector<VertexPair> ReadPrincipalEdges(const std::string& path, const std::string& key,
                                           const Mesh& mesh) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, key, "cannot read the principal-edge file");
  std::set<VertexPair> seen;
  std::vector<VertexPair> edges;
  std::string line;
  const long long n = mesh.number_of_vertices();
  for (int number = 1; std::getline(in, line); ++number) {
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string a, b, extra;
    if (!(words >> a)) continue;  // blank or comment
    auto index = [&](const std::string& word) {
      if (word.empty() || word.find_first_not_of("0123456789") != std::string::npos ||
          word.size() > 12) {
        throw InputError(path, number, key,
                         "expected two vertex indices \"i j\", got '" + word + "'");
      }
      const long long i = std::stoll(word);
      if (i >= n) {
        throw InputError(path, number, key,
                         "vertex " + word + " out of range: the mesh has " + std::to_string(n) +
                             " vertices");
      }
      return int(i);
    };
    if (!(words >> b)) {
      throw InputError(path, number, key, "expected two vertex indices \"i j\", got one");
    }
    if (words >> extra) {
      throw InputError(path, number, key, "expected two vertex indices \"i j\", got more");
    }
    const int i = index(a), j = index(b);
    if (mesh.halfedge(VertexIndex(i), VertexIndex(j)) == Mesh::null_halfedge()) {
      throw InputError(path, number, key, a + " " + b + " is not an edge of the mesh");
    }
    if (!seen.insert(Pair(i, j)).second) {
      throw InputError(path, number, key, "edge " + a + " " + b + " is listed twice");
    }
    edges.push_back(Pair(i, j));
  }
  return edges;
}

std::string CheckPrincipalStars(const Mesh& mesh, const std::vector<VertexPair>& principal) {
  std::string problem;
  Stars(mesh, std::set<VertexPair>(principal.begin(), principal.end()), &problem);
  return problem;
}

Mesh SplitQuads(const Mesh& quads, bool second_diagonal, const std::string& principal,
                std::vector<VertexPair>* labels, const std::string& file, const std::string& key) {
  CHECK(principal == "diagonals" || principal == "first" || principal == "second");
  Mesh out;
  for (VertexIndex v : quads.vertices()) out.add_vertex(quads.point(v));
  // Families of quad edges: same across a quad, different at a corner.
  std::vector<int> family(quads.number_of_edges(), -1);
  std::vector<std::array<EdgeIndex, 4>> quad_edges(quads.number_of_faces());
  std::vector<bool> is_quad(quads.number_of_faces(), false);
  for (FaceIndex f : quads.faces()) {
    if (quads.degree(f) > 4) {
      throw InputError(file, 0, key, "face " + std::to_string(f.idx()) +
                                          " has more than four sides; split needs quads and "
                                          "triangles");
    }
    if (quads.degree(f) != 4) continue;
    is_quad[f.idx()] = true;
    int k = 0;
    for (HalfedgeIndex h : CGAL::halfedges_around_face(quads.halfedge(f), quads)) {
      quad_edges[f.idx()][k++] = quads.edge(h);
    }
  }
  if (principal != "diagonals") {
    // Edge → quads containing it.
    std::vector<std::vector<int>> quads_of(quads.number_of_edges());
    for (FaceIndex f : quads.faces()) {
      if (!is_quad[f.idx()]) continue;
      for (EdgeIndex e : quad_edges[f.idx()]) quads_of[e.idx()].push_back(int(f.idx()));
    }
    for (FaceIndex start : quads.faces()) {
      if (!is_quad[start.idx()] || family[quad_edges[start.idx()][0].idx()] >= 0) continue;
      family[quad_edges[start.idx()][0].idx()] = 0;
      std::deque<EdgeIndex> queue{quad_edges[start.idx()][0]};
      while (!queue.empty()) {
        const EdgeIndex e = queue.front();
        queue.pop_front();
        for (int f : quads_of[e.idx()]) {
          const auto& q = quad_edges[f];
          const int k = int(std::find(q.begin(), q.end(), e) - q.begin());
          for (int j = 0; j < 4; ++j) {
            const int want = (j - k) % 2 == 0 ? family[e.idx()] : 1 - family[e.idx()];
            int& got = family[q[j].idx()];
            if (got < 0) {
              got = want;
              queue.push_back(q[j]);
            } else if (got != want) {
              throw InputError(file, 0, key,
                               "the quad edges do not split into two families (a singular "
                               "vertex near face " + std::to_string(f) +
                                   "); use principal: diagonals or an edge-label file");
            }
          }
        }
      }
    }
  }
  for (FaceIndex f : quads.faces()) {
    std::vector<VertexIndex> vs;
    for (VertexIndex v : CGAL::vertices_around_face(quads.halfedge(f), quads)) vs.push_back(v);
    if (vs.size() == 3) {
      out.add_face(vs[0], vs[1], vs[2]);
      continue;
    }
    if (!second_diagonal) {
      out.add_face(vs[0], vs[1], vs[2]);
      out.add_face(vs[0], vs[2], vs[3]);
      if (principal == "diagonals") labels->push_back(Pair(int(vs[0].idx()), int(vs[2].idx())));
    } else {
      out.add_face(vs[0], vs[1], vs[3]);
      out.add_face(vs[1], vs[2], vs[3]);
      if (principal == "diagonals") labels->push_back(Pair(int(vs[1].idx()), int(vs[3].idx())));
    }
  }
  if (principal != "diagonals") {
    const int want = principal == "first" ? 0 : 1;
    for (EdgeIndex e : quads.edges()) {
      if (family[e.idx()] == want) {
        labels->push_back(Pair(int(quads.vertex(e, 0).idx()), int(quads.vertex(e, 1).idx())));
      }
    }
  }
  std::sort(labels->begin(), labels->end());
  labels->erase(std::unique(labels->begin(), labels->end()), labels->end());
  return out;
}

Mesh PrincipalSymmetricTorus(double R, double r, int n_u, int n_v, double noise, unsigned seed,
                             std::vector<VertexPair>* principal) {
  if (!(r > 0 && r < R && std::isfinite(R))) {
    throw InputError("", 0, "torus", "need 0 < r < R");
  }
  if (n_u < 3 || n_v < 4 || n_v % 2 != 0) {
    throw InputError("", 0, "torus", "need n_u >= 3 and an even n_v >= 4");
  }
  if (!(noise >= 0 && std::isfinite(noise))) throw InputError("", 0, "torus", "need noise >= 0");
  Mesh mesh;
  for (int j = 0; j < n_v; ++j) {
    const double v = 2 * kPi * j / n_v;
    for (int i = 0; i < n_u; ++i) {
      const double u = 2 * kPi * (i + 0.5 * j) / n_u;
      mesh.add_vertex(Point((R + r * std::cos(v)) * std::cos(u),
                            (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)));
    }
  }
  auto id = [&](int i, int j) {
    // Ring n_v is ring 0 turned by n_v/2 steps.
    int shift = 0;
    if (j >= n_v) {
      j -= n_v;
      shift = n_v / 2;
    }
    return VertexIndex(j * n_u + ((i + shift) % n_u + n_u) % n_u);
  };
  for (int j = 0; j < n_v; ++j) {
    for (int i = 0; i < n_u; ++i) {
      // Ring j+1 is turned by half a step: (i, j+1) sits between (i, j) and (i+1, j).
      mesh.add_face(id(i, j), id(i + 1, j), id(i, j + 1));
      mesh.add_face(id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
      if (principal) principal->push_back(Pair(int(id(i, j).idx()), int(id(i + 1, j).idx())));
    }
  }
  if (principal) std::sort(principal->begin(), principal->end());
  if (noise > 0) {
    double mean = 0;
    for (EdgeIndex e : mesh.edges()) {
      mean += Norm(Sub(P(mesh, mesh.vertex(e, 0)), P(mesh, mesh.vertex(e, 1))));
    }
    mean /= double(mesh.number_of_edges());
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (VertexIndex v : mesh.vertices()) {
      Vec3 d;
      do {
        d = {uniform(rng), uniform(rng), uniform(rng)};
      } while (Dot(d, d) > 1);
      const Vec3 p = P(mesh, v);
      mesh.point(v) = Point(p[0] + noise * mean * d[0], p[1] + noise * mean * d[1],
                            p[2] + noise * mean * d[2]);
    }
  }
  return mesh;
}

PrincipalSymmetricResult SolvePrincipalSymmetric(Mesh& mesh, const ReferenceSurface& reference,
                                                 const PrincipalSymmetricSettings& settings,
                                                 const ProgressSink& progress) {
  for (FaceIndex f : mesh.faces()) CHECK_EQ(mesh.degree(f), 3u) << "principal_symmetric: triangles only";
  PrincipalSymmetricResult result;
  const PrincipalSymmetricWeights& w = settings.terms;
  const std::set<VertexPair> principal(settings.principal.begin(), settings.principal.end());
  for (const VertexPair& e : principal) {
    CHECK(mesh.halfedge(VertexIndex(e.first), VertexIndex(e.second)) != Mesh::null_halfedge())
        << "principal edge " << e.first << " " << e.second << " is not an edge";
  }
  State st;
  std::string problem_text;
  st.stars = Stars(mesh, principal, &problem_text);
  CHECK(problem_text.empty()) << problem_text;
  st.sphere_of.assign(mesh.number_of_vertices(), -1);
  for (size_t i = 0; i < st.stars.size(); ++i) st.sphere_of[st.stars[i].v.idx()] = int(i);
  for (const VertexPair& e : principal) {
    const int a = st.sphere_of[e.first], b = st.sphere_of[e.second];
    if (a >= 0 && b >= 0) st.strips.push_back({VertexIndex(e.first), VertexIndex(e.second), a, b});
  }
  InitialiseSpheres(mesh, st);
  UpdateSaddles(mesh, st, true);
  result.before = MeasureConditions(mesh, st, settings.residual_max);

  const std::vector<bool> boundary = BoundaryVertices(mesh);
  const std::vector<bool> fixed =
      settings.fixed.empty() ? std::vector<bool>(mesh.number_of_vertices(), false) : settings.fixed;
  const std::vector<Vec3> original = Positions(mesh);
  std::vector<std::array<VertexIndex, 3>> triples;
  std::vector<Vec3> triple_target;
  if (w.fairness > 0) {
    triples = SmoothFairnessTriples(mesh);
    triple_target = FairnessTargets(triples, original, w.fairness_relative);
  }
  const ceres::Solver::Options options = ToCeresOptions(settings.solver);
  const bool project = w.proximity > 0 || w.proximity_point > 0 || w.boundary_proximity > 0;

  {
    PrincipalSymmetricRound r0;
    r0.residuals = result.before;
    const SmoothnessMetrics m = ComputeSmoothnessMetrics(mesh);
    r0.E = m.E;
    r0.self_intersecting_pyramids = m.self_intersecting_pyramids;
    result.log.push_back(r0);
  }
  std::unique_ptr<ceres::Problem> problem;
  TermBlocks terms;
  for (int round = 1; round <= settings.solver.outer_iterations; ++round) {
    const auto start = Clock::now();
    Projection proj;
    if (project) proj = Project(mesh, reference, boundary);
    if (round > 1) UpdateSaddles(mesh, st, false);
    const std::vector<Vec3> previous = Positions(mesh);
    ceres::Problem::Options problem_options;
    problem_options.enable_fast_removal = false;
    problem = std::make_unique<ceres::Problem>(problem_options);
    terms.clear();
    auto pos = [&](VertexIndex v) { return PositionBlock(mesh, v); };
    for (size_t i = 0; i < st.stars.size(); ++i) {
      const Star& s = st.stars[i];
      if (w.co_spherical > 0) {
        for (VertexIndex o : s.other) {
          terms["co_spherical"].push_back(problem->AddResidualBlock(
              MakeCoSpherical(1.0), Weight(w.co_spherical), pos(s.v), st.n[i].data(),
              st.kappa[i].data(), pos(o)));
        }
      }
      if (w.saddle > 0 && st.saddle[i]) {
        for (int k = 0; k < 2; ++k) {
          terms["saddle"].push_back(problem->AddResidualBlock(
              MakeSaddleSign(), Weight(w.saddle), pos(s.v), st.n[i].data(), st.kappa[i].data(),
              pos(s.principal[k]), st.delta[i][k].data()));
        }
      }
    }
    if (w.strip > 0) {
      for (size_t i = 0; i < st.strips.size(); ++i) {
        const Strip& e = st.strips[i];
        terms["strip"].push_back(problem->AddResidualBlock(
            MakePrincipalStrip(1.0), Weight(w.strip), st.n_e[i].data(), pos(e.v), pos(e.w),
            st.n[e.sphere_v].data(), st.n[e.sphere_w].data()));
      }
    }
    if (w.dihedral_energy > 0) {
      for (EdgeIndex e : mesh.edges()) {
        if (mesh.is_border(e)) continue;
        const HalfedgeIndex h = mesh.halfedge(e, 0), o = mesh.opposite(h);
        const VertexIndex v = mesh.source(h), x = mesh.target(h);
        const VertexIndex a = mesh.target(mesh.next(h)), b = mesh.target(mesh.next(o));
        const Vec3 nl = Unit(Cross(Sub(P(mesh, x), P(mesh, v)), Sub(P(mesh, a), P(mesh, v))));
        const Vec3 nr = Unit(Cross(Sub(P(mesh, v), P(mesh, x)), Sub(P(mesh, b), P(mesh, x))));
        const double omega =
            DihedralIrlsWeight(Norm(Sub(P(mesh, x), P(mesh, v))), Norm(Sub(nl, nr)), 1.0);
        terms["dihedral_energy"].push_back(problem->AddResidualBlock(
            MakeDihedralTriTri(1.0, omega), Weight(w.dihedral_energy), pos(v), pos(x), pos(a),
            pos(b)));
      }
    }
    AddProximityTerms(*problem, mesh, project ? &proj : nullptr, original, ProximityWeightsOf(w),
                      terms);
    for (size_t t = 0; t < triples.size(); ++t) {
      terms["fairness"].push_back(problem->AddResidualBlock(
          MakeFairness(triple_target[t].data(), 1.0), Weight(w.fairness), pos(triples[t][0]),
          pos(triples[t][1]), pos(triples[t][2])));
    }
    if (w.step > 0) {
      for (VertexIndex v : mesh.vertices()) {
        if (mesh.is_isolated(v)) continue;
        terms["step"].push_back(problem->AddResidualBlock(
            MakeAnchor(previous[v.idx()].data(), 1.0), Weight(w.step), pos(v)));
      }
    }
    for (size_t i = 0; i < st.stars.size(); ++i) {
      if (problem->HasParameterBlock(st.n[i].data())) {
        problem->SetManifold(st.n[i].data(), new ceres::SphereManifold<3>());
      }
    }
    for (size_t i = 0; i < st.strips.size(); ++i) {
      if (problem->HasParameterBlock(st.n_e[i].data())) {
        problem->SetManifold(st.n_e[i].data(), new ceres::SphereManifold<3>());
      }
    }
    FixVertices(*problem, mesh, fixed);

    ceres::Solver::Summary summary;
    ceres::Solve(options, problem.get(), &summary);
    result.outer_iterations = round;
    if (!RecordSolve(summary, *problem, mesh, result)) return result;
    PrincipalSymmetricRound log;
    log.round = round;
    log.iterations = std::max(0, int(summary.iterations.size()) - 1);
    log.cost = summary.final_cost;
    log.residuals = MeasureConditions(mesh, st, settings.residual_max);
    const SmoothnessMetrics m = ComputeSmoothnessMetrics(mesh);
    log.E = m.E;
    log.self_intersecting_pyramids = m.self_intersecting_pyramids;
    log.max_move = MaxMove(Positions(mesh), previous);
    log.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.log.push_back(log);
    if (progress) {
      char line[260];
      std::snprintf(line, sizeof line,
                    "round %2d  %3d iterations  cost %.6e  co-sphericity max %.3e  strip max "
                    "%.3e  saddle violations %d  E %.6e  max move %.2e",
                    round, log.iterations, log.cost, log.residuals.co_spherical_max,
                    log.residuals.strip_max, log.residuals.saddle_violations, log.E, log.max_move);
      progress(line);
    }
    const PrincipalSymmetricResiduals& r = log.residuals;
    if (r.co_spherical_max <= settings.residual_max && r.strip_max <= settings.residual_max &&
        r.saddle_violations == 0) {
      break;
    }
  }
  result.after = result.log.back().residuals;
  if (problem) result.objective = TermObjective(*problem, terms);
  return result;
}

namespace {

class PrincipalSymmetricBuilder : public Builder {
 public:
  std::set<std::string> Keys() const override {
    return {"terms", "tolerance", "split", "principal_edges"};
  }
  std::set<std::string> OutputKeys() const override { return {"principal_edges"}; }

  void Read(const SpecReader& r, const YAML::Node& root) override {
    file_ = r.file();
    if (root["terms"]) ReadTerms(r, root["terms"]);
    if (const YAML::Node t = root["tolerance"]) {
      r.CheckKeys(t, "tolerance", {"residual_max"});
      if (t["residual_max"]) {
        s_.residual_max = r.Number(t["residual_max"], "tolerance.residual_max", 0, 1);
      }
    }
    if (root["split"] && root["principal_edges"]) {
      r.Fail(root["split"], "split", "give either split or principal_edges, not both");
    }
    if (const YAML::Node split = root["split"]) {
      if (!split.IsMap()) r.Fail(split, "split", "expected {diagonal: first|second, principal: ...}");
      r.CheckKeys(split, "split", {"diagonal", "principal"});
      split_ = true;
      if (split["diagonal"]) {
        second_diagonal_ =
            r.String(split["diagonal"], "split.diagonal", {"first", "second"}) == "second";
      }
      if (split["principal"]) {
        split_principal_ =
            r.String(split["principal"], "split.principal", {"diagonals", "first", "second"});
      }
      split_file_ = r.Overridden("split") ? "--set" : r.file();
    }
    if (const YAML::Node edges = root["principal_edges"]) {
      edges_path_ = r.Path(edges, "principal_edges");
    }
    if (!split_ && edges_path_.empty()) {
      r.Fail(root, "principal_edges",
             "principal_symmetric needs principal_edges: FILE or split: {...} (see "
             "problems/principal_symmetric.h)");
    }
  }

  nlohmann::json SettingsJson() const override {
    const PrincipalSymmetricWeights& w = s_.terms;
    nlohmann::json j = {
        {"terms",
         {{"co_spherical", w.co_spherical},
          {"strip", w.strip},
          {"saddle", w.saddle},
          {"proximity", {{"weight", w.proximity}, {"point_weight", w.proximity_point}}},
          {"boundary_proximity", w.boundary_proximity},
          {"anchor", w.anchor},
          {"fairness", {{"weight", w.fairness}, {"relative_to_original", w.fairness_relative}}},
          {"step", w.step},
          {"dihedral_energy", w.dihedral_energy}}},
        {"tolerance", {{"residual_max", s_.residual_max}}}};
    if (split_) {
      j["split"] = {{"diagonal", second_diagonal_ ? "second" : "first"},
                    {"principal", split_principal_}};
    } else {
      j["principal_edges"] = edges_path_;
    }
    return j;
  }

  void CheckInput(const Mesh& input, const std::string& path) const override {
    std::vector<VertexPair> labels;
    Mesh triangles;
    if (split_) {
      bool quads = false;
      for (FaceIndex f : input.faces()) quads = quads || input.degree(f) == 4;
      if (!quads) throw InputError(path, 0, "mesh", "split: needs a mesh with quads");
      triangles = SplitQuads(input, second_diagonal_, split_principal_, &labels, split_file_, "split");
    } else {
      for (FaceIndex f : input.faces()) {
        if (input.degree(f) != 3) {
          throw InputError(path, 0, "mesh",
                           "principal_edges needs a triangle mesh (use split: for quads)");
        }
      }
      labels = ReadPrincipalEdges(edges_path_, "principal_edges", input);
      triangles = input;
    }
    const std::string problem = CheckPrincipalStars(triangles, labels);
    if (!problem.empty()) {
      throw InputError(split_ ? split_file_ : edges_path_, 0, split_ ? "split" : "principal_edges",
                       problem);
    }
    labels_ = labels;
    labelled_vertices_ = int(input.number_of_vertices());
  }

  SolveOutcome Solve(Mesh& mesh, const SolveContext& context) const override {
    bool quads = false;
    for (FaceIndex f : mesh.faces()) quads = quads || mesh.degree(f) != 3;
    if (quads) {
      std::vector<VertexPair> unused;
      mesh = SplitQuads(mesh, second_diagonal_, split_principal_, &unused, split_file_, "split");
    }
    if (int(mesh.number_of_vertices()) != labelled_vertices_) FollowLoopSubdivision(mesh);
    PrincipalSymmetricSettings settings = s_;
    settings.principal = labels_;
    settings.fixed = context.fixed;
    settings.solver = context.solver;
    const PrincipalSymmetricResult r =
        SolvePrincipalSymmetric(mesh, *context.reference, settings, context.progress);
    SolveOutcome out = r;
    out.details["principal_edges"] = int(labels_.size());
    out.details["conditions_before"] = ResidualsJson(r.before);
    out.details["conditions_after"] = ResidualsJson(r.after);
    nlohmann::json log = nlohmann::json::array();
    for (const PrincipalSymmetricRound& l : r.log) {
      nlohmann::json j = ResidualsJson(l.residuals);
      j["round"] = l.round;
      j["iterations"] = l.iterations;
      j["cost"] = l.cost;
      j["E"] = l.E;
      j["self_intersecting_pyramids"] = l.self_intersecting_pyramids;
      j["max_move"] = l.max_move;
      j["seconds"] = l.seconds;
      log.push_back(j);
    }
    out.details["rounds"] = log;
    out.details["rounds_units"] = "E and max_move in input mean edge lengths; round 0 = input";
    char line[400];
    std::snprintf(line, sizeof line,
                  "principal-symmetric: %d spheres, %d strips, %d saddle terms\n"
                  "  co-sphericity max %.3e -> %.3e, strip coplanarity max %.3e -> %.3e, "
                  "saddle violations %d -> %d\n",
                  r.after.spheres, r.after.strips, r.after.saddle_terms, r.before.co_spherical_max,
                  r.after.co_spherical_max, r.before.strip_max, r.after.strip_max,
                  r.before.saddle_violations, r.after.saddle_violations);
    out.headline = line;
    return out;
  }

  std::set<std::string> Analyses() const override { return {"smoothness"}; }

  FaceColors Colors(const Mesh& output, double color_max) const override {
    return BendingColors(output, color_max);
  }

  void WriteOutputs(const Mesh& output, const std::map<std::string, std::string>& temporary,
                    nlohmann::json& report) const override {
    const auto it = temporary.find("principal_edges");
    if (it == temporary.end()) return;
    std::string text =
        "# principal edges of the output mesh (archgeo principal_symmetric): \"i j\", "
        "0-based vertex indices\n";
    for (const VertexPair& e : labels_) {
      text += std::to_string(e.first) + " " + std::to_string(e.second) + "\n";
    }
    WriteTextFile(it->second, text, "output.principal_edges");
  }

  std::vector<std::string> InputFiles() const override {
    return edges_path_.empty() ? std::vector<std::string>{} : std::vector<std::string>{edges_path_};
  }

 private:
  // Loop subdivision keeps the old vertices' indices and adds one vertex per
  // old edge, adjacent to exactly two old vertices (its edge's endpoints):
  // the halves of a principal edge are principal.
  void FollowLoopSubdivision(const Mesh& mesh) const {
    const int old = labelled_vertices_;
    const std::set<VertexPair> principal(labels_.begin(), labels_.end());
    std::vector<VertexPair> finer;
    for (VertexIndex m : mesh.vertices()) {
      if (int(m.idx()) < old) continue;
      std::vector<int> ends;
      for (VertexIndex w : CGAL::vertices_around_target(mesh.halfedge(m), mesh)) {
        if (int(w.idx()) < old) ends.push_back(int(w.idx()));
      }
      if (ends.size() != 2) {
        throw InputError(file_, 0, "multiresolution.scheme",
                         "principal edges follow only loop subdivision");
      }
      if (principal.count(Pair(ends[0], ends[1]))) {
        finer.push_back(Pair(ends[0], int(m.idx())));
        finer.push_back(Pair(ends[1], int(m.idx())));
      }
    }
    std::sort(finer.begin(), finer.end());
    labels_ = finer;
    labelled_vertices_ = int(mesh.number_of_vertices());
  }

  void ReadTerms(const SpecReader& r, const YAML::Node& terms) {
    r.CheckKeys(terms, "terms",
                {"co_spherical", "strip", "saddle", "proximity", "boundary_proximity", "anchor",
                 "fairness", "step", "dihedral_energy"});
    PrincipalSymmetricWeights& w = s_.terms;
    const PrincipalSymmetricWeights defaults;
    w = PrincipalSymmetricWeights{0, 0, 0, 0, 0, 0, 0, 0, false, 0, 0};
    auto weight = [&](const char* name, double& out) {
      if (terms[name]) r.Weight(terms[name], std::string("terms.") + name, &out);
    };
    weight("co_spherical", w.co_spherical);
    weight("strip", w.strip);
    weight("saddle", w.saddle);
    weight("boundary_proximity", w.boundary_proximity);
    weight("anchor", w.anchor);
    weight("step", w.step);
    weight("dihedral_energy", w.dihedral_energy);
    if (const YAML::Node fair = terms["fairness"]) {
      r.FairnessTerm(fair, &w.fairness, &w.fairness_relative);
    }
    if (const YAML::Node prox = terms["proximity"]) {
      w.proximity_point = defaults.proximity_point;
      r.ProximityTerm(prox, &w.proximity, &w.proximity_point);
    }
  }

  PrincipalSymmetricSettings s_;
  std::string file_;
  bool split_ = false, second_diagonal_ = false;
  std::string split_principal_ = "diagonals";
  std::string split_file_;
  std::string edges_path_;
  // Set by CheckInput, followed through loop subdivision by Solve.
  mutable std::vector<VertexPair> labels_;
  mutable int labelled_vertices_ = 0;
};

}  // namespace

std::unique_ptr<Builder> MakePrincipalSymmetricBuilder() {
  return std::make_unique<PrincipalSymmetricBuilder>();
}

}  // namespace archgeo
