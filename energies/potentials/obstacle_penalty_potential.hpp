#pragma once
#include "sinew/bodies/analytic_obstacle.hpp"
#include "sinew/bodies/placed_body.hpp"
#include "sinew/energies/potentials/potential.hpp"

#include <memory>
#include <vector>

namespace sinew {

/// What a PSD-projected Hessian (Projection::clamp) keeps of a penalty
/// node's ε(∇φ∇φᵀ − δ∇²φ).
enum class ContactCurvature {
    /// ε ∇φ∇φᵀ only, the Gauss–Newton part (PSD by construction).
    gauss_newton,
    /// The whole term with its negative eigenvalues clamped: it keeps the
    /// body's curvature where it pushes a node back (inside a convex corner).
    projected,
};

/// "gauss-newton" or "projected".
std::string to_string(ContactCurvature curvature);

/// Collisions with a rigid body as an external penalty force (seed 000
/// §5.7): a node inside the body is pushed back towards the surface by a
/// force of strength ε scaled by its depth δ, f = ε δ ∇φ. Its potential,
/// one-sided quadratic in the signed distance φ (> 0 outside):
///
///     E(x) = Σ_i ε/2 δ_i²,   δ_i = max(0, −φ(x_i))
///     ∇_{x_i} E = −ε δ_i ∇φ
///     ∇²_{x_i} E = ε (∇φ ∇φᵀ − δ_i ∇²φ)                 (δ_i > 0; else 0)
///
/// The body is any CollisionBody (an analytic plane or ball, a closed
/// surface, a level set) at its current placement. Projection::none gives
/// the exact Hessian; Projection::clamp what ContactCurvature says. On a
/// plane ∇²φ = 0; on a ball's outside ∇²φ = (I − uuᵀ)/ρ, so the exact
/// tangential eigenvalue −εδ/ρ is negative and both projections keep
/// ε uuᵀ.
///
/// E is C¹: the Hessian jumps from 0 to ε ∇φ∇φᵀ at the surface. Where ∇φ is
/// undefined (the centre of a ball) the node gets zero gradient and
/// Hessian. ε is in N/m (force per metre of depth, per node).
class ObstaclePenaltyPotential final : public Potential {
public:
    /// `nodes` the nodes that collide (each at most once); empty: every node.
    /// InputError for a non-positive or non-finite stiffness, a null body or
    /// one of another dimension than the scene's (a 3D body in 2D), a node
    /// out of range or listed twice.
    ObstaclePenaltyPotential(int dimension, int num_nodes, std::shared_ptr<const PlacedBody> body, double stiffness,
                             std::vector<int> nodes = {},
                             ContactCurvature curvature = ContactCurvature::gauss_newton);
    /// An analytic obstacle (analytic_body's errors), at rest.
    ObstaclePenaltyPotential(int dimension, int num_nodes, const AnalyticObstacle& obstacle, double stiffness,
                             std::vector<int> nodes = {});

    std::string name() const override { return body_->body().kind() + " obstacle penalty"; }
    int dimension() const override { return dimension_; }
    int num_nodes() const override { return num_nodes_; }
    double value(ConstVectorRef x) override;
    void add_gradient(ConstVectorRef x, VectorRef gradient) override;
    /// One single-node stencil per colliding node.
    const Stencils& hessian_stencils() const override { return nodes_; }
    void add_hessian(ConstVectorRef x, Projection projection, const StencilSlots& slots, VectorRef values) override;
    /// "penetration" (δ per node, m) and "contact_force" (ε δ ∇φ per node, N).
    void add_output_data(ConstVectorRef x, OutputArrays& arrays) override;

    const PlacedBody& body() const { return *body_; }
    /// The largest depth δ over the colliding nodes at x, m.
    double max_penetration(ConstVectorRef x) const;
    /// Σ_i ε δ_i ∇φ_i at x: the force the body exerts on the mesh, N.
    Eigen::Vector3d total_force(ConstVectorRef x) const;
    /// ∂(∇E)/∂(A, t) at x, the body placed by x = A y + t (PlacedBody, 3D
    /// only): 12 columns, A(a, b) in column 3a + b and t(a) in column 9 + a,
    /// rows over all coordinates; what a sensitivity needs when the placement
    /// is a parameter (the rig's lower teeth, carried by the jaw map). With
    /// g = ∇φ, H = ∇²φ, y = A⁻¹(x_i − t) at a node inside (δ > 0):
    ///     ∂(∇_{x_i}E)/∂t_a    = ε(−g_a g + δ H e_a)          (= −∇²_{x_i}E e_a)
    ///     ∂(∇_{x_i}E)/∂A_ab   = ε(−g_a y_b g + δ(g_a A⁻ᵀe_b + y_b H e_a)).
    Eigen::MatrixXd placement_gradient_derivatives(ConstVectorRef x) const;

private:
    /// φ and its derivatives at node `node` of x.
    BodyDistance at_node(ConstVectorRef x, int node) const;

    int dimension_;
    int num_nodes_;
    std::shared_ptr<const PlacedBody> body_;
    double stiffness_;  ///< ε, N/m
    ContactCurvature curvature_;
    Stencils nodes_;    ///< 1 × count
};

} // namespace sinew
