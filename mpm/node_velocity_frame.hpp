#pragma once
#include "sinew/mpm/grid_condition.hpp"

#include <Eigen/Core>

#include <vector>

namespace sinew {

/// The velocities an implicit solve leaves free at a node its contacts hold:
/// v = offset + basis · y, y ∈ ℝᵏ, basis Dim × k with orthonormal columns
/// (k = Dim for a free node, 0 for a held one).
template <int Dim>
struct NodeVelocityFrame {
    Eigen::Matrix<double, Dim, 1> offset = Eigen::Matrix<double, Dim, 1>::Zero();
    Eigen::Matrix<double, Dim, Eigen::Dynamic> basis = Eigen::Matrix<double, Dim, Dim>::Identity();
};

/// The frame of a node held by `contacts`, with the conditions decided at the
/// step's predictor v* (an active set fixed for the solve): sticky (or no
/// normal) fixes v = v_b; slip fixes n·v = n·v_b; separate does the same
/// when v* approaches the obstacle, (v* − v_b)·n < 0, and leaves v free
/// otherwise. The fixed components are the rows N v = d; basis spans N's
/// null space (from a rank-revealing QR of Nᵀ), offset is the least-norm
/// solution of N v = d (least squares where contacts disagree).
template <int Dim>
NodeVelocityFrame<Dim> node_velocity_frame(const std::vector<NodeContact<Dim>>& contacts,
                                           const Eigen::Matrix<double, Dim, 1>& predictor);

} // namespace sinew
