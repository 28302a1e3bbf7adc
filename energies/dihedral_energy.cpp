#include "energies/dihedral_energy.h"

#include <cmath>

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

namespace archgeo {
namespace {

void CheckConstants(const char* name, double inv_length, double omega) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << name << ": inv_length must be finite and > 0, got " << inv_length;
  CHECK(std::isfinite(omega) && omega > 0.0)
      << name << ": omega must be finite and > 0, got " << omega;
}

template <typename Functor>
ceres::CostFunction* MakeDihedral(const char* name, double inv_length,
                                  double omega, Functor** functor) {
  CheckConstants(name, inv_length, omega);
  auto* f = new Functor(inv_length, omega);
  if (functor != nullptr) *functor = f;
  return new ceres::AutoDiffCostFunction<Functor, 3, 3, 3, 3, 3>(f);
}

}  // namespace

double DihedralIrlsWeight(double edge_length, double dual_edge_length,
                          double inv_length, double epsilon) {
  CHECK(std::isfinite(edge_length) && edge_length >= 0.0)
      << "DihedralIrlsWeight: edge_length must be finite and >= 0, got "
      << edge_length;
  CHECK(std::isfinite(dual_edge_length) && dual_edge_length >= 0.0)
      << "DihedralIrlsWeight: dual_edge_length must be finite and >= 0, got "
      << dual_edge_length;
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "DihedralIrlsWeight: inv_length must be finite and > 0, got "
      << inv_length;
  CHECK(std::isfinite(epsilon) && epsilon > 0.0)
      << "DihedralIrlsWeight: epsilon must be finite and > 0, got " << epsilon;
  return edge_length * inv_length * dual_edge_length + epsilon;
}

ceres::CostFunction* MakeDihedralTriTri(double inv_length, double omega,
                                        DihedralTriTri** functor) {
  return MakeDihedral("MakeDihedralTriTri", inv_length, omega, functor);
}

ceres::CostFunction* MakeDihedralTriPoly(double inv_length, double omega,
                                         DihedralTriPoly** functor) {
  return MakeDihedral("MakeDihedralTriPoly", inv_length, omega, functor);
}

ceres::CostFunction* MakeDihedralPolyPoly(double inv_length, double omega,
                                          DihedralPolyPoly** functor) {
  return MakeDihedral("MakeDihedralPolyPoly", inv_length, omega, functor);
}

}  // namespace archgeo
