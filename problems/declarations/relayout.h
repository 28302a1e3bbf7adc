// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — planar_quads' way out for a net far from conjugate (key
// `relayout`). A quad net planarises without folds only if its edges follow
// conjugate directions of its surface [Zadravec 2010, §1]; when they do not,
// more rounds do not help (the stall rule ends the run) but a new net along
// a conjugate field does: the conjugate-layout pipeline (field → level sets →
// layout, problems/declarations/conjugate_layout.cpp) on the net's own
// surface, its triangulation (field_pipeline.h DesignSurface).
//
//   never    nothing is offered
//   suggest  a run that misses the tolerance ends with the suitability
//            figures and the exact `archgeo solve examples/conjugate_layout.yaml`
//            command for the net's surface, with as many target faces as the
//            net has (details.relayout.command)
//   auto     a net the suitability check finds unsuitable is replaced, before
//            the solve, by the conjugate layout of its surface (target faces:
//            the net's face count); planar_quads planarises that layout, and
//            details.relayout says the connectivity changed and how the
//            panel count differs
#pragma once

#include <memory>
#include <string>

#include "core/settings.h"
#include "mesh/surface_mesh.h"
#include "problems/runtime/model.h"

namespace archgeo {

// Splits the panels of a layout with a corner straight or bent inward to
// within the convexity barrier's margin (degrees) from that corner
// (fields/layout_cleanup.h SplitReflexCorners, boundary corners included;
// the extraction splits only interior ones beyond extraction.reflex_margin).
// The barrier holds every corner the net has inside the margin but lets a
// corner already outside it get worse by the margin: a layout corner at 180°
// on a straight or concave stretch of the boundary would end reflex. Returns
// how many were split. First, a boundary vertex only one panel uses, on a
// stretch of the boundary straight to within 2° or the margin (in space), leaves
// that panel (a quad through it is a triangle in shape: one triangle then,
// not two); `dissolved` gets how many, and the mesh loses them.
int SplitBentPanels(Mesh& mesh, double margin_degrees, int* dissolved = nullptr);

// Makes `layout` (a level-set layout, problems/declarations/field_pipeline.h)
// the net the solve starts from, in file units, its bent panels split
// (SplitBentPanels at terms.convexity.margin_degrees): c.level_sets, c.net
// with details "net" = `what` and "split_bent_panels". Returns the splits.
int UseLayoutAsNet(HookContext& c, std::shared_ptr<const LevelSetResult> layout,
                   const std::string& what);

// The command that lays out `net`'s surface anew (the spec's mesh file,
// absolute; target faces = the net's faces).
std::string RelayoutCommand(const Settings& s, const Mesh& net);

// planar_quads' `net` hook: the suitability check (on its own thread; at
// once with relayout: auto, which then re-lays an unsuitable net).
void CheckOrRelayout(HookContext& c);

// planar_quads' `finish` hook (relayout: suggest): the advice when the
// tolerance was missed.
void SuggestRelayout(HookContext& c);

}  // namespace archgeo
