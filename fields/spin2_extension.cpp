// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/spin2_extension.h"

#include <cmath>

namespace archgeo {
namespace {

// The rotation by 2τ_fg (g's frame to f's) of a spin-2 quantity.
Eigen::Matrix2d Spin2Rotation(const EdgeTransport& t) {
  const double c = std::cos(2 * t.angle), s = std::sin(2 * t.angle);
  Eigen::Matrix2d R;
  R << c, -s, s, c;
  return R;
}

}  // namespace

Spin2Extension::Spin2Extension(const std::vector<EdgeTransport>& transports,
                               const std::vector<bool>& free, double regularisation)
    : transports_(transports), slot_(free.size(), -1) {
  for (size_t f = 0; f < free.size(); ++f) {
    if (free[f]) slot_[f] = unknowns_++;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  auto add_block = [&](int row, int col, const Eigen::Matrix2d& m) {
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) triplets.emplace_back(2 * row + i, 2 * col + j, m(i, j));
    }
  };
  for (const EdgeTransport& t : transports) {
    const int sf = slot_[t.f.idx()], sg = slot_[t.g.idx()];
    if (sf < 0 && sg < 0) continue;
    // w |u_f − R u_g|²: blocks I for f, −R for g.
    const Eigen::Matrix2d R = Spin2Rotation(t);
    const double w = t.weight;
    const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
    if (sf >= 0) add_block(sf, sf, w * I);
    if (sg >= 0) add_block(sg, sg, w * I);
    if (sf >= 0 && sg >= 0) {
      add_block(sf, sg, -w * R);
      add_block(sg, sf, -w * R.transpose());
    } else {
      anchored_ = true;
    }
  }
  if (regularisation > 0) {
    for (int k = 0; k < 2 * unknowns_; ++k) triplets.emplace_back(k, k, regularisation);
  }
  Eigen::SparseMatrix<double> A(2 * unknowns_, 2 * unknowns_);
  A.setFromTriplets(triplets.begin(), triplets.end());
  solver_.compute(A);
}

bool Spin2Extension::Extend(std::vector<Eigen::Vector2d>* values) const {
  if (solver_.info() != Eigen::Success) return false;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * unknowns_);
  for (const EdgeTransport& t : transports_) {
    const int sf = slot_[t.f.idx()], sg = slot_[t.g.idx()];
    if ((sf < 0) == (sg < 0)) continue;
    const Eigen::Matrix2d R = Spin2Rotation(t);
    if (sf >= 0) {
      rhs.segment<2>(2 * sf) += t.weight * (R * (*values)[t.g.idx()]);
    } else {
      rhs.segment<2>(2 * sg) += t.weight * (R.transpose() * (*values)[t.f.idx()]);
    }
  }
  const Eigen::VectorXd x = solver_.solve(rhs);
  if (solver_.info() != Eigen::Success || !x.allFinite()) return false;
  for (size_t f = 0; f < slot_.size(); ++f) {
    if (slot_[f] >= 0) (*values)[f] = x.segment<2>(2 * slot_[f]);
  }
  return true;
}

bool Spin2Extension::InverseStep(std::vector<Eigen::Vector2d>* values) const {
  if (solver_.info() != Eigen::Success) return false;
  Eigen::VectorXd y(2 * unknowns_);
  for (size_t f = 0; f < slot_.size(); ++f) {
    if (slot_[f] >= 0) y.segment<2>(2 * slot_[f]) = (*values)[f];
  }
  const Eigen::VectorXd x = solver_.solve(y);
  if (solver_.info() != Eigen::Success || !x.allFinite()) return false;
  for (size_t f = 0; f < slot_.size(); ++f) {
    if (slot_[f] >= 0) (*values)[f] = x.segment<2>(2 * slot_[f]);
  }
  return true;
}

}  // namespace archgeo
