// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The Morse–Smale complex (spectral/morse_smale.h) of Laplacian
// eigenfunctions 10 … 100 on a sphere and a torus: max + min − saddles = χ
// always; the complexes reported valid have cells that are discs with four
// distinct corners and a quasi-dual of quads with V − E + F = χ; every one
// is valid (on the torus with the whole-mesh refinement of
// problems/declarations/surface_complex.h); a complex placed on a refined
// mesh lies on the input surface and its function has the input's critical
// points. On an open roof, the complex of its double. Cancellation removes
// the extrema noise adds.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "fields/triangle_surfaces.h"
#include "generators/smoothness_surfaces.h"
#include "geometry/reference.h"
#include "io/io.h"
#include "make_mesh.h"
#include "problems/commands/spectral.h"
#include "problems/declarations/surface_complex.h"
#include "scratch_dir.h"
#include "spectral/base_complex_charts.h"
#include "spectral/critical_points.h"
#include "spectral/eigenpairs.h"
#include "spectral/morse_smale.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

struct Sweep {
  int complexes = 0, euler_ok = 0, valid = 0, dual_ok = 0, primal_ok = 0;
  int refined = 0;      // complexes kept from a round of local refinement
  std::string invalid;  // k (unresolved arcs, invalid cells) of the invalid ones
};

// The mesh the complex's arcs lie on (the input, locally refined) and its
// function, as SpectralArrays of a Surface_mesh.
SpectralMesh ArcMeshOf(const MorseSmaleComplex& c) {
  Mesh mesh;
  for (const Eigen::Vector3d& p : c.points) mesh.add_vertex(Point(p.x(), p.y(), p.z()));
  for (const std::array<int, 3>& t : c.triangles) {
    EXPECT_NE(mesh.add_face(VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2])), Mesh::null_face());
  }
  return SpectralArrays(mesh);
}

// A refined complex lies on the same surface with the same critical points:
// its vertices on the input triangles, its function's critical points (f
// linear on the new vertices) those of the input's, the same Euler
// characteristic.
void ExpectSameSurfaceAndCriticalPoints(const SpectralMesh& input, const Eigen::VectorXd& f,
                                        const ReferenceSurface& surface,
                                        const MorseSmaleComplex& c, int k) {
  constexpr double kOnSurface = 1e-12;
  const SpectralMesh refined = ArcMeshOf(c);
  EXPECT_EQ(refined.euler, input.euler) << "k " << k;
  ASSERT_EQ(c.values.size(), c.points.size());
  for (size_t v = 0; v < input.points.size(); ++v) {
    ASSERT_EQ(c.points[v], input.points[v]) << "k " << k;
    ASSERT_EQ(c.values[v], f[Eigen::Index(v)]) << "k " << k;
  }
  for (size_t v = input.points.size(); v < c.points.size(); ++v) {
    const Eigen::Vector3d& p = c.points[v];
    const Vec3 q = surface.Closest(Vec3{p.x(), p.y(), p.z()}).point;
    EXPECT_LT((Eigen::Vector3d(q[0], q[1], q[2]) - p).norm(), kOnSurface) << "k " << k;
  }
  const Eigen::Map<const Eigen::VectorXd> g(c.values.data(), Eigen::Index(c.values.size()));
  const CriticalPoints a = FindCriticalPoints(input.rings, input.closed, f);
  const CriticalPoints b = FindCriticalPoints(refined.rings, refined.closed, g);
  EXPECT_EQ(a.maxima, b.maxima) << "k " << k;
  EXPECT_EQ(a.minima, b.minima) << "k " << k;
  EXPECT_EQ(a.saddles, b.saddles) << "k " << k;
  EXPECT_EQ(a.multi_saddles, b.multi_saddles) << "k " << k;
}

Eigenpairs LowestOf(const SpectralMesh& m, int count) {
  const Laplacian l = BuildLaplacian(m.points, m.triangles, LaplacianKind::kCotangent);
  return LowestEigenpairs(l.stiffness, l.mass, count);
}

