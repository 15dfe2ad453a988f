#pragma once
#include "sinew/energies/constraints/constraint_set.hpp"

#include <string>

namespace sinew {

/// MᵀM = I for a 3×3 matrix M stored row by row in x (entry `offset` + 3k + i
/// is M_ki): the orthogonality of the cranium and jaw maps of seed 000
/// §2.2–2.3, as constraints (DESIGN.md, "Constraints"). One constraint per
/// entry i ≤ j of the symmetric MᵀM (6), in the order (0,0) (0,1) (0,2)
/// (1,1) (1,2) (2,2):
///
///     c_ij = Σ_k M_ki M_kj − δ_ij,
///     ∂c_ij/∂M_ki = M_kj,  ∂c_ij/∂M_kj = M_ki  (2M_ki when i = j),
///     ∂²c_ij/∂M_ki∂M_kj = 1 (i ≠ j),  ∂²c_ii/∂M_ki² = 2,  all others 0.
///
/// Under Projection::clamp each λ_ij∇²c_ij is projected onto the PSD cone:
/// for i = j, max(2λ, 0) on the diagonal; for i ≠ j, each k's 2×2 block
/// λ[0 1; 1 0] (eigenvalues ±λ) becomes (|λ|/2)[1 s; s 1], s = sign λ.
class Orthogonality final : public ConstraintSet {
public:
    /// `name` for messages ("cranium", "jaw"); `offset` the index of M_00 in x;
    /// InputError for a negative offset.
    Orthogonality(std::string name, int offset);

    std::string name() const override { return name_ + " orthogonality"; }
    int num_constraints() const override { return 6; }
    void values(ConstVectorRef x, VectorRef c) override;
    const SparsityPattern& jacobian_pattern() const override { return jacobian_pattern_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override;
    const SparsityPattern& hessian_pattern() const override { return hessian_pattern_; }
    void hessian_values(ConstVectorRef x, ConstVectorRef lambda, Projection projection, VectorRef values) override;

    /// ‖MᵀM − I‖_F of the M stored in x.
    double violation(ConstVectorRef x) const;

private:
    /// Index in x of M_ki.
    int entry(int k, int i) const { return offset_ + 3 * k + i; }

    std::string name_;
    int offset_;
    SparsityPattern jacobian_pattern_;
    SparsityPattern hessian_pattern_;
};

} // namespace sinew
