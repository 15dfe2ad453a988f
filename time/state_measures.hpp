#pragma once
#include <Eigen/Core>

namespace sinew {

/// Measures of a state on lumped node masses m_i (positions x and velocities
/// v node-major, `dimension` 2 or 3 coordinates per node).

/// ½ Σ m_i ‖v_i‖².
double kinetic_energy(const Eigen::VectorXd& masses, const Eigen::VectorXd& v, int dimension);
/// Σ m_i v_i, as a 3-vector (z = 0 in 2D).
Eigen::Vector3d linear_momentum(const Eigen::VectorXd& masses, const Eigen::VectorXd& v, int dimension);
/// Σ m_i x_i × v_i about the origin, as a 3-vector (in 2D only z is nonzero).
Eigen::Vector3d angular_momentum(const Eigen::VectorXd& masses, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                 int dimension);

} // namespace sinew