// Eigenfunctions 10 … 100 (max |φ| scaled to 1), pairs up to 0.02 cancelled;
// `whole_mesh`: built as `archgeo spectral --complex` and spectral_quads
// build it (BuildSurfaceComplex: the whole mesh refined where arcs are left
// unplaced), else by BuildMorseSmale alone (local refinement only).
Sweep SweepEigenfunctions(const Mesh& mesh, int chi, bool whole_mesh) {
  const SpectralMesh m = SpectralArrays(mesh);
  const Eigenpairs pairs = LowestOf(m, 101);
  const ReferenceSurface surface(mesh);
  Sweep s;
  MorseSmaleOptions options;
  options.persistence = 0.02;
  for (int k = 10; k <= 100; ++k) {
    Eigen::VectorXd f = pairs.vectors.col(k);
    f /= f.cwiseAbs().maxCoeff();
    const SurfaceComplex whole = whole_mesh ? BuildSurfaceComplex(mesh, f, options) : SurfaceComplex{};
    const MorseSmaleComplex c =
        whole_mesh ? whole.complex : BuildMorseSmale(m.points, m.triangles, m.rings, f, options);
    ++s.complexes;
    s.euler_ok += c.maxima + c.minima - c.saddles == chi;
    if (c.refinements > 0 || whole.refinements > 0) {
      ++s.refined;
      ExpectSameSurfaceAndCriticalPoints(m, f, surface, c, k);
    }
    if (!c.valid) {
      s.invalid += " " + std::to_string(k) + " (unresolved " + std::to_string(c.unresolved) +
                 ", invalid cells " + std::to_string(c.invalid_cells) + ")";
      continue;
    }
    ++s.valid;
    for (const MorseSmaleCell& cell : c.cells) {
      EXPECT_EQ(cell.euler, 1) << "k " << k;
      EXPECT_EQ(cell.corners.size(), 4u) << "k " << k;
    }
    EXPECT_EQ(c.shared_vertices, 0) << "k " << k;
    EXPECT_EQ(c.cells.size(), size_t(2 * c.saddles)) << "k " << k;
    const QuadBaseComplex dual = QuasiDual(c, c.points);
    s.dual_ok += dual.euler == chi && dual.missing_saddles == 0 &&
                 int(dual.quads.size()) == c.saddles && dual.edges == int(c.cells.size());
    const QuadBaseComplex primal = PrimalQuads(c, c.points);
    s.primal_ok += primal.degenerate_quads == 0 && primal.quads.size() == c.cells.size() &&
                   primal.edges == int(c.arcs.size()) && primal.euler == chi;
  }
  return s;
}

TEST(MorseSmale, SphereEigenfunctions10To100) {
  const Sweep s = SweepEigenfunctions(TriangulatedEllipsoid(1, 1, 1, 4), 2, false);
  EXPECT_EQ(s.complexes, 91);
  EXPECT_EQ(s.euler_ok, 91);
  // Every one valid; 89 without the refinement, 85 without the turns at
  // saddle-saddle connections, 84 with neither (nor the look-ahead).
  EXPECT_EQ(s.valid, 91) << "invalid:" << s.invalid;
  EXPECT_GE(s.refined, 1);
  EXPECT_EQ(s.dual_ok, s.valid);
  EXPECT_EQ(s.primal_ok, s.valid);  // the cells as quads: four distinct corners, V − E + F = χ
}

TEST(MorseSmale, TorusEigenfunctions10To100) {
  const Sweep s = SweepEigenfunctions(TriangulatedCopy(TorusPrincipalQuads(3, 1, 90, 30)), 0, true);
  EXPECT_EQ(s.complexes, 91);
  EXPECT_EQ(s.euler_ok, 91);
  // Every one valid. BuildMorseSmale alone places every arc in 89 (88
  // without the look-ahead, 87 without doubling the extrema's valence, 84
  // without the local refinement, 85 without the turns at saddle-saddle
  // connections, 81 with none of them); in the other two (k = 81, 95) a
  // saddle's two arcs to one extremum round the tube close a loop that
  // leaves another arc on the far side from its extremum, and the mesh
  // split at its triangles' centroids (the same critical points, twice the
  // valence at every old vertex) gives the arcs room to be placed apart.
  EXPECT_EQ(s.valid, 91) << "invalid:" << s.invalid;
  EXPECT_GE(s.refined, 2);
  EXPECT_EQ(s.dual_ok, s.valid);
  EXPECT_EQ(s.primal_ok, s.valid);  // the cells as quads: four distinct corners, V − E + F = χ
}

