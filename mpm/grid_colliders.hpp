#pragma once
#include "sinew/bodies/placed_body.hpp"
#include "sinew/mpm/grid_condition.hpp"
#include "sinew/mpm/sparse_grid.hpp"

#include <Eigen/Geometry>

#include <memory>
#include <vector>

namespace sinew {

/// A rigid collision body of the scene (bodies/, the same bodies that the
/// meshes' contact terms see; docs/contact.md) acting on MPM's grid, moving
/// at `velocity` and turning at `angular_velocity` about `center`. The
/// caller moves its placement and its centre between steps.
template <int Dim>
struct GridCollider {
    using Vector = Eigen::Matrix<double, Dim, 1>;

    std::shared_ptr<const PlacedBody> body;
    GridCondition condition = GridCondition::separate;
    Vector velocity = Vector::Zero();  ///< v, the velocity of its centre
    /// The band outside the body whose nodes it holds too, in cells of dx:
    /// the condition acts on nodes, so a particle stops only within a cell
    /// of the nodes held (0 lets particles a cell into the body).
    double thickness = 1.0;
    /// ω (rad/s); a 2D collider turns about z, ω = (0, 0, ω_z).
    Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
    Vector center = Vector::Zero();  ///< c, the point it turns about, where it is now

    /// The velocity of the body's point at x, v + ω × (x − c).
    Vector velocity_at(const Vector& x) const
    {
        Eigen::Vector3d arm = Eigen::Vector3d::Zero();
        arm.head<Dim>() = x - center;
        return velocity + angular_velocity.cross(arm).template head<Dim>();
    }
};

/// Appends the colliders holding the node at x (grid spacing dx) to
/// `contacts`, in their order: those with φ(x) < thickness · dx, with
/// n = ∇φ(x) (zero where ∇φ vanishes, a ball's centre), at the velocity of
/// the body's point at x (velocity_at).
template <int Dim>
void add_collider_contacts(const std::vector<GridCollider<Dim>>& colliders, const Eigen::Matrix<double, Dim, 1>& x,
                           double dx, std::vector<NodeContact<Dim>>& contacts);

/// Every node with mass inside a collider or within its band,
/// φ(x_i) < thickness · dx, takes its condition
/// against the velocity of the body's point there with n = ∇φ(x_i) (conditioned_velocity);
/// a node where ∇φ vanishes (a ball's centre) is held at the body's velocity.
template <int Dim>
void apply_colliders(const std::vector<GridCollider<Dim>>& colliders, SparseGrid<Dim>& grid);

} // namespace sinew
