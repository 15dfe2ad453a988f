#pragma once
#include "sinew/energies/constraints/fiber_inextensibility.hpp"

#include <memory>
#include <vector>

namespace sinew {

/// Fiber inextensibility in weak form on a coarse background grid, one
/// multiplier per grid cell (P0, as seed 004 §4.2.2 does on the MPM grid
/// with one λ_z per cell z):
///
///     c_z(x) = Σ_{e ∈ z} V_e (a₀ᵀ C_e a₀ − 1),
///
/// e ∈ z when the element's rest centroid lies in cell z of a regular grid
/// of `cells` over the rest mesh's bounding box; V_e the element's rest
/// measure. Cells that hold no listed element carry no constraint. With
/// enough elements per cell the rows are independent where the per-element
/// form (FiberInextensibility) is rank-deficient. ∇²c_z = Σ V_e ∇²c_e is PSD;
/// under Projection::clamp λ_z is replaced by max(λ_z, 0).
class WeakFiberInextensibility final : public ConstraintSet {
public:
    /// `elements` and `fibers` as for FiberInextensibility; `cells` the grid
    /// size per space dimension (each ≥ 1). InputError as FiberInextensibility,
    /// or for a cell count below 1.
    WeakFiberInextensibility(const Mesh& mesh, std::vector<int> elements, const Eigen::MatrixXd& fibers,
                             const Eigen::VectorXi& cells);

    std::string name() const override { return "weak fiber inextensibility"; }
    int num_constraints() const override { return static_cast<int>(cell_of_row_.size()); }
    void values(ConstVectorRef x, VectorRef c) override;
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override;
    const SparsityPattern& hessian_pattern() const override { return per_element_->hessian_pattern(); }
    void hessian_values(ConstVectorRef x, ConstVectorRef lambda, Projection projection, VectorRef values) override;

    /// The grid cell (linear index) of each constraint row.
    const std::vector<int>& cell_of_row() const { return cell_of_row_; }
    /// The constraint row of each listed element.
    const std::vector<int>& row_of_element() const { return row_of_element_; }

private:
    std::unique_ptr<FiberInextensibility> per_element_;
    Eigen::VectorXd volumes_;          ///< V_e of each listed element
    std::vector<int> row_of_element_;  ///< z(e), as a constraint row
    std::vector<int> cell_of_row_;
    SparsityPattern jacobian_;         ///< the per-element pattern with rows mapped to cells
    Eigen::VectorXd scratch_;          ///< per-element c, J or λ values
};

} // namespace sinew