// The shared Concerthall roof (open, a disc): every eigenfunction 1 … 60
// whose complex has 8 charts or more (a chart per saddle, half a chart per
// boundary saddle) gives a valid quad complex on the roof doubled across its
// boundary (a sphere: max + min − saddles = 2 there, interior points twice)
// without refining it, mirror-symmetric (every arc's mirror image an arc:
// none crosses the boundary), and its half a base complex of the roof whose
// faces have distinct corners and whose every edge two faces share but the
// sides along the boundary.
TEST(MorseSmale, EigenfunctionsOfTheOpenHallRoofGiveSymmetricComplexesOnItsDouble) {
  const Mesh hall = TriangulatedCopy(ReadMesh(ARCHGEO_DATA_DIR "/directional_Concerthall.off"));
  const SpectralMesh m = SpectralArrays(hall);
  const Eigenpairs pairs = LowestOf(m, 61);
  const std::vector<SpectralCandidate> candidates = SpectralCandidatesOf(m, pairs);
  MorseSmaleOptions options;
  options.persistence = 0.02;
  int tried = 0, along = 0;
  std::string invalid;
  for (const SpectralCandidate& cand : candidates) {
    if (SpectralCharts(cand.critical) < 8) continue;
    ++tried;
    Eigen::VectorXd f = pairs.vectors.col(cand.k);
    f /= f.cwiseAbs().maxCoeff();
    const SurfaceComplex s = BuildSurfaceComplex(hall, f, options, 0);
    ASSERT_TRUE(s.built) << s.error;
    EXPECT_TRUE(s.doubled);
    const MorseSmaleComplex& c = s.complex;
    EXPECT_EQ(c.maxima + c.minima - c.saddles, 2) << "k " << cand.k;
    if (!c.valid) {
      invalid += " " + std::to_string(cand.k);
      continue;
    }
    for (const MorseSmaleCell& cell : c.cells) {
      EXPECT_EQ(cell.euler, 1) << "k " << cand.k;
      EXPECT_EQ(cell.corners.size(), 4u) << "k " << cand.k;
    }
    EXPECT_EQ(s.quasi_dual.euler, 2) << "k " << cand.k;
    const std::vector<int>& image = c.mirror_image;
    ASSERT_EQ(image.size(), c.points.size());
    for (int v = 0; v < int(s.half_points.size()); ++v) {  // the roof's boundary: fixed
      EXPECT_EQ(image[size_t(v)] == v, bool(s.half_boundary[size_t(v)]));
    }
    std::set<std::vector<int>> paths;
    for (const MorseSmaleArc& a : c.arcs) paths.insert(a.path);
    for (const MorseSmaleArc& a : c.arcs) {
      along += a.side == 1;
      std::vector<int> mirrored;
      for (int v : a.path) mirrored.push_back(image[size_t(v)]);
      EXPECT_EQ(paths.count(mirrored), 1u) << "k " << cand.k << ": an arc without its image";
    }
    const BaseComplex half_base = HalfBaseComplex(s);
    std::map<long, int> uses;
    for (size_t f = 0; f < half_base.faces.size(); ++f) {
      std::set<int> corners(half_base.faces[f].begin(), half_base.faces[f].end());
      EXPECT_EQ(corners.size(), half_base.faces[f].size()) << "k " << cand.k;
      for (long e : half_base.edges[f]) ++uses[e];
    }
    for (const auto& [e, n] : uses) EXPECT_LE(n, 2) << "k " << cand.k;
  }
  EXPECT_GE(tried, 45);
  EXPECT_GT(along, 0);  // arcs along the boundary
  EXPECT_TRUE(invalid.empty()) << "invalid:" << invalid;
}

