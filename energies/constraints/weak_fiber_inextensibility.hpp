#pragma once
#include "sinew/energies/constraints/fiber_inextensibility.hpp"

#include <memory>
#include <vector>

namespace sinew {

/// Fiber inextensibility in weak form on a coarse background grid, one
/// multiplier per grid cell (P0, as seed 004 §4.2.2 does on the MPM grid
/// with one λ_z per cell z):
///
///     c_z(x) = Σ_{e ∈ z} V_e (a₀ᵀ C_e a₀ − 1) / Σ_{e ∈ z} V_e,
///
/// e ∈ z when the element's rest centroid lies in cell z of a regular grid
/// of `cells` over the bounding box of the listed elements' rest nodes; V_e
/// the element's rest measure. Each row is the volume-weighted mean of
/// a₀ᵀCa₀ − 1 over its cell: dimensionless, so that a constraint tolerance
/// reads the same on every mesh (as Σ V_e(…) alone, with units of volume,
/// a violation of 1e-6 on a 1 mm³ cell was a mean stretch error of 100 %). Row z is cell z (x fastest), and every cell
/// must hold an element. With enough elements per cell the rows are
/// independent where the per-element form (FiberInextensibility) is
/// rank-deficient. ∇²c_z = Σ w_e ∇²c_e (w_e = V_e / Σ_{e∈z} V_e) is PSD;
/// under Projection::clamp λ_z is replaced by max(λ_z, 0).
class WeakFiberInextensibility final : public ConstraintSet {
public:
    /// `elements` and `fibers` as for FiberInextensibility; `cells` the grid
    /// size per space dimension (each ≥ 1). InputError as FiberInextensibility,
    /// for a cell count below 1, or for a cell that holds no element (named
    /// by its grid index).
    WeakFiberInextensibility(const Mesh& mesh, std::vector<int> elements, const Eigen::MatrixXd& fibers,
                             const Eigen::VectorXi& cells);

    std::string name() const override { return "weak fiber inextensibility"; }
    int num_constraints() const override { return static_cast<int>(cells_.prod()); }
    void values(ConstVectorRef x, VectorRef c) override;
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override;
    const SparsityPattern& hessian_pattern() const override { return per_element_->hessian_pattern(); }
    void hessian_values(ConstVectorRef x, ConstVectorRef lambda, Projection projection, VectorRef values) override;

    /// The constraint row, which is its grid cell z, of each listed element.
    /// The per-element data of FiberInextensibility (each element with its
    /// cell's multiplier λ_z) and "inextensibility_cell", the grid cell z of
    /// each element (−1 elsewhere).
    void add_output_data(ConstVectorRef x, ConstVectorRef multipliers, OutputArrays& arrays) override;
    const std::vector<int>& row_of_element() const { return row_of_element_; }
    /// The per-element constraints c_e = a₀ᵀC_e a₀ − 1 the rows sum.
    FiberInextensibility& per_element() { return *per_element_; }

private:
    std::unique_ptr<FiberInextensibility> per_element_;
    Eigen::VectorXd weights_;          ///< w_e = V_e / V_z(e) of each listed element
    Eigen::VectorXi cells_;            ///< grid cells per dimension
    std::vector<int> row_of_element_;  ///< z(e), as a constraint row
    SparsityPattern jacobian_;         ///< one entry per (cell row, coordinate) the cell's elements touch
    std::vector<int> entry_of_element_entry_;  ///< the entry of jacobian_ each per-element entry adds to
    Eigen::VectorXd scratch_;          ///< per-element c, J or λ values
};

} // namespace sinew
