// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/report/analysis.h"

#include <cmath>
#include <limits>
#include <cstdio>

#include "analysis/validity.h"
#include "analysis/goal_metrics.h"
#include "analysis/grid_metrics.h"
#include "geometry/hnet.h"
#include "analysis/smoothness_metrics.h"
#include "problems/declarations/hnet_net.h"
#include "problems/report/report.h"

namespace archgeo {
namespace {

// Pads to `width` characters as displayed (UTF-8 code points, not bytes).
std::string Cell(const AnalysisRow& row, double scale) {
  char buf[64];
  switch (row.kind) {
    case AnalysisRow::Kind::kLength:
      std::snprintf(buf, sizeof buf, "%.4e (%.3e)", row.value, row.value / scale);
      break;
    case AnalysisRow::Kind::kDegrees:
      std::snprintf(buf, sizeof buf, "%.4g°", row.value);
      break;
    case AnalysisRow::Kind::kCount:
      std::snprintf(buf, sizeof buf, "%.0f", row.value);
      break;
    case AnalysisRow::Kind::kRatio:
      std::snprintf(buf, sizeof buf, "%.4e", row.value);
      break;
    case AnalysisRow::Kind::kPercent:
      std::snprintf(buf, sizeof buf, "%.4g%%", row.value);
      break;
  }
  return buf;
}

bool PureQuad(const Mesh& mesh) {
  if (mesh.number_of_faces() == 0) return false;
  for (FaceIndex f : mesh.faces()) {
    if (mesh.degree(f) != 4) return false;
  }
  return true;
}

// A pure quad mesh with interior valence 4 and boundary valence 2 or 3.
bool IsGrid(const Mesh& mesh) {
  if (!PureQuad(mesh) || mesh.has_garbage()) return false;
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v)) return false;
    const size_t k = mesh.degree(v);
    if (mesh.is_border(v) ? (k != 2 && k != 3) : k != 4) return false;
  }
  return true;
}

void AddGrid(const Mesh& mesh, AnalysisRows& rows) {
  using K = AnalysisRow::Kind;
  const GridQuality q = MeasureQuadGridMesh(mesh);
  rows.push_back({"mdo", "MDO (eq. 4, splines)", q.spline.mdo, K::kDegrees});
  rows.push_back({"ado", "ADO (eq. 5, splines)", q.spline.ado, K::kDegrees});
  rows.push_back({"mde", "MDE (eq. 6, quad sides)", q.discrete.mde, K::kPercent});
  rows.push_back({"ade", "ADE (eq. 6, quad sides)", q.discrete.ade, K::kPercent});
  rows.push_back({"mdo_discrete", "MDO on the polygon", q.discrete.mdo, K::kDegrees});
  rows.push_back({"ado_discrete", "ADO on the polygon", q.discrete.ado, K::kDegrees});
  rows.push_back({"mde_spline", "MDE on spline arcs", q.spline.mde, K::kPercent});
  rows.push_back({"ade_spline", "ADE on spline arcs", q.spline.ade, K::kPercent});
  rows.push_back({"grid_crossings", "grid crossings measured", double(q.crossings), K::kCount});
  rows.push_back({"grid_quads", "grid quads measured", double(q.quads), K::kCount});
}

void AddSmoothness(const Mesh& mesh, AnalysisRows& rows) {
  using K = AnalysisRow::Kind;
  const SmoothnessMetrics m = ComputeSmoothnessMetrics(mesh);
  rows.push_back({"E", "E = Σ ℓ ℓ* (Pellis §3)", m.E, K::kLength});
  rows.push_back({"E_prime", "E′ = Σ ℓ |α|", m.E_prime, K::kLength});
  rows.push_back({"C", "C = Σ |λ1|+|λ2| of W′ (§5.3)", m.C, K::kLength});
  rows.push_back({"max_edge_energy", "max ℓ |α| of an edge", m.max_edge_energy, K::kLength});
  rows.push_back({"saddles", "saddle vertices", double(m.saddles), K::kCount});
  rows.push_back({"bad_saddles", "bad saddles (§2.2)", double(m.bad_saddles), K::kCount});
  rows.push_back({"self_intersecting_pyramids", "self-intersecting pyramids",
                  double(m.self_intersecting_pyramids), K::kCount});
}

