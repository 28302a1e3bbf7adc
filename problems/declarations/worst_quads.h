// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — planar_quads' second stage, the worst quads (term pq_worst,
// energies/pq_worst.h).
//
// The tolerance bounds the MAXIMUM of δ_PQ,n over the quads; pq_diagonal and
// face_planarity lower the SUM of squares. On a net close to conjugate both
// fall together and the first stage meets the tolerance. On a net far from
// conjugate they part: the sum falls while the worst quad gets worse (the
// DOS pillow's first two rounds, cost down, max δ_PQ,n 0.0470 → 0.0475), and as
// continuation stiffens the sum the rounds that lower the max fold creases
// and are refused; the stall rule ends the stage. Then this stage runs:
//   - from the input (the first stage's rounds leave the net pressed against
//     its barriers: restarting from them, M2 gains nothing), keeping the
//     first stage's best valid state as the one to beat;
//   - pq_worst instead of pq_diagonal: each round only the quads within
//     `level` of the round's worst quad cost, relative to it, so each round
//     lowers the maximum and the flatter quads give way;
//   - at the settings' weights, no continuation: the level follows the
//     worst quad, and the residual relative to it grows the pull as the
//     quads flatten;
//   - the same tolerance, keep-best and stall rule as the first stage.
// A net the first stage planarises never gets here (skip_if_met), so its
// result is unchanged. Why a moving band and not per-face weights or a
// p-norm: docs/methods/planar_quads.md#the-worst-quads.
#pragma once

#include "core/problem.h"

namespace archgeo::problems {

// Whether planar_quads runs the stage: relayout: never, a tolerance, and
// pq_worst on (false where there is no relayout key: conjugate_layout).
bool HasWorstQuadsStage(const Settings& settings);

// The stage after `first` (planar_quads' stage): pq_worst in place of
// pq_diagonal, started from the input.
Stage WorstQuadsStage(const Stage& first);

// The stage's stall measure: max δ_PQ,n of its own rounds (infinite before
// its first round restarts from the input, so that the first stage's best
// does not count against it).
inline constexpr const char* kWorstStagePq = "worst_stage_pq_normalized_max";
double WorstStagePq(HookContext& c);

// planar_quads' init hook: keeps the state at the start of the solve for
// WorstQuadsStage to start from (nothing without the stage).
void KeepStartState(HookContext& c);

}  // namespace archgeo::problems
