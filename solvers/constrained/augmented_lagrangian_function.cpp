#include "sinew/solvers/constrained/augmented_lagrangian_function.hpp"

#include <cmath>

namespace sinew {

AugmentedLagrangianFunction::AugmentedLagrangianFunction(Nlp& problem)
    : problem_(problem), constraints_(problem),
      schur_(problem.hessian_pattern(), problem.jacobian_pattern(), problem.num_constraints()),
      lambda_(Eigen::VectorXd::Zero(problem.num_constraints())), start_(problem.starting_point()),
      c_(problem.num_constraints()), r_(problem.num_constraints()), multipliers_(problem.num_constraints()),
      active_(problem.num_constraints()), jacobian_(problem.jacobian_pattern().nonzeros()),
      active_jacobian_(problem.jacobian_pattern().nonzeros()), weights_(problem.num_constraints()),
      problem_hessian_(problem.hessian_pattern().nonzeros()), values_(schur_.pattern().nonzeros()),
      constraint_gradient_(problem.num_variables())
{
}

void AugmentedLagrangianFunction::set_parameters(const Eigen::VectorXd& lambda, double kappa)
{
    lambda_ = lambda;
    kappa_ = kappa;
}

void AugmentedLagrangianFunction::evaluate_rows()
{
    constraints_.values(x_, c_);
    constraints_.shifted(c_, lambda_, kappa_, r_, multipliers_, active_);
}

double AugmentedLagrangianFunction::objective(ConstVectorRef x)
{
    const double f = problem_.objective(x);
    objective_x_ = x;
    objective_f_ = f;
    if (!std::isfinite(f))
        return f;
    x_ = x;
    evaluate_rows();
    return f + lambda_.dot(r_) + 0.5 * kappa_ * r_.squaredNorm();  // φ = f + Σ λᵢrᵢ + κ/2 rᵢ²
}

void AugmentedLagrangianFunction::gradient(ConstVectorRef x, VectorRef grad)
{
    x_ = x;
    problem_.gradient(x_, grad);
    last_g_ = grad;
    // f is known when the line search's accepted point is this x (it usually is).
    last_f_ = x_ == objective_x_ ? objective_f_ : problem_.objective(x_);
    evaluate_rows();
    last_violation_ = constraints_.max_violation(c_);
    constraints_.jacobian(x_, jacobian_);
    constraints_.transpose_times(jacobian_, multipliers_, constraint_gradient_);
    grad += constraint_gradient_;  // ∇φ = ∇f + Jᵀμ
}

void AugmentedLagrangianFunction::fill(ConstVectorRef x, double sigma, Projection projection, VectorRef values)
{
    x_ = x;
    evaluate_rows();
    constraints_.jacobian(x_, jacobian_);
    weights_ = sigma * multipliers_;
    // σ∇²f + Σᵢ σμᵢ∇²cᵢ, then + σκ Σ_{i active} ∇cᵢ∇cᵢᵀ: the Schur pattern
    // keeps every row, an inactive one with its Jacobian row zeroed.
    problem_.hessian(x_, sigma, weights_, projection, problem_hessian_);
    constraints_.scale_rows(jacobian_, active_, active_jacobian_);
    schur_.fill(problem_hessian_, active_jacobian_, sigma * kappa_, values_);
    values = values_;
}

void AugmentedLagrangianFunction::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    fill(x, sigma, Projection::none, values);
}

void AugmentedLagrangianFunction::projected_hessian_values(ConstVectorRef x, double sigma, ConstVectorRef,
                                                           VectorRef values)
{
    fill(x, sigma, Projection::clamp, values);
}

} // namespace sinew