void AddHNet(const Mesh& mesh, const HNetOptions& options, AnalysisRows& rows) {
  using K = AnalysisRow::Kind;
  const HNet h = BuildHNet(mesh, options);
  rows.push_back({"star_planarity_max", "A-net star planarity max", h.star_planarity_max,
                  K::kRatio});
  rows.push_back({"star_planarity_mean", "A-net star planarity mean", h.star_planarity_mean,
                  K::kRatio});
  const double diagonal = DiagonalNetStarPlanarityMean(mesh);
  if (diagonal >= 0) {
    rows.push_back({"diagonal_star_planarity_mean", "  of the flatter diagonal net", diagonal,
                    K::kRatio});
  }
  rows.push_back({"alpha_max", "H-net kink α_max (Shi Table 1)", h.kink_max, K::kDegrees});
  rows.push_back({"alpha_mean", "H-net kink α_mean", h.kink_mean, K::kDegrees});
  rows.push_back({"W_min", "H-net shape parameter W min", h.W_min, K::kRatio});
  rows.push_back({"W_max", "H-net shape parameter W max", h.W_max, K::kRatio});
  rows.push_back({"odd_valence_vertices", "odd interior valences",
                  double(h.odd_valence_vertices.size()), K::kCount});
  rows.push_back({"not_equitwist_edges", "edges not equitwist (Remark 2)",
                  double(h.not_equitwist_edges.size()), K::kCount});
  rows.push_back({"mismatch_max", "W mismatch max (eq. 7)", h.mismatch_max,
                  K::kRatio});
}

// Every mesh with panels (faces of four or more sides): how many are convex.
void AddPanels(const Mesh& mesh, AnalysisRows& rows) {
  using K = AnalysisRow::Kind;
  const PanelShapes shapes = MeasurePanelShapes(mesh);
  if (shapes.panels == 0) return;
  rows.push_back({"nonconvex_panels", "non-convex panels (of 4+ sides)", double(shapes.nonconvex),
                  K::kCount});
  rows.push_back({"worst_reflex_degrees", "worst corner bent inward", shapes.worst_reflex_degrees,
                  K::kDegrees});
}

// Conical meshes [Liu 2006; Gebreiter 2012, §10.1]: the angle criterion,
// constant face offsets (offset = the mean edge length) and convex quads.
void AddConical(const Mesh& mesh, AnalysisRows& rows) {
  using K = AnalysisRow::Kind;
  const ConicalMeasure conical = MeasureConical(mesh);
  const double edge = EdgeLengthSpread(mesh).mean;
  const FaceOffsetMeasure offsets = MeasureFaceOffsets(mesh, edge);
  rows.push_back({"conical_max", "conical residual max (rad)", conical.max, K::kRatio});
  rows.push_back({"conical_mean", "conical residual mean (rad)", conical.mean, K::kRatio});
  rows.push_back({"face_offset_miss", "face-offset miss / mean edge", offsets.max_relative,
                  K::kRatio});
  rows.push_back({"non_convex_quads", "non-convex quads", double(NonConvexQuads(mesh)),
                  K::kCount});
}

// Spread of edge lengths and of the boundary spacing [Gebreiter 2012,
// §11.2.2, §11.7.1].
void AddSpreads(const Mesh& mesh, AnalysisRows& rows) {
  using K = AnalysisRow::Kind;
  const LengthSpread all = EdgeLengthSpread(mesh);
  rows.push_back({"edge_length_spread", "edge lengths max |ℓ/mean − 1|", all.max_relative_deviation,
                  K::kRatio});
  rows.push_back({"edge_length_ratio", "edge lengths max / min", all.ratio, K::kRatio});
  const LengthSpread boundary = BoundaryEdgeLengthSpread(mesh);
  if (boundary.count > 0) {
    rows.push_back({"boundary_spacing_spread", "boundary edges max |ℓ/mean − 1|",
                    boundary.max_relative_deviation, K::kRatio});
    rows.push_back({"boundary_length_ratio", "boundary edges max / min", boundary.ratio,
                    K::kRatio});
  }
}

}  // namespace

