#pragma once
#include "sinew/energies/constraints/constraint_set.hpp"
#include "sinew/mesh/mesh.hpp"

#include <vector>

namespace sinew {

/// Inextensible fibers, one constraint per listed element (seed 004 §4.1,
/// eq. (2): tr(C M) = a₀ᵀ C a₀ = 1 with C = FᵀF, M = a₀ ⊗ a₀):
///
///     c_e(x) = a₀ᵀ C_e a₀ − 1 = |F_e a₀|² − 1,    F_e = Ds(x)·Dm⁻¹,
///
/// for tets (F 3×3), triangles in 2D (F 2×2) and triangles in 3D (membranes,
/// F 3×2, written in the element's 2D rest frame membrane_rest_frame, as the
/// elastic potential does). With b = Dm⁻¹a₀,
///
///     F a₀ = Σ_a w_a x_a,   w_a = b_{a−1} (a ≥ 1),   w₀ = −Σ_k b_k,
///
/// a fixed linear combination of the element's node positions, so
///
///     ∂c_e/∂x_a = 2 w_a (F a₀),    ∇²c_e = 2 (w wᵀ) ⊗ I,
///
/// the Hessian constant in x and positive semidefinite. Under
/// Projection::clamp the term λ_e∇²c_e is projected onto the PSD cone, which
/// for a PSD ∇²c_e is max(λ_e, 0)∇²c_e.
///
/// Fibers follow the elastic potential's convention (ElasticPotential::set_fiber,
/// Mesh::element_fibers): a direction in material space, material_dimension
/// components (for triangles in 2D the rest plane's (X, Y); for triangles in 3D
/// the element's rest frame (e₁, e₂) of membrane_rest_frame), or, for triangles
/// in 3D only, 3 components: a direction in space whose in-plane part Eᵀa is
/// taken. Each fiber is normalized here, so c_e = 0 at rest.
///
/// Jacobian pattern: row k (the k-th listed element), the coordinates of its
/// nodes, node by node in mesh order, each node's coordinates in order.
/// Hessian pattern: per listed element, the lower triangle (row ≥ col) of its
/// block: for each node pair a ≥ b (local order) and each coordinate m, the
/// entry of (x_a[m], x_b[m]). Elements sharing nodes repeat entries; repeated
/// entries are summed.
class FiberInextensibility final : public ConstraintSet {
public:
    /// `mesh` gives the kind, rest positions and element nodes; `elements`
    /// the elements that carry a constraint (each at most once), `fibers`
    /// one column a₀ per listed element (material_dimension rows, or 3 for
    /// triangles in 3D; see above). InputError, one line naming what is
    /// wrong: inconsistent mesh arrays, an element index out of range or
    /// listed twice, a fiber count or size that does not match, a zero,
    /// non-finite or (membranes) plane-normal fiber, a degenerate element.
    FiberInextensibility(const Mesh& mesh, std::vector<int> elements, const Eigen::MatrixXd& fibers);

    std::string name() const override { return "fiber inextensibility"; }
    int num_constraints() const override { return static_cast<int>(elements_.size()); }
    /// c_k = |F a₀|² − 1 for the k-th listed element.
    void values(ConstVectorRef x, VectorRef c) override;
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override;
    const SparsityPattern& hessian_pattern() const override { return hessian_; }
    /// Σ_k λ_k 2 (w wᵀ) ⊗ I (independent of x); λ_k replaced by max(λ_k, 0)
    /// under Projection::clamp.
    void hessian_values(ConstVectorRef x, ConstVectorRef lambda, Projection projection, VectorRef values) override;

    /// Cell data: "inextensible" (1 on the listed elements), their own
    /// a₀ᵀC a₀ − 1 ("inextensibility_value") and the multiplier of their row
    /// ("inextensibility_multiplier"); 0 on other elements.
    void add_output_data(ConstVectorRef x, ConstVectorRef multipliers, OutputArrays& arrays) override;
    /// The same with the k-th listed element's multiplier at row row_of[k]
    /// (the weak form's cell of the element).
    void add_element_data(ConstVectorRef x, ConstVectorRef multipliers, const std::vector<int>& row_of,
                          OutputArrays& arrays);

    ElementKind kind() const { return kind_; }
    int dimension() const { return dimension_; }
    const std::vector<int>& elements() const { return elements_; }
    /// The unit fiber a₀ of the k-th listed element in material coordinates
    /// (material_dimension components).
    const Eigen::VectorXd& fiber(int k) const { return fibers_[k]; }
    /// The weights w_a of the k-th listed element, F a₀ = Σ_a w_a x_a.
    const Eigen::VectorXd& node_weights(int k) const { return weights_[k]; }

private:
    /// A vector of space dimension entries, on the stack.
    using SpaceVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
    /// F a₀ = Σ_a w_a x_a of the k-th listed element.
    SpaceVector stretched_fiber(ConstVectorRef x, int k) const;

    ElementKind kind_;
    int dimension_;                        ///< space dimension
    int nodes_per_element_;
    std::vector<int> elements_;
    Eigen::MatrixXi element_nodes_;        ///< nodes of each listed element, one column each
    std::vector<Eigen::VectorXd> fibers_;  ///< unit a₀ in material coordinates
    std::vector<Eigen::VectorXd> weights_; ///< w = (−Σ b, b), b = Dm⁻¹a₀
    SparsityPattern jacobian_, hessian_;
};

} // namespace sinew
