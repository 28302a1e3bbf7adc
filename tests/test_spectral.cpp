// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Spectral candidates (problems/commands/spectral.h): the cotangent
// Laplacian's spectrum on the unit sphere is l(l+1) with multiplicity 2l+1;
// every eigenfunction's critical points satisfy max + min − saddles = χ on
// closed surfaces (sphere 2, torus 0); the normalised Laplacian's spectrum
// lies in [0, 2]; bad requests are input errors.
#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "fields/triangle_surfaces.h"
#include "generators/smoothness_surfaces.h"
#include "geometry/reference.h"
#include "io/io.h"
#include "problems/commands/spectral.h"
#include "scratch_dir.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// 10,242 vertices: 0.4% or better for l ≤ 6 (the acceptance asks 1%).
TEST(Spectral, UnitSphereEigenvaluesAreLTimesLPlusOneWithMultiplicity2LPlus1) {
  const Mesh sphere = TriangulatedEllipsoid(1, 1, 1, 5);
  ASSERT_EQ(sphere.number_of_vertices(), 10242u);
  const std::vector<SpectralCandidate> c = SpectralCandidates(sphere, 49, LaplacianKind::kCotangent);
  ASSERT_EQ(c.size(), 48u);
  for (int l = 1; l <= 6; ++l) {
    for (int k = l * l; k < (l + 1) * (l + 1); ++k) {  // the 2l+1 eigenfunctions of degree l
      EXPECT_NEAR(c[size_t(k - 1)].eigenvalue, l * (l + 1), 0.01 * l * (l + 1)) << "k " << k;
    }
  }
  for (const SpectralCandidate& s : c) {
    EXPECT_EQ(s.critical.EulerSum(), 2) << "k " << s.k;
  }
}

TEST(Spectral, TorusEigenfunctionsHaveAsManySaddlesAsExtrema) {
  const Mesh torus = TriangulatedCopy(TorusPrincipalQuads(3, 1, 60, 20));
  const std::vector<SpectralCandidate> c = SpectralCandidates(torus, 40, LaplacianKind::kCotangent);
  int with_saddles = 0;
  for (const SpectralCandidate& s : c) {
    EXPECT_EQ(s.critical.EulerSum(), 0) << "k " << s.k;
    with_saddles += s.critical.saddles >= 4;
  }
  EXPECT_GT(with_saddles, 20);
}

// An open surface (Concerthall, a disc: χ = 1): boundary critical points
// classified on the surface doubled across its (Neumann) boundary count half.
TEST(Spectral, ConcerthallEigenfunctionsSumToItsEulerCharacteristic) {
  const Mesh hall = TriangulatedCopy(ReadMesh(ARCHGEO_DATA_DIR "/directional_Concerthall.off"));
  ASSERT_EQ(int(hall.number_of_vertices()) - int(hall.number_of_edges()) +
                int(hall.number_of_faces()), 1);
  const std::vector<SpectralCandidate> c = SpectralCandidates(hall, 60, LaplacianKind::kCotangent);
  int eight_charts = 0;
  for (const SpectralCandidate& s : c) {
    EXPECT_EQ(s.critical.EulerSum(), 1) << "k " << s.k;
    eight_charts += s.critical.saddles + s.critical.boundary_saddles / 2 >= 8;
  }
  EXPECT_GT(eight_charts, 20);
}

TEST(Spectral, NormalisedLaplacianEigenvaluesLieBetweenZeroAndTwo) {
  const Mesh sphere = TriangulatedEllipsoid(1.5, 1, 0.6, 3);
  const std::vector<SpectralCandidate> c = SpectralCandidates(sphere, 30, LaplacianKind::kNormalised);
  for (size_t i = 0; i < c.size(); ++i) {
    EXPECT_GT(c[i].eigenvalue, 1e-6);
    EXPECT_LT(c[i].eigenvalue, 2.0);
    if (i > 0) {
      EXPECT_GE(c[i].eigenvalue, c[i - 1].eigenvalue - 1e-12);
    }
  }
}

class SpectralList_ : public ScratchDirTest {};

TEST_F(SpectralList_, MarksTheCandidateNearestTheChartTargetAndRefusesBadRequests) {
  WriteMesh(Path("sphere.obj"), TriangulatedEllipsoid(1, 1, 1, 3));
  SpectralRequest q;
  q.mesh = Path("sphere.obj");
  q.count = 30;
  q.charts = 10;
  const std::string table = SpectralList(q);
  EXPECT_NE(table.find("Euler characteristic 2, closed"), std::string::npos) << table;
  EXPECT_NE(table.find("closest to 10 charts: k = "), std::string::npos) << table;
  q.count = 100000;
  EXPECT_THROW(SpectralList(q), InputError);
  q.count = 30;
  q.laplacian = "graph";
  EXPECT_THROW(SpectralList(q), InputError);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
