#include "energies/pq_diagonal.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {

ceres::CostFunction* MakePqDiagonal(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MakePqDiagonal: inv_length must be finite and > 0, got " << inv_length;
  return new ceres::AutoDiffCostFunction<PqDiagonal, 1, 3, 3, 3, 3>(
      new PqDiagonal(inv_length));
}

}  // namespace archgeo

// --- term `pq_diagonal` --------------------------------------------------------
#include <Eigen/Core>

#include "core/term.h"
#include "core/tolerance_band.h"

namespace archgeo::terms {
namespace {

// L = the quad's mean diagonal length at the start of the solve.
void AddPqDiagonal(TermContext& c, size_t i) {
  const int* q = c.elements->Vertices(i);
  using V = Eigen::Map<const Eigen::Vector3d>;
  const double d0 = (V(c.Original(q[2])) - V(c.Original(q[0]))).norm();
  const double d1 = (V(c.Original(q[3])) - V(c.Original(q[1]))).norm();
  ceres::CostFunction* cost = MakePqDiagonal(2.0 / (d0 + d1));
  if (c.band >= 0) cost = new ToleranceBand(cost, c.band);
  c.Add(cost, {c.Position(q[0]), c.Position(q[1]), c.Position(q[2]), c.Position(q[3])});
}

}  // namespace

const TermSpec& pq_diagonal() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "pq_diagonal";
    t.summary = "quad planarity: distance between the diagonals over the mean diagonal";
    t.paper = "[Zadravec 2010, §6, eq. 8, f_PQ; Shi 2014, §3.2, F_quad]";
    t.elements = "quads";
    t.supports_band = true;
    t.drives = "pq_normalized_max";
    t.add = &AddPqDiagonal;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms
