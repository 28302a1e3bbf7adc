// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — clean-ups of a layout's polygon soup (fields/extract.h step 6):
// faces as cycles of point indices, oriented consistently, points in 3D.
// Each function keeps that orientation; "dropped" counts faces left with
// fewer than three vertices.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace archgeo {

// Removes consecutive duplicates and spikes (a, b, a → a), cyclically.
void CleanCycle(std::vector<int>* cycle);

// Splits a cycle that visits a vertex twice (a region pinched at a vertex)
// into simple cycles, each cleaned; appends those with ≥ 3 vertices to `out`.
void SimpleCycles(std::vector<int> cycle, std::vector<std::vector<int>>* out, int* dropped);

// Merges the two faces of every interior valence-2 vertex: F1 = (v, b, X…, a)
// and F2 = (v, a, Y…, b) become (b, X…, a, Y…).
void MergeValenceTwo(std::vector<std::vector<int>>* faces, int* merged, int* dropped);

// Merges every interior triangle with a corner above cap_angle_deg (its
// vertices nearly on a line) into the face across its longest side.
void MergeCaps(const std::vector<Eigen::Vector3d>& points, double cap_angle_deg,
               std::vector<std::vector<int>>* faces, int* merged, int* dropped);

// Removes near-slits: a corner x of a face f whose two sides leave x within
// angle_deg of each other (two level lines side by side from a singular
// vertex). The far end q of the shorter side lies beside the longer side x–p;
// that side is split at q in the face across it, and x leaves f
// (f: … q, x, p … → … q, p …). A side on the boundary, or a face across that
// already has q, leaves the corner as it is.
void RemoveNearSlits(const std::vector<Eigen::Vector3d>& points, double angle_deg,
                     std::vector<std::vector<int>>* faces, int* removed, int* dropped);

// Splits faces with a corner above 180° + margin_deg (in the plane of the
// face's Newell normal) at a vertex not on the boundary, along a diagonal
// from that corner x to a vertex y. The diagonal is chosen among those whose
// two parts turn as the face does and have convex corners at x and y
// (checked in each part's own plane), preferring parts with four vertices,
// then the largest smallest corner at x and y; a diagonal that makes a
// corner at x or y below min_corner_deg is not taken (the face then keeps its
// corner).
void SplitReflexCorners(const std::vector<Eigen::Vector3d>& points,
                        const std::vector<bool>& on_boundary, double margin_deg,
                        std::vector<std::vector<int>>* faces, int* split,
                        double min_corner_deg = 0);

}  // namespace archgeo
