#pragma once
#include "sinew/bodies/placed_body.hpp"
#include "sinew/energies/constraints/constraint_set.hpp"

#include <memory>
#include <vector>

namespace sinew {

/// Contact with a rigid body as exact inequality constraints (issue 32): no
/// node of the mesh enters the body,
///
///     c_i(x) = φ(x_i) / L ≥ 0,   ∇c_i = ∇φ(x_i) / L,   ∇²c_i = ∇²φ(x_i) / L,
///
/// φ the body's signed distance at its current placement and L a length of
/// the scene (its size), so that a constraint tolerance is a penetration
/// relative to the scene, as the other sets' rows are dimensionless.
///
/// Rows are kept for the candidate nodes only: the colliding nodes with
/// φ(x_i) < margin at the configuration of the last refresh() (the rest
/// positions at construction). A solver moves nodes only within one solve,
/// so the runner refreshes between solves and re-solves when rows_suffice() finds
/// a node outside the candidates inside the body (docs/contact.md). With
/// Ipopt's sign convention an active row has λ_i ≤ 0 and the body pushes
/// node i with the force −λ_i ∇φ / L.
///
/// Under Projection::clamp each λ_i∇²c_i is projected onto the PSD cone.
class BodyGaps final : public ConstraintSet {
public:
    /// `rest_coordinates` node-major (the layout of x); `nodes` the nodes
    /// that collide, each once (empty: every node); `length` L > 0 and
    /// `margin` ≥ 0 in metres. InputError for a null body or one of another
    /// dimension, rest coordinates of another size or not finite, a node out
    /// of range or listed twice, a non-positive or non-finite L, a negative
    /// or non-finite margin.
    BodyGaps(int dimension, int num_nodes, std::shared_ptr<const PlacedBody> body,
             const Eigen::VectorXd& rest_coordinates, std::vector<int> nodes, double length, double margin);

    std::string name() const override { return "gaps to body '" + body_->name() + "'"; }
    int num_constraints() const override { return static_cast<int>(candidates_.size()); }
    /// 0 ≤ c ≤ ∞.
    void bounds(VectorRef lower, VectorRef upper) const override;
    void values(ConstVectorRef x, VectorRef c) override;
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override;
    const SparsityPattern& hessian_pattern() const override { return hessian_; }
    void hessian_values(ConstVectorRef x, ConstVectorRef lambda, Projection projection, VectorRef values) override;
    /// Candidates anew: the colliding nodes with φ(x_i) < margin.
    bool refresh(ConstVectorRef x) override;
    /// Whether every colliding node outside the candidates is outside the body at x.
    bool rows_suffice(ConstVectorRef x) const override;
    /// "gap" (φ at every node, m), "penetration" (max(0, −φ) at the
    /// colliding nodes, m) and "contact_force" (−λ_i∇φ/L, N).
    void add_output_data(ConstVectorRef x, ConstVectorRef multipliers, OutputArrays& arrays) override;

    const PlacedBody& body() const { return *body_; }
    /// The candidate nodes, in row order.
    const std::vector<int>& candidates() const { return candidates_; }
    /// The largest −φ over the colliding nodes at x (0 when none is inside), m.
    double max_penetration(ConstVectorRef x) const;
    /// Σ_i −λ_i ∇φ_i / L: the force the body exerts on the mesh, N.
    Eigen::Vector3d total_force(ConstVectorRef x, ConstVectorRef multipliers) const;

private:
    BodyDistance at_node(ConstVectorRef x, int node) const;
    /// The colliding nodes with φ(x_i) < margin.
    std::vector<int> candidates_at(ConstVectorRef x) const;
    /// Jacobian and Hessian patterns of the candidates.
    void build_patterns();

    int dimension_;
    int num_nodes_;
    std::shared_ptr<const PlacedBody> body_;
    std::vector<int> nodes_;
    double length_;  ///< L, m
    double margin_;  ///< m
    std::vector<int> candidates_;
    SparsityPattern jacobian_, hessian_;
};

} // namespace sinew
