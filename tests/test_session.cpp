// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo::Session (api/archgeo/archgeo.h): a warm solve after moving fixed
// vertices or changing a weight is the cold solve of the same start against
// the same reference; it keeps the structure's Cholesky analysis; bad input
// is an archgeo::Error.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "archgeo/archgeo.h"

namespace ARCHGEO_UNITY_ID {

// examples/planar_quads.yaml (the smooth terms, the barriers, the deviation
// band, every check; its terms listed, so that a --set of one weight keeps
// the others) with the boundary held: a designer drags boundary vertices
// (supports) and the quads follow. No output files.
const std::string kSpecPath = std::string(ARCHGEO_SOURCE_DIR) + "/examples/planar_quads.yaml";
const std::vector<std::string> kSets = {"fixed=boundary", "output.mesh=", "output.image=",
                                        "output.report="};

std::string SpecText() {
  std::ifstream in(kSpecPath);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

archgeo::Session MakeSession(const archgeo::MeshData& mesh) {
  return archgeo::Session(SpecText(), mesh, nullptr, kSets, kSpecPath);
}

archgeo::SolveResult ColdSolve(const archgeo::MeshData& start, const archgeo::MeshData& reference,
                               std::vector<std::string> sets = {}) {
  sets.insert(sets.begin(), kSets.begin(), kSets.end());
  return archgeo::Solve(SpecText(), start, &reference, sets, kSpecPath);
}
constexpr double kPqTolerance = 1e-3;  // tolerance.pq_normalized_max's default

archgeo::MeshData Roof() { return archgeo::Generate({"roof", 14, 10}); }

double Distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// Largest distance between corresponding vertices.
double MaxDistance(const archgeo::MeshData& a, const archgeo::MeshData& b) {
  EXPECT_EQ(a.vertices.size(), b.vertices.size());
  double m = 0;
  for (size_t i = 0; i < std::min(a.vertices.size(), b.vertices.size()); ++i) {
    m = std::max(m, Distance(a.vertices[i], b.vertices[i]));
  }
  return m;
}

double MeanEdge(const archgeo::MeshData& mesh) {
  double sum = 0;
  int count = 0;
  for (const auto& f : mesh.faces) {
    for (size_t k = 0; k < f.size(); ++k) {
      sum += Distance(mesh.vertices[f[k]], mesh.vertices[f[(k + 1) % f.size()]]);
      ++count;
    }
  }
  return sum / count;
}

// A boundary vertex of the roof in the middle of a side (not a corner):
// the first vertex on exactly two boundary edges whose neighbours along
// the boundary are both on it too. The roof's first row is on the boundary.
int BoundaryVertex(const archgeo::MeshData& mesh) {
  std::vector<int> uses(mesh.vertices.size(), 0);
  std::map<std::pair<int, int>, int> edges;
  for (const auto& f : mesh.faces) {
    for (size_t k = 0; k < f.size(); ++k) {
      const int a = f[k], b = f[(k + 1) % f.size()];
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::vector<int> boundary_edges(mesh.vertices.size(), 0);
  for (const auto& [e, n] : edges) {
    if (n == 1) {
      ++boundary_edges[e.first];
      ++boundary_edges[e.second];
    }
  }
  // Vertex valence 3 on the boundary: a side's middle, not a corner (2).
  std::vector<int> valence(mesh.vertices.size(), 0);
  for (const auto& [e, n] : edges) {
    ++valence[e.first];
    ++valence[e.second];
  }
  int best = -1;
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (boundary_edges[v] == 2 && valence[v] == 3) {
      best = int(v);
      if (v > mesh.vertices.size() / 8) break;  // away from a corner
    }
  }
  return best;
}

nlohmann::json Report(const archgeo::SolveResult& r) { return nlohmann::json::parse(r.report); }

// A written, valid result that meets the planarity tolerance and the
// deviation band. (A drag may raise the dihedral energy E above the dragged
// start's: tolerance.energy_not_above_input then ends the solve with exit 4,
// the cold solve's too.)
void ExpectPlanarAndValid(const archgeo::SolveResult& r) {
  ASSERT_TRUE(r.status == 0 || r.status == 4) << r.summary;
  const nlohmann::json rep = Report(r);
  EXPECT_TRUE(rep["validity"]["valid"].get<bool>());
  EXPECT_LE(rep["after"]["pq_normalized_max"].get<double>(), kPqTolerance);
  EXPECT_TRUE(rep["tolerances"]["tolerance.pq_normalized_max"]["met"].get<bool>());
  EXPECT_TRUE(rep["tolerances"]["tolerance.surface_distance_max"]["met"].get<bool>());
}

// What a session's solve started from besides the mesh: the continuation's
// weight scale and the trust region the last solve ended with (its report's
// settings), as --set arguments.
std::vector<std::string> WarmStart(const archgeo::SolveResult& r) {
  const nlohmann::json settings = Report(r)["settings"];
  char scale[64], radius[80];
  std::snprintf(scale, sizeof scale, "continuation.start=%.17g",
                settings["continuation"]["start"].get<double>());
  std::snprintf(radius, sizeof radius, "solver.initial_trust_region_radius=%.17g",
                settings["solver"]["initial_trust_region_radius"].get<double>());
  return {scale, radius};
}

TEST(Session, WarmSolveAfterAMoveIsTheColdSolveOfTheSameStart) {
  const archgeo::MeshData roof = Roof();
  archgeo::Session session = MakeSession(roof);
  const archgeo::SolveResult first = session.Solve();
  ExpectPlanarAndValid(first);
  const nlohmann::json first_report = Report(first);
  EXPECT_GE(first_report["cholesky_analyses"].get<int>(), 1);

  // Drag a boundary vertex by a tenth of a mean edge, out of the surface
  // (within the deviation band around the first mesh: 1.5% of the diagonal).
  const int v = BoundaryVertex(roof);
  ASSERT_GE(v, 0);
  const double move = MeanEdge(roof) / 10;
  std::array<double, 3> target = first.mesh.vertices[v];
  target[2] += move;
  session.MoveVertices({v}, {target});
  const archgeo::MeshData start = session.Current();
  EXPECT_EQ(start.vertices[v], target);
  EXPECT_LT(MaxDistance(start, first.mesh), move * (1 + 1e-12));  // only v moved

  const archgeo::SolveResult warm = session.Solve();
  ExpectPlanarAndValid(warm);
  const nlohmann::json warm_report = Report(warm);
  // The structure is the first solve's: no new ordering or symbolic
  // factorisation, every round by the kept Cholesky analysis.
  EXPECT_EQ(warm_report["cholesky_analyses"].get<int>(), 0);
  EXPECT_GE(warm_report["cholesky_rounds"].get<int>(), 1);
  // The fixed vertex is where it was put; the quads around it followed.
  EXPECT_EQ(warm.mesh.vertices[v], target);
  EXPECT_GT(MaxDistance(warm.mesh, start), 0.0);

  // The cold solve of the same start against the same reference (the first
  // mesh), the same vertices fixed.
  // The warm solve starts the weights where the first solve's rounds left
  // them (continuation.start, in its report's settings), and its trust
  // region where the first solve's last round left it.
  EXPECT_GT(Report(warm)["settings"]["continuation"]["start"].get<double>(), 1.0);
  EXPECT_EQ(Report(warm)["rounds"][1]["weight_scale"].get<double>(),
            first_report["rounds"].back()["weight_scale"].get<double>());
  const archgeo::SolveResult cold = ColdSolve(start, roof, WarmStart(warm));
  ExpectPlanarAndValid(cold);
  EXPECT_EQ(cold.mesh.vertices[v], target);
  EXPECT_EQ(cold.status, warm.status);
  // The same solve but for the frame: the session's is the first mesh's
  // (mean edge length 1, principal axes), the cold solve's its start's,
  // whose mean edge length the first solve and the drag changed by about
  // 2e-3; each stops the moment δ_PQ,n ≤ τ, so their states differ by about
  // that fraction of the way they moved. (A re-solve whose blocks kept the
  // last solution's plane normals instead of the start's ended 2.7% of the
  // drag away from the cold solve here.)
  EXPECT_LT(MaxDistance(warm.mesh, cold.mesh), 0.01 * move);
  EXPECT_EQ(warm_report["iterations"]["inner"], Report(cold)["iterations"]["inner"]);

  // The next solve starts from the warm result.
  const archgeo::MeshData next = session.Current();
  EXPECT_EQ(MaxDistance(next, warm.mesh), 0.0);
}

TEST(Session, AWeightChangeTakesEffect) {
  const archgeo::MeshData roof = Roof();
  const int v = BoundaryVertex(roof);
  ASSERT_GE(v, 0);
  const double move = MeanEdge(roof) / 10;
  // Two sessions from the same first solve, the same drag; one with the
  // anchor (the pull towards the start) 100 times stronger.
  archgeo::Session light = MakeSession(roof), heavy = MakeSession(roof);
  const archgeo::SolveResult first = light.Solve();
  ExpectPlanarAndValid(first);
  ExpectPlanarAndValid(heavy.Solve());
  std::array<double, 3> target = first.mesh.vertices[v];
  target[2] += move;
  light.MoveVertices({v}, {target});
  heavy.MoveVertices({v}, {target});
  EXPECT_DOUBLE_EQ(heavy.Weight("anchor"), 1.0);
  heavy.SetWeight("anchor", 100.0);
  EXPECT_DOUBLE_EQ(heavy.Weight("anchor"), 100.0);
  const archgeo::MeshData start = heavy.Current();
  const archgeo::SolveResult a = light.Solve(), b = heavy.Solve();
  ExpectPlanarAndValid(a);
  ExpectPlanarAndValid(b);
  // A stronger anchor moves the free vertices less from the start.
  double moved_light = 0, moved_heavy = 0;
  for (size_t i = 0; i < start.vertices.size(); ++i) {
    if (int(i) == v) continue;
    moved_light += Distance(a.mesh.vertices[i], start.vertices[i]);
    moved_heavy += Distance(b.mesh.vertices[i], start.vertices[i]);
  }
  EXPECT_LT(moved_heavy, 0.9 * moved_light);
  // And it is the cold solve with that weight.
  std::vector<std::string> heavier = WarmStart(b);
  heavier.push_back("terms.anchor.weight=100");
  const archgeo::SolveResult cold = ColdSolve(start, roof, heavier);
  ExpectPlanarAndValid(cold);
  EXPECT_LT(MaxDistance(b.mesh, cold.mesh), 0.01 * move);
  EXPECT_EQ(Report(b)["settings"]["terms"]["anchor"]["weight"].get<double>(), 100.0);
}

TEST(Session, BadInputIsAnErrorAndChangesNothing) {
  const archgeo::MeshData roof = Roof();
  archgeo::Session session = MakeSession(roof);
  const int n = int(roof.vertices.size());
  try {
    session.MoveVertices({0, n}, {roof.vertices[0], roof.vertices[0]});
    FAIL() << "no error for a vertex index out of range";
  } catch (const archgeo::Error& e) {
    EXPECT_EQ(e.key(), "vertex");
    EXPECT_NE(std::string(e.what()).find("vertex index " + std::to_string(n) + " out of range"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(session.MoveVertices({-1}, {roof.vertices[0]}), archgeo::Error);
  EXPECT_THROW(session.MoveVertices({1}, {{0.0, NAN, 0.0}}), archgeo::Error);
  EXPECT_THROW(session.MoveVertices({1, 2}, {roof.vertices[0]}), std::invalid_argument);
  EXPECT_EQ(MaxDistance(session.Current(), roof), 0.0);  // nothing moved
  try {
    session.SetWeight("no_such_term", 1.0);
    FAIL() << "no error for an unknown term";
  } catch (const archgeo::Error& e) {
    EXPECT_EQ(e.key(), "terms");
    EXPECT_NE(std::string(e.what()).find("'no_such_term' is not a term of planar_quads"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(session.SetWeight("anchor", -1.0), archgeo::Error);
  EXPECT_THROW(session.Weight("no_such_term"), archgeo::Error);
  // A problem that solves a net of its own is refused before any work.
  EXPECT_THROW(archgeo::Session(SpecText(), roof, nullptr, {"multiresolution.levels=1"}, kSpecPath),
               archgeo::Error);
}

}  // namespace ARCHGEO_UNITY_ID