// An open cylinder (an annulus) with f = cos 2a · (z + ½): along the bottom
// loop f has two maxima and two minima, and f rises away from the first and
// falls away from the second, so every critical point of that loop is a
// saddle of the double; the top loop holds two maxima and two minima. The
// half of the quasi-dual has no corner on the bottom loop: its base complex
// takes the four saddles as corners there, one quad between each two arcs
// into the surface (from the top's extrema down to two saddles), and the
// charts of those four quads cover the cylinder.
TEST(MorseSmale, ABoundaryLoopOfSaddlesOnlyTakesTheSaddlesAsCorners) {
  const Mesh cylinder = TriangulatedCopy(QuadCylinder(1, 2, 50, 24));
  Eigen::VectorXd f(long(cylinder.number_of_vertices()));
  for (VertexIndex v : cylinder.vertices()) {
    const Point& p = cylinder.point(v);
    f[long(v.idx())] = std::cos(2 * std::atan2(p.y(), p.x())) * (p.z() + 0.5);
  }
  const SurfaceComplex s = BuildSurfaceComplex(cylinder, f, {}, 0);
  ASSERT_TRUE(s.built) << s.error;
  const MorseSmaleComplex& c = s.complex;
  EXPECT_EQ(c.maxima, 2);
  EXPECT_EQ(c.minima, 2);
  EXPECT_EQ(c.saddles, 4);  // max + min − saddles = 0: the double is a torus
  ASSERT_TRUE(c.valid) << c.invalid_cells << " invalid cells";
  const BaseComplex base = HalfBaseComplex(s);
  ASSERT_EQ(base.faces.size(), 4u);
  int bottom = 0;
  for (int node : base.nodes) bottom += cylinder.point(VertexIndex(VertexIndex::size_type(node))).z() < 1e-9;
  EXPECT_EQ(base.nodes.size(), 8u);
  EXPECT_EQ(bottom, 4);
  for (const auto& face : base.faces) EXPECT_EQ(face.size(), 4u);
  const ChartQuadsResult q = ChartQuads(s.half_points, s.half_triangles, base, 4, 0, ChartWeights::kCotangent);
  EXPECT_EQ(q.quads.quads.size(), 4u * 16u);
  EXPECT_EQ(q.flipped, 0);
  EXPECT_EQ(q.boundary_edges, q.expected_boundary_edges);
}

// φ_17 of the sphere plus a ±0.03 ripple: the raw complex has over twice
// φ_17's extrema; cancelling pairs of persistence ≤ 0.08, or down to φ_17's
// number of extrema, gives φ_17's counts and a valid complex. (Not every
// ripple cancels this cleanly: a ripple that makes multi-saddles leaves
// them, as only simple saddles are cancelled; docs/methods/spectral.md.)
TEST(MorseSmale, CancellationRemovesARipplesExtrema) {
  const SpectralMesh m = SpectralArrays(TriangulatedEllipsoid(1, 1, 1, 4));
  const Eigenpairs pairs = LowestOf(m, 18);
  Eigen::VectorXd f = pairs.vectors.col(17);
  f /= f.cwiseAbs().maxCoeff();
  const MorseSmaleComplex smooth = BuildMorseSmale(m.points, m.triangles, m.rings, f, {});
  ASSERT_TRUE(smooth.valid);
  Eigen::VectorXd noisy = f;
  for (Eigen::Index i = 0; i < f.size(); ++i) noisy[i] += 0.03 * std::sin(12345.678 * double(i * i % 9973));
  const MorseSmaleComplex raw = BuildMorseSmale(m.points, m.triangles, m.rings, noisy, {});
  EXPECT_GT(raw.maxima + raw.minima, 2 * (smooth.maxima + smooth.minima));
  EXPECT_FALSE(raw.valid);
  MorseSmaleOptions by_persistence;
  by_persistence.persistence = 0.08;
  MorseSmaleOptions by_count;
  by_count.target_extrema = smooth.maxima + smooth.minima;
  for (const MorseSmaleOptions& o : {by_persistence, by_count}) {
    const MorseSmaleComplex c = BuildMorseSmale(m.points, m.triangles, m.rings, noisy, o);
    EXPECT_EQ(c.maxima, smooth.maxima);
    EXPECT_EQ(c.minima, smooth.minima);
    EXPECT_EQ(c.saddles, smooth.saddles);
    EXPECT_EQ(c.cancelled, raw.saddles - smooth.saddles);
    EXPECT_TRUE(c.valid) << "persistence " << o.persistence << " unresolved " << c.unresolved << " invalid cells " << c.invalid_cells;
  }
}

