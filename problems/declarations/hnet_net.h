// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — which net the hnet builder optimises: the input quad mesh or one
// of its diagonal nets (geometry/diagonal_net.h).
//
// An A-net candidate may come as the quad mesh whose *diagonals* follow the
// asymptotic directions (the way ArchGeo stores A-nets, e.g.
// ../shared/data/dos_free_negshell_marc_anet.obj). Its own vertex stars are
// then far from planar (0.145 of the edge length there) and flattening them
// would have to turn the net's edges onto the asymptotic directions — a large
// deformation; its diagonal net of the right colour is the A-net.
//
// `hnet.net`:
//   mesh         the input itself;
//   diagonal_0   the diagonal net on the vertices of colour 0 (the colour of
//   diagonal_1   vertex 0, see TwoColouring in mesh/topology.h), or colour 1;
//   auto         (default) a diagonal net whose mean interior star planarity
//                (geometry/hnet.h) is below 1/kDiagonalGain of the input's, else
//                the input. Of two such nets, the flatter one: the net that
//                already is an A-net. Holes do not count against a net (a
//                hole is an other-colour vertex of valence ≠ 4): the shape
//                parameters are found by least squares over every edge
//                (geometry/hnet.h HNetShape), so W need not close around a hole.
//                On the negshell the colour-1 net (mean 5.4e-7, 9 holes)
//                wins over the colour-0 net (1.7e-4, no holes). (The mean,
//                not the max: the few stars at irregular vertices start
//                further off-plane, e.g. 0.03 on the colour-0 net.)
// The choice and the three star planarities go to the report ("net") and the
// terminal.
#pragma once

#include <string>

#include "geometry/hnet.h"
#include "mesh/surface_mesh.h"
#include "problems/runtime/model.h"

namespace archgeo {

// auto picks a diagonal net only if its stars are this many times flatter.
constexpr double kDiagonalGain = 10;

// The mean interior star planarity of the flatter of the two diagonal nets
// of `mesh` (−1 if neither can be built or has an interior vertex): shown by
// `archgeo measure` beside the mesh's own, so a net stored along its
// diagonals is recognised.
double DiagonalNetStarPlanarityMean(const Mesh& mesh);

// The net for `choice` (auto | mesh | diagonal_0 | diagonal_1) of the pure
// quad mesh `input` read from `path`. Throws InputError (key hnet.net, file
// `spec_file`, line `spec_line`) if an explicitly chosen diagonal net cannot be
// built.
WorkingNet ChooseHNetNet(const Mesh& input, const std::string& path, const std::string& choice,
                         const std::string& spec_file, int spec_line);

// The H-net options of the settings hnet.start_face, hnet.kink_samples and
// hnet.shape_parameters; the defaults of HNetOptions for settings without
// them (another problem's).
HNetOptions HNetOptionsOf(const Settings& s);

}  // namespace archgeo
