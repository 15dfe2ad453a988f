#pragma once
// Rotations by their rotation vector ω (axis × angle): R(ω) = exp([ω]×).
#include <Eigen/Core>

#include <array>

namespace sinew {

/// R(ω) = I + a [ω]× + b [ω]×², θ = |ω|, a = sin θ / θ, b = (1 − cos θ) / θ²
/// (Rodrigues), by series where θ is small.
Eigen::Matrix3d rotation_matrix(const Eigen::Vector3d& omega);

/// ∂R/∂ω_k, k = 0, 1, 2, exact at every ω including 0 (where it is [e_k]×).
std::array<Eigen::Matrix3d, 3> rotation_matrix_derivatives(const Eigen::Vector3d& omega);

/// The ω, |ω| ≤ π, of a rotation matrix R (R orthogonal with det +1).
Eigen::Vector3d rotation_vector(const Eigen::Matrix3d& R);

} // namespace sinew
