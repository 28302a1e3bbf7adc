// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the connection-harmonic extension of a spin-2 quantity per face
// (one that turns by −2φ or 2φ when a face frame turns by φ: z_N − z_M of a TCD
// field, a line field as (cos 2θ, sin 2θ)): on the `free` faces the values
// minimising
//
//   Σ_e w_e |u_f − R(2τ_fg) u_g|²   over the interior edges e = (f, g)
//
// with every other face held (τ_fg, w_e: fields/face_frames.h EdgeTransport),
// a sparse LDLᵀ solve. Used by the pair cancellation (fields/pair_cancellation.h)
// and the principal-field propagation (fields/principal_field.h).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include "fields/face_frames.h"

namespace archgeo {

class Spin2Extension {
 public:
  // `free`: per face index. `regularisation` ≥ 0 adds that times |u|² on
  // every free face, so that free faces no held face touches stay solvable
  // (u = 0 there).
  Spin2Extension(const std::vector<EdgeTransport>& transports, const std::vector<bool>& free,
                 double regularisation = 0);

  // Whether an interior edge joins a free face to a held one.
  bool anchored() const { return anchored_; }

  // `values` (per face) with the free faces' replaced by the extension of the
  // held faces' values; false when the factorisation or the solve fails.
  bool Extend(std::vector<Eigen::Vector2d>* values) const;

  // One step of inverse iteration on the free faces: their values become
  // A⁻¹ times them (A the matrix of the energy above on the free faces);
  // the held faces' values are left. False when the solve fails.
  bool InverseStep(std::vector<Eigen::Vector2d>* values) const;

 private:
  const std::vector<EdgeTransport>& transports_;
  std::vector<int> slot_;  // per face: its unknown's index, −1 if held
  int unknowns_ = 0;
  bool anchored_ = false;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
};

}  // namespace archgeo
