#pragma once
#include "sinew/bodies/placed_body.hpp"
#include "sinew/mpm/grid_condition.hpp"
#include "sinew/mpm/sparse_grid.hpp"

#include <memory>
#include <vector>

namespace sinew {

/// A rigid collision body of the scene (bodies/, the same bodies that the
/// meshes' contact terms see; docs/contact.md) acting on MPM's grid, moving
/// at `velocity`. The caller moves its placement between steps.
template <int Dim>
struct GridCollider {
    std::shared_ptr<const PlacedBody> body;
    GridCondition condition = GridCondition::separate;
    Eigen::Matrix<double, Dim, 1> velocity = Eigen::Matrix<double, Dim, 1>::Zero();
    /// The band outside the body whose nodes it holds too, in cells of dx:
    /// the condition acts on nodes, so a particle stops only within a cell
    /// of the nodes held (0 lets particles a cell into the body).
    double thickness = 1.0;
};

/// Appends the colliders holding the node at x (grid spacing dx) to
/// `contacts`, in their order: those with φ(x) < thickness · dx, with
/// n = ∇φ(x) (zero where ∇φ vanishes, a ball's centre).
template <int Dim>
void add_collider_contacts(const std::vector<GridCollider<Dim>>& colliders, const Eigen::Matrix<double, Dim, 1>& x,
                           double dx, std::vector<NodeContact<Dim>>& contacts);

/// Every node with mass inside a collider or within its band,
/// φ(x_i) < thickness · dx, takes its condition
/// against the collider's velocity with n = ∇φ(x_i) (conditioned_velocity);
/// a node where ∇φ vanishes (a ball's centre) is held at the body's velocity.
template <int Dim>
void apply_colliders(const std::vector<GridCollider<Dim>>& colliders, SparseGrid<Dim>& grid);

} // namespace sinew
