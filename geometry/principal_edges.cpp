// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Principal edges of triangle meshes (geometry/principal_edges.h).
#include "geometry/principal_edges.h"

#include <Eigen/Core>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "io/input_file.h"
#include "mesh/eigen_point.h"

namespace archgeo {
namespace {

std::vector<VertexIndex> Ring(const Mesh& mesh, VertexIndex v) {
  std::vector<VertexIndex> ring;
  for (VertexIndex w : CGAL::vertices_around_target(mesh.halfedge(v), mesh)) ring.push_back(w);
  return ring;
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

VertexPair Pair(int a, int b) { return a < b ? VertexPair{a, b} : VertexPair{b, a}; }

// Stars of the interior valence-6 vertices with principal edges; `problem`
// receives the first violation of the star rule (then the result is partial).
std::vector<PrincipalStar> PrincipalStars(const Mesh& mesh, const std::set<VertexPair>& principal,
                        std::string* problem) {
  std::vector<PrincipalStar> stars;
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
    PrincipalStar s;
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

std::vector<VertexPair> ReadPrincipalEdges(const std::string& path, const std::string& key,
                                           const Mesh& mesh) {
  std::istringstream in(ReadInputFile(path, key, std::uint64_t{1} << 30, ""));
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
  if (edges.empty()) throw InputError(path, 0, key, "the file lists no principal edge");
  return edges;
}

std::string CheckPrincipalStars(const Mesh& mesh, const std::vector<VertexPair>& principal) {
  std::string problem;
  PrincipalStars(mesh, std::set<VertexPair>(principal.begin(), principal.end()), &problem);
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
      mean += (EigenPoint(mesh, mesh.vertex(e, 0)) - EigenPoint(mesh, mesh.vertex(e, 1))).norm();
    }
    mean /= double(mesh.number_of_edges());
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (VertexIndex v : mesh.vertices()) {
      Eigen::Vector3d d;
      do {
        d = Eigen::Vector3d{uniform(rng), uniform(rng), uniform(rng)};  // braces: drawn in order
      } while (d.squaredNorm() > 1);
      const Eigen::Vector3d p = EigenPoint(mesh, v) + noise * mean * d;
      mesh.point(v) = Point(p[0], p[1], p[2]);
    }
  }
  return mesh;
}

std::vector<VertexPair> FollowLoopSubdivision(const Mesh& mesh, const std::vector<VertexPair>& labels,
                                              int old_vertices, const std::string& file) {
  const std::set<VertexPair> principal(labels.begin(), labels.end());
  std::vector<VertexPair> finer;
  for (VertexIndex m : mesh.vertices()) {
    if (int(m.idx()) < old_vertices) continue;
    std::vector<int> ends;
    for (VertexIndex w : CGAL::vertices_around_target(mesh.halfedge(m), mesh)) {
      if (int(w.idx()) < old_vertices) ends.push_back(int(w.idx()));
    }
    if (ends.size() != 2) {
      throw InputError(file, 0, "multiresolution.scheme",
                       "principal edges follow only loop subdivision");
    }
    if (principal.count(Pair(ends[0], ends[1]))) {
      finer.push_back(Pair(ends[0], int(m.idx())));
      finer.push_back(Pair(ends[1], int(m.idx())));
    }
  }
  std::sort(finer.begin(), finer.end());
  return finer;
}

}  // namespace archgeo
