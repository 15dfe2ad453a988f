#pragma once
// The rig fit over rotation vectors: the maps are rotations by construction,
// so there is nothing to constrain (the unconstrained baseline).
#include "sinew/inverse/rig_fit_problem.hpp"

#include <optional>

namespace sinew {

/// minimize ½‖S x̂(θ(φ)) − x*‖² + τ/2 ‖α‖² over φ = (α ∈ [0, 1], ω_c, t_c, ω_j,
/// t_j): 12 fewer variables than θ, M_c = R(ω_c), M_j = R(ω_j)
/// (core/rotation_vector.hpp), no constraints. Values and the adjoint
/// gradient come from a RigFitProblem on θ (its constraint form, whose
/// constraints are not used): ∇_φ f = Dᵀ ∇_θ f, D = ∂θ/∂φ; Hessian by
/// Gauss-Newton, Dᵀ(JᵀJ + τE_α)D, which is exactly the Gauss-Newton matrix of
/// the composed residual (not exact: exact_hessian() is false).
class RotationVectorFitProblem final : public Nlp {
public:
    /// InputError as RigFitProblem's, and for starting maps that are not
    /// rotations (‖MᵀM − I‖_F > 1e-9 or det M < 0).
    RotationVectorFitProblem(MuscleRig& rig, Eigen::VectorXd targets, RigFitSettings settings,
                             std::optional<RigParameters> start = std::nullopt);

    std::string name() const override { return "rig fit (rotation vectors)"; }
    int num_variables() const override { return affine_.rig().num_muscles() + 12; }
    void variable_bounds(VectorRef lower, VectorRef upper) const override;
    Vector starting_point() const override { return start_; }

    double objective(ConstVectorRef phi) override { return affine_.objective(affine_parameters(phi)); }
    void gradient(ConstVectorRef phi, VectorRef grad) override;
    const SparsityPattern& hessian_pattern() const override { return hessian_pattern_; }
    bool supports(Projection) const override { return true; }
    bool exact_hessian() const override { return false; }

    /// θ(φ): the packed affine parameters (rig_parameters.hpp) of φ.
    Eigen::VectorXd affine_parameters(ConstVectorRef phi) const;
    /// The problem on θ that evaluates this one.
    RigFitProblem& affine_problem() { return affine_; }

protected:
    void hessian_values(ConstVectorRef phi, double sigma, ConstVectorRef lambda, VectorRef values) override;
    /// Gauss-Newton is positive semidefinite already: the same values.
    void projected_hessian_values(ConstVectorRef phi, double sigma, ConstVectorRef lambda, VectorRef values) override
    {
        hessian_values(phi, sigma, lambda, values);
    }

private:
    /// D = ∂θ/∂φ, (muscles + 24) × (muscles + 12).
    Eigen::MatrixXd parameter_jacobian(ConstVectorRef phi) const;

    RigFitProblem affine_;
    Vector start_;
    SparsityPattern hessian_pattern_;   ///< dense lower triangle
};

} // namespace sinew
