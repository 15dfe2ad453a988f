#pragma once
#include "sinew/core/near_null_space.hpp"

#include <Eigen/Core>

#include <vector>

namespace sinew {

/// The rigid-body modes of nodes at `positions` (node-major, `dimension` = 2
/// or 3 coordinates per node), restricted to the coordinates listed in
/// `variables` (sorted, whole nodes): the translations e_k and the
/// infinitesimal rotations ω × (x_i − x̄) about the centroid x̄ (3 in 3D, 1 in
/// 2D), orthonormalized. An elastic energy's Hessian annihilates them at a
/// stress-free state, and nearly so elsewhere; with prescribed nodes removed
/// they are still the smooth modes an algebraic multigrid must keep.
/// Block size: `dimension`.
NearNullSpace rigid_body_modes(const Eigen::VectorXd& positions, int dimension, const std::vector<int>& variables);

} // namespace sinew
