#pragma once
#include "sinew/energies/potentials/analytic_obstacle.hpp"
#include "sinew/energies/potentials/potential.hpp"

#include <vector>

namespace sinew {

/// Collisions with an analytic obstacle as an external penalty force (seed
/// 000 §5.7): a node inside the obstacle is pushed back towards the surface
/// by a force of strength ε scaled by its depth δ, f = ε δ ∇φ. Its potential,
/// one-sided quadratic in the signed distance φ (> 0 outside):
///
///     E(x) = Σ_i ε/2 δ_i²,   δ_i = max(0, −φ(x_i))
///     ∇_{x_i} E = −ε δ_i ∇φ
///     ∇²_{x_i} E = ε (∇φ ∇φᵀ − δ_i ∇²φ)                 (δ_i > 0; else 0)
///
/// plane: φ = n̂·x − d, ∇²φ = 0, so ∇²E = ε n̂ n̂ᵀ;
/// sphere: φ = ρ − r, ρ = |x − c|, u = (x − c)/ρ, ∇²φ = (I − u uᵀ)/ρ, so
/// ∇²E = ε (u uᵀ − (δ/ρ)(I − u uᵀ)): its tangential eigenvalue −ε δ/ρ is
/// negative, and Projection::clamp keeps ε u uᵀ.
///
/// E is C¹: the Hessian jumps from 0 to ε ∇φ∇φᵀ at the surface. At the center
/// of a sphere (ρ = 0) the direction is undefined and the node gets zero
/// gradient and Hessian. ε is in N/m (force per metre of depth, per node).
class ObstaclePenaltyPotential final : public Potential {
public:
    /// `nodes` the nodes that collide (each at most once); empty: every node.
    /// InputError for a non-positive or non-finite stiffness, an obstacle of
    /// another dimension, a zero or non-finite normal or center, a
    /// non-positive radius, a node out of range or listed twice.
    ObstaclePenaltyPotential(int dimension, int num_nodes, AnalyticObstacle obstacle, double stiffness,
                             std::vector<int> nodes = {});

    std::string name() const override { return obstacle_kind(obstacle_) + " obstacle penalty"; }
    int dimension() const override { return dimension_; }
    int num_nodes() const override { return num_nodes_; }
    double value(ConstVectorRef x) override;
    void add_gradient(ConstVectorRef x, VectorRef gradient) override;
    /// One single-node stencil per colliding node.
    const Stencils& hessian_stencils() const override { return nodes_; }
    void add_hessian(ConstVectorRef x, Projection projection, const StencilSlots& slots, VectorRef values) override;

private:
    template <int Dim>
    void add_gradient_in(ConstVectorRef x, VectorRef gradient) const;
    template <int Dim>
    void add_hessian_in(ConstVectorRef x, Projection projection, const StencilSlots& slots, VectorRef values) const;

    int dimension_;
    int num_nodes_;
    AnalyticObstacle obstacle_;  ///< plane normal stored normalized, offset scaled to match
    double stiffness_;           ///< ε, N/m
    Stencils nodes_;             ///< 1 × count
};

} // namespace sinew
