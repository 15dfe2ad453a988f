#pragma once
// Fitting a muscle-driven facial rig to landmark targets (seed 000 §1) as an NLP.
#include "sinew/energies/constraints/orthogonality.hpp"
#include "sinew/inverse/muscle_rig.hpp"
#include "sinew/problems/nlp.hpp"

#include <memory>
#include <optional>
#include <string>

namespace sinew {

/// How the orthogonality of M_c and M_j enters the fit.
enum class OrthogonalityForm {
    /// M_cᵀM_c = I and M_jᵀM_j = I as 12 equality constraints (Orthogonality).
    constraints,
    /// The seed's form (§2.2–2.3): extra energy terms k/2 ‖MᵀM − I‖²_F for both
    /// maps, no constraints; the violation it leaves is reported as it is.
    penalty,
    /// M = R(ω): rotations by construction, nothing to constrain; fitted by
    /// RotationVectorFitProblem (RigFitProblem refuses it).
    rotation_vectors,
};
std::string to_string(OrthogonalityForm form);
/// The form to_string() names; InputError for any other text.
OrthogonalityForm orthogonality_form(const std::string& name);

struct RigFitSettings {
    OrthogonalityForm orthogonality = OrthogonalityForm::constraints;
    /// τ of the Tikhonov term τ/2 ‖α‖² (m²); 0: none.
    double tikhonov = 0.0;
    /// w of the penalty form: k = w · landmarks · size² (m²), so that an
    /// orthogonality error ε costs about what a landmark error of ε · size
    /// does on every landmark.
    double penalty_weight = 1.0;
};

/// minimize ½‖S x̂(θ) − x*‖² + τ/2 ‖α‖² (+ the penalty terms) over θ = (α ∈ [0, 1],
/// M_c, t_c, M_j, t_j) (rig_parameters.hpp), subject to M_cᵀM_c = I, M_jᵀM_j = I
/// (constraints form). x̂(θ) is a nested equilibrium solve (MuscleRig):
///   - objective +∞ where the inner solve fails (a failed evaluation: the
///     solvers' line searches back off); the gradient and Hessian are then
///     not asked for (the Nlp contract) and throw std::runtime_error if they are;
///   - gradient exact, by the adjoint (one solve with the equilibrium's factors);
///   - Hessian of the objective by Gauss-Newton, JᵀJ + τ I_α (J = ∂(S x̂)/∂θ,
///     forward sensitivities) and k J_Rᵀ W J_R for the penalty residuals;
///     with the exact Σλ∇²c of the constraints. exact_hessian() is false, so
///     Ipopt runs its limited-memory mode unless told hessian_approximation=exact.
/// Evaluations are cached by θ (the rig does not re-solve at its last θ).
/// Activations are evaluated clamped to [0, 1]: Ipopt evaluates up to
/// bound_relax_factor outside its bounds.
class RigFitProblem final : public Nlp {
public:
    /// `targets`: 3 per landmark (m). InputError for targets of the wrong size
    /// or not finite, a negative τ, a non-positive penalty weight or the
    /// rotation_vectors form.
    RigFitProblem(MuscleRig& rig, Eigen::VectorXd targets, RigFitSettings settings,
                  std::optional<RigParameters> start = std::nullopt);
    /// The same, owning the rig (a problem handed on as an Nlp alone).
    RigFitProblem(std::shared_ptr<MuscleRig> rig, Eigen::VectorXd targets, RigFitSettings settings,
                  std::optional<RigParameters> start = std::nullopt);

    std::string name() const override { return "rig fit (" + to_string(settings_.orthogonality) + ")"; }
    int num_variables() const override { return rig_.num_parameters(); }
    int num_constraints() const override;
    void variable_bounds(VectorRef lower, VectorRef upper) const override;
    void constraint_bounds(VectorRef lower, VectorRef upper) const override;
    Vector starting_point() const override { return start_; }

    double objective(ConstVectorRef theta) override;
    void gradient(ConstVectorRef theta, VectorRef grad) override;
    void constraints(ConstVectorRef theta, VectorRef c) override;
    const SparsityPattern& jacobian_pattern() const override { return jacobian_pattern_; }
    void jacobian_values(ConstVectorRef theta, VectorRef values) override;
    const SparsityPattern& hessian_pattern() const override { return hessian_pattern_; }
    bool supports(Projection) const override { return true; }
    bool exact_hessian() const override { return false; }

    /// ‖M_cᵀM_c − I‖_F and ‖M_jᵀM_j − I‖_F at θ.
    double cranium_violation(ConstVectorRef theta) const { return cranium_.violation(theta); }
    double jaw_violation(ConstVectorRef theta) const { return jaw_.violation(theta); }
    /// Landmark residual S x̂(θ) − x* (evaluating θ; InputError-free: throws
    /// std::runtime_error where the inner solve fails).
    Eigen::VectorXd residual(ConstVectorRef theta);
    /// J = ∂(S x̂)/∂θ at θ (forward sensitivities, kept for the last θ).
    /// std::runtime_error where the inner solve fails.
    const Eigen::MatrixXd& landmark_jacobian(ConstVectorRef theta);
    /// ∂c/∂θ of M_cᵀM_c − I and M_jᵀM_j − I (12 × n, dense) in either form.
    Eigen::MatrixXd orthogonality_jacobian(ConstVectorRef theta);
    const MuscleRig& rig() const { return rig_; }
    const RigFitSettings& settings() const { return settings_; }

protected:
    void hessian_values(ConstVectorRef theta, double sigma, ConstVectorRef lambda, VectorRef values) override;
    void projected_hessian_values(ConstVectorRef theta, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    /// Evaluates the rig at θ (activations clamped); false where the inner solve fails.
    bool evaluate(ConstVectorRef theta);
    void require(ConstVectorRef theta);
    /// k/2 Σ_p w_p c_p² over both maps (w = 1 on the diagonal pairs, 2 off it: ‖·‖²_F).
    double penalty(ConstVectorRef theta);
    void fill_hessian(ConstVectorRef theta, double sigma, ConstVectorRef lambda, Projection projection,
                      VectorRef values);

    std::shared_ptr<MuscleRig> owned_rig_;  ///< null unless the problem owns its rig
    MuscleRig& rig_;
    Eigen::VectorXd targets_;
    RigFitSettings settings_;
    Vector start_;
    double penalty_stiffness_ = 0.0;  ///< k
    Orthogonality cranium_;
    Orthogonality jaw_;
    SparsityPattern jacobian_pattern_;
    SparsityPattern hessian_pattern_;   ///< dense lower triangle
    std::optional<Eigen::VectorXd> landmark_jacobian_at_;  ///< θ of the cached J
    Eigen::MatrixXd landmark_jacobian_;
};

} // namespace sinew
