#pragma once
#include "sinew/problems/nlp.hpp"
#include "sinew/solvers/constrained/equality_constraints.hpp"
#include "sinew/solvers/newton/kkt_matrix.hpp"

namespace sinew {

/// The augmented Lagrangian of an equality-constrained NLP, as a problem with
/// the original bounds and no constraints (Ipopt's sign convention, λ as in
/// ∇f + Jᵀλ = 0):
///
///     φ(x) = f(x) + λᵀc̃(x) + κ/2 ‖c̃(x)‖²,      ∇φ = ∇f + Jᵀ(λ + κc̃),
///     ∇²φ = ∇²f + Σᵢ (λᵢ + κc̃ᵢ) ∇²cᵢ + κ JᵀJ.
///
/// λ = 0 is the quadratic penalty E + κ/2‖c‖² (seed 004 §4.3). With
/// Projection::clamp every term of the problem's Lagrangian Hessian, the
/// constraint curvature (λᵢ + κc̃ᵢ)∇²cᵢ included, is projected by the
/// problem; κJᵀJ is PSD already.
class AugmentedLagrangianFunction final : public Nlp {
public:
    explicit AugmentedLagrangianFunction(Nlp& problem);

    /// The multipliers λ and the stiffness κ > 0 of the next evaluations.
    void set_parameters(const Eigen::VectorXd& lambda, double kappa);
    /// Where the next minimization starts.
    void set_starting_point(const Eigen::VectorXd& x) { start_ = x; }
    /// At the last point whose gradient was evaluated: f, ∇f and c̃.
    double last_objective() const { return last_f_; }
    const Eigen::VectorXd& last_objective_gradient() const { return last_g_; }
    const Eigen::VectorXd& last_residuals() const { return c_; }
    /// J's values at the last point whose gradient or Hessian was evaluated.
    const Eigen::VectorXd& last_jacobian() const { return jacobian_; }
    EqualityConstraints& equality_constraints() { return constraints_; }

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
    void fill(ConstVectorRef x, double sigma, Projection projection, VectorRef values);

    Nlp& problem_;
    EqualityConstraints constraints_;
    SchurComplementPattern schur_;
    Eigen::VectorXd lambda_, start_;
    double kappa_ = 1.0;
    double last_f_ = 0.0;
    Eigen::VectorXd objective_x_;  ///< where objective() last evaluated f, and its value
    double objective_f_ = 0.0;
    Eigen::VectorXd last_g_;
    Eigen::VectorXd x_, c_, jacobian_, weights_, problem_hessian_, values_, constraint_gradient_;  ///< scratch
};

} // namespace sinew
