#pragma once
#include "sinew/problems/nlp.hpp"
#include "sinew/solvers/constrained/constraint_residuals.hpp"
#include "sinew/solvers/constrained/equality_constraints.hpp"  // refuse_inequalities, for the strategies using this
#include "sinew/solvers/newton/kkt_matrix.hpp"

namespace sinew {

/// The Powell–Hestenes–Rockafellar augmented Lagrangian of an NLP with
/// constraints g_L ≤ c(x) ≤ g_U (equalities and inequalities), as a problem
/// with the original bounds and no constraints (Ipopt's sign convention, λ as
/// in ∇f + Jᵀλ = 0; Rockafellar 1973, Nocedal & Wright §17.4). With the
/// shifted residuals r = c − P(c + λ/κ) and clipped multipliers μ (μ = λ + κr
/// on active rows, 0 on the others; ConstraintResiduals):
///
///     φ(x) = f(x) + Σᵢ (λᵢrᵢ + κ/2 rᵢ²) = f(x) + Σᵢ (μᵢ² − λᵢ²)/(2κ),
///     ∇φ = ∇f + Jᵀμ,
///     ∇²φ = ∇²f + Σᵢ μᵢ ∇²cᵢ + κ Σ_{i active} ∇cᵢ∇cᵢᵀ.
///
/// On equality rows r = c − g_L: φ = f + λᵀc̃ + κ/2‖c̃‖². An inequality row
/// adds nothing to the Hessian where it is inactive (its entries stay in the
/// pattern with zero weight); φ is C¹ and ∇²φ jumps where a row's shifted
/// value c + λ/κ crosses a side. λ = 0 is the quadratic penalty
/// E + κ/2‖c − P(c)‖² (seed 004 §4.3). With Projection::clamp every term of
/// the problem's Lagrangian Hessian, the constraint curvature μᵢ∇²cᵢ
/// included, is projected by the problem; κJᵀJ is PSD already.
class AugmentedLagrangianFunction final : public Nlp {
public:
    explicit AugmentedLagrangianFunction(Nlp& problem);

    /// The multipliers λ and the stiffness κ > 0 of the next evaluations.
    void set_parameters(const Eigen::VectorXd& lambda, double kappa);
    /// Where the next minimization starts.
    void set_starting_point(const Eigen::VectorXd& x) { start_ = x; }
    /// At the last point whose gradient was evaluated: f, ∇f, the shifted
    /// residuals r (c − g_L on equality rows; with λ = 0 the violation
    /// c − P(c)), the multipliers μ and the largest distance of c to [g_L, g_U].
    double last_objective() const { return last_f_; }
    const Eigen::VectorXd& last_objective_gradient() const { return last_g_; }
    const Eigen::VectorXd& last_residuals() const { return r_; }
    const Eigen::VectorXd& last_multipliers() const { return multipliers_; }
    double last_violation() const { return last_violation_; }
    /// J's values at the last point whose gradient or Hessian was evaluated.
    const Eigen::VectorXd& last_jacobian() const { return jacobian_; }
    ConstraintResiduals& constraint_residuals() { return constraints_; }

    std::string name() const override { return problem_.name(); }
    int num_variables() const override { return problem_.num_variables(); }
    void variable_bounds(VectorRef lower, VectorRef upper) const override { problem_.variable_bounds(lower, upper); }
    Vector starting_point() const override { return start_; }
    double objective(ConstVectorRef x) override;
    void gradient(ConstVectorRef x, VectorRef grad) override;
    const SparsityPattern& hessian_pattern() const override { return schur_.pattern(); }
    bool supports(Projection projection) const override { return problem_.supports(projection); }
    bool exact_hessian() const override { return problem_.exact_hessian(); }
    NearNullSpace near_null_space(ConstVectorRef x) const override { return problem_.near_null_space(x); }

protected:
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;
    void projected_hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    /// c, r, μ and the active rows at x_.
    void evaluate_rows();
    void fill(ConstVectorRef x, double sigma, Projection projection, VectorRef values);

    Nlp& problem_;
    ConstraintResiduals constraints_;
    SchurComplementPattern schur_;
    Eigen::VectorXd lambda_, start_;
    double kappa_ = 1.0;
    double last_f_ = 0.0;
    double last_violation_ = 0.0;
    Eigen::VectorXd objective_x_;  ///< where objective() last evaluated f, and its value
    double objective_f_ = 0.0;
    Eigen::VectorXd last_g_;
    Eigen::VectorXd x_, c_, r_, multipliers_, active_, jacobian_, active_jacobian_, weights_, problem_hessian_,
        values_, constraint_gradient_;  ///< scratch
};

} // namespace sinew
