#include "sinew/solvers/interior/slack_formulation.hpp"

namespace sinew {

SlackFormulation::SlackFormulation(Nlp& problem)
    : problem_(problem), n_(problem.num_variables()), m_(problem.num_constraints()), row_lower_(m_),
      row_upper_(m_), jacobian_pattern_(problem.jacobian_pattern()),
      problem_jacobian_nonzeros_(problem.jacobian_pattern().nonzeros())
{
    problem.constraint_bounds(row_lower_, row_upper_);
    for (int i = 0; i < m_; ++i)
        if (row_lower_[i] != row_upper_[i]) {
            jacobian_pattern_.add(i, n_ + num_slacks());  // ∂r_i/∂s_k = −1
            slack_rows_.push_back(i);
        }
}

Nlp::Vector SlackFormulation::starting_point() const
{
    Vector w(num_variables());
    w.head(n_) = problem_.starting_point();
    if (num_slacks() > 0) {
        Vector c(m_);
        problem_.constraints(w.head(n_), c);
        for (int k = 0; k < num_slacks(); ++k)
            w[n_ + k] = c[slack_rows_[static_cast<size_t>(k)]];  // s⁰ = c_I(x⁰)
    }
    return w;
}

void SlackFormulation::variable_bounds(VectorRef lower, VectorRef upper) const
{
    problem_.variable_bounds(lower.head(n_), upper.head(n_));
    for (int k = 0; k < num_slacks(); ++k) {
        lower[n_ + k] = row_lower_[slack_rows_[static_cast<size_t>(k)]];  // g_L ≤ s ≤ g_U
        upper[n_ + k] = row_upper_[slack_rows_[static_cast<size_t>(k)]];
    }
}

void SlackFormulation::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

void SlackFormulation::gradient(ConstVectorRef w, VectorRef grad)
{
    problem_.gradient(w.head(n_), grad.head(n_));
    grad.tail(num_slacks()).setZero();
}

void SlackFormulation::constraints(ConstVectorRef w, VectorRef r)
{
    problem_.constraints(w.head(n_), r);
    for (int i = 0; i < m_; ++i)
        if (row_lower_[i] == row_upper_[i])
            r[i] -= row_lower_[i];  // r_E = c_E − g_E
    for (int k = 0; k < num_slacks(); ++k)
        r[slack_rows_[static_cast<size_t>(k)]] -= w[n_ + k];  // r_I = c_I − s
}

void SlackFormulation::jacobian_values(ConstVectorRef w, VectorRef values)
{
    problem_.jacobian_values(w.head(n_), values.head(problem_jacobian_nonzeros_));
    values.tail(num_slacks()).setConstant(-1.0);
}

void SlackFormulation::hessian_values(ConstVectorRef w, double sigma, ConstVectorRef lambda, VectorRef values)
{
    problem_.hessian(w.head(n_), sigma, lambda, Projection::none, values);
}

void SlackFormulation::projected_hessian_values(ConstVectorRef w, double sigma, ConstVectorRef lambda,
                                                VectorRef values)
{
    problem_.hessian(w.head(n_), sigma, lambda, Projection::clamp, values);
}

} // namespace sinew