std::set<std::string> ApplicableAnalyses(const Mesh& mesh) {
  std::set<std::string> names;
  if (mesh.number_of_faces() > 1) names.insert("smoothness");
  if (PureQuad(mesh)) names.insert("hnet");
  if (IsGrid(mesh)) names.insert("grid");
  bool quads = false;
  for (FaceIndex f : mesh.faces()) quads = quads || mesh.degree(f) == 4;
  if (quads && MeasureConical(mesh).vertices > 0) names.insert("conical");
  if (mesh.number_of_edges() > 0) names.insert("spreads");
  return names;
}

AnalysisRows Analyse(const Mesh& mesh, const std::set<std::string>& names,
                     const HNetOptions& hnet) {
  AnalysisRows rows;
  AddPanels(mesh, rows);
  const std::set<std::string> applicable = ApplicableAnalyses(mesh);
  if (names.count("smoothness") && applicable.count("smoothness")) AddSmoothness(mesh, rows);
  if (names.count("hnet") && applicable.count("hnet")) AddHNet(mesh, hnet, rows);
  if (names.count("grid") && applicable.count("grid")) AddGrid(mesh, rows);
  if (names.count("conical") && applicable.count("conical")) AddConical(mesh, rows);
  if (names.count("spreads") && applicable.count("spreads")) AddSpreads(mesh, rows);
  return rows;
}

const double* RowValue(const AnalysisRows& rows, const std::string& key) {
  for (const AnalysisRow& r : rows) {
    if (r.key == key) return &r.value;
  }
  return nullptr;
}

AnalysisRows RowsThatApply(const Mesh& mesh, const AnalysisRows& rows) {
  auto value = [&](const std::string& key) {
    const double* v = RowValue(rows, key);
    return v ? *v : std::numeric_limits<double>::infinity();
  };
  bool triangles = false;
  for (FaceIndex f : mesh.faces()) triangles = triangles || mesh.degree(f) == 3;
  const bool anet = value("star_planarity_max") <= 1e-3 || value("diagonal_star_planarity_mean") <= 1e-3;
  const bool conical = value("conical_mean") <= 0.05;
  const std::set<std::string> saddle = {"saddles", "bad_saddles"};
  const std::set<std::string> net = {"star_planarity_max", "star_planarity_mean",
                                     "diagonal_star_planarity_mean", "alpha_max", "alpha_mean",
                                     "W_min", "W_max", "odd_valence_vertices",
                                     "not_equitwist_edges", "mismatch_max"};
  const std::set<std::string> cone = {"conical_max", "conical_mean", "face_offset_miss"};
  AnalysisRows kept;
  for (const AnalysisRow& r : rows) {
    if ((saddle.count(r.key) && !triangles) || (net.count(r.key) && !anet) ||
        (cone.count(r.key) && !conical) || r.key == "non_convex_quads") {
      continue;
    }
    kept.push_back(r);
  }
  return kept;
}

void ScaleLengths(AnalysisRows& rows, double factor) {
  for (AnalysisRow& row : rows) {
    if (row.kind == AnalysisRow::Kind::kLength) row.value *= factor;
  }
}

void AnalysisToJson(const AnalysisRows& rows, double scale, nlohmann::json& json) {
  for (const AnalysisRow& row : rows) {
    if (row.kind == AnalysisRow::Kind::kCount && std::isfinite(row.value)) {
      json[row.key] = std::llround(row.value);  // counts are JSON integers
    } else {
      json[row.key] = row.value;
    }
    if (row.kind == AnalysisRow::Kind::kLength) json[row.key + "_relative"] = row.value / scale;
  }
}

std::string FormatAnalysis(const AnalysisRows& before, const AnalysisRows* after, double scale) {
  std::string out;
  for (const AnalysisRow& row : before) {
    std::string a;
    if (after) {
      for (const AnalysisRow& r : *after) {
        if (r.key == row.key) a = Cell(r, scale);
      }
    }
    out += PadColumns(row.label, 32) + PadColumns(Cell(row, scale), 26) + a + "\n";
  }
  if (after) {  // rows only after (e.g. a quantity undefined before)
    for (const AnalysisRow& r : *after) {
      bool seen = false;
      for (const AnalysisRow& b : before) seen |= b.key == r.key;
      if (!seen) out += PadColumns(r.label, 32) + PadColumns("-", 26) + Cell(r, scale) + "\n";
    }
  }
  return out;
}

}  // namespace archgeo