// f = z on a sphere: one maximum, one minimum, no saddle, no arc, one cell.
TEST(MorseSmale, HeightOnASphereHasOneMaximumAndOneMinimum) {
  const SpectralMesh m = SpectralArrays(TriangulatedEllipsoid(1, 1, 1, 3));
  Eigen::VectorXd z(Eigen::Index(m.points.size()));
  for (size_t i = 0; i < m.points.size(); ++i) z[Eigen::Index(i)] = m.points[i].z();
  const MorseSmaleComplex c = BuildMorseSmale(m.points, m.triangles, m.rings, z, {});
  EXPECT_EQ(c.maxima, 1);
  EXPECT_EQ(c.minima, 1);
  EXPECT_EQ(c.saddles, 0);
  EXPECT_TRUE(c.arcs.empty());
  EXPECT_EQ(c.cells.size(), 1u);
  EXPECT_FALSE(c.valid);  // a sphere, not a disc with four corners
}

class SpectralComplex_ : public ScratchDirTest {};

TEST_F(SpectralComplex_, WritesArcsAndQuadsAndNamesBadOptions) {
  WriteMesh(Path("sphere.obj"), TriangulatedEllipsoid(1, 1, 1, 4));
  SpectralRequest q;
  q.mesh = Path("sphere.obj");
  q.eigenfunction = 10;
  q.complex_out = Path("complex.obj");
  q.quasi_dual_out = Path("quads.obj");
  const SpectralComplexResult result = SpectralComplex(q);
  const std::string& text = result.text;
  EXPECT_TRUE(result.valid) << text;
  EXPECT_TRUE(result.why.empty()) << result.why;
  EXPECT_NE(text.find("valid yes"), std::string::npos) << text;
  EXPECT_NE(text.find("V - E + F = 2"), std::string::npos) << text;
  std::ifstream arcs(Path("complex.obj")), quads(Path("quads.obj"));
  std::stringstream a, b;
  a << arcs.rdbuf();
  b << quads.rdbuf();
  EXPECT_NE(a.str().find("\nl "), std::string::npos);
  EXPECT_NE(b.str().find("\nf "), std::string::npos);
  auto option_of = [&](const SpectralRequest& bad) {
    try {
      SpectralComplex(bad);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  SpectralRequest bad = q;
  bad.eigenfunction = 100000;
  EXPECT_NE(option_of(bad).find("--eigenfunction"), std::string::npos);
  bad = q;
  bad.persistence = -1;
  EXPECT_NE(option_of(bad).find("--persistence"), std::string::npos);
}

// An open mesh (the shared inspired mesh, a disc): the complex of its double,
// a sphere (max + min − saddles = 2).
TEST_F(SpectralComplex_, AnOpenMeshGivesTheComplexOfItsDouble) {
  SpectralRequest q;
  q.mesh = ARCHGEO_DATA_DIR "/libigl_inspired_mesh.obj";
  q.eigenfunction = 20;
  q.persistence = 0.02;
  q.complex_out = Path("complex.obj");
  const SpectralComplexResult result = SpectralComplex(q);
  EXPECT_TRUE(result.valid) << result.text;
  EXPECT_NE(result.text.find("(max + min - saddles = 2)"), std::string::npos) << result.text;
  EXPECT_NE(result.text.find("doubled across its boundary"), std::string::npos) << result.text;
  EXPECT_NE(result.text.find("on the surface: "), std::string::npos) << result.text;
  EXPECT_NE(result.text.find(" quads, "), std::string::npos) << result.text;
  std::ifstream arcs(Path("complex.obj"));
  std::stringstream a;
  a << arcs.rdbuf();
  EXPECT_NE(a.str().find("eigenfunction 20"), std::string::npos);
  EXPECT_NE(a.str().find("\nl "), std::string::npos);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
