#pragma once
// The structural tensor of AnisoMPM's anisotropic driving force (seed 004
// Alg. 2).
#include "sinew/mpm/damage/phase_field_point.hpp"

#include <Eigen/Core>

namespace sinew {

/// A = I + Σ_k α_k (R a_k)(R a_k)ᵀ over the point's directors, R the rotation
/// of the polar decomposition F = R S (from the rotation-variant SVD
/// F = U Σ Vᵀ, R = U Vᵀ, a proper rotation also for an inverted F): the
/// directors turned with the material.
template <int Dim>
Eigen::Matrix<double, Dim, Dim> structural_tensor(const PhaseFieldPoint<Dim>& point,
                                                  const Eigen::Matrix<double, Dim, Dim>& F);

} // namespace sinew
