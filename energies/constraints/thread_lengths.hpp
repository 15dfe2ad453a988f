#pragma once
#include "sinew/energies/constraints/constraint_set.hpp"

#include <utility>
#include <vector>

namespace sinew {

/// Inextensible threads: polylines through mesh nodes whose segments keep
/// their rest lengths (DESIGN.md, "Constraints"; the discrete form of seed 004
/// §4.1's a₀ᵀ C a₀ = 1 along a thread). One constraint per segment (i, j):
///
///     c(x) = |x_j − x_i|² / L_ij² − 1,    L_ij = |X_j − X_i|,
///
///     ∂c/∂x_i = −2 (x_j − x_i) / L²,   ∂c/∂x_j = 2 (x_j − x_i) / L²,
///     ∇²c = 2/L² [I −I; −I I]   (constant, PSD).
///
/// c is the segment's squared stretch minus one, dimensionless like
/// a₀ᵀCa₀ − 1, so that a constraint tolerance means the same relative length
/// error on every segment whatever its length.
///
/// Under Projection::clamp λ∇²c is projected onto the PSD cone: max(λ, 0)∇²c.
///
/// Constraints are the segments of the polylines in order (polyline by
/// polyline, consecutive node pairs). Jacobian pattern: row k, the
/// coordinates of i then of j. Hessian pattern per segment and coordinate m:
/// (i[m], i[m]), (j[m], j[m]), (max, min) of (i[m], j[m]). Segments sharing a
/// node repeat diagonal entries; repeated entries are summed.
class ThreadLengths final : public ConstraintSet {
public:
    /// `rest_coordinates` node-major, [X₀ Y₀ (Z₀) X₁ …], dimension · num_nodes
    /// entries (the layout of x); `polylines` node index sequences, each of at
    /// least 2 nodes (a closed thread repeats its first node at the end).
    /// InputError, one line naming what is wrong: a dimension other than 2
    /// or 3, rest coordinates of another size or not finite, a polyline of
    /// fewer than 2 nodes, a node index out of range, a node repeated
    /// consecutively, a segment of zero rest length, a segment listed twice.
    ThreadLengths(int num_nodes, int dimension, const Eigen::VectorXd& rest_coordinates,
                  const std::vector<std::vector<int>>& polylines);

    std::string name() const override { return "thread lengths"; }
    int num_constraints() const override { return static_cast<int>(segments_.size()); }
    /// c_k = |x_j − x_i|² / L_k² − 1 for segment k = (i, j).
    void values(ConstVectorRef x, VectorRef c) override;
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override;
    const SparsityPattern& hessian_pattern() const override { return hessian_; }
    void hessian_values(ConstVectorRef x, ConstVectorRef lambda, Projection projection, VectorRef values) override;

    int dimension() const { return dimension_; }
    /// The segments (i, j) in constraint order, and their rest lengths L.
    const std::vector<std::pair<int, int>>& segments() const { return segments_; }
    const std::vector<double>& rest_lengths() const { return rest_lengths_; }

private:
    int dimension_;
    std::vector<std::pair<int, int>> segments_;
    std::vector<double> rest_lengths_;
    SparsityPattern jacobian_, hessian_;
};

} // namespace sinew
