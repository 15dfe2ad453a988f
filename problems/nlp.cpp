#include "sinew/problems/nlp.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sinew {

void Nlp::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setConstant(-kInfinity);
    upper.setConstant(kInfinity);
}

void Nlp::constraint_bounds(VectorRef, VectorRef) const {}

void Nlp::constraints(ConstVectorRef, VectorRef) {}

const SparsityPattern& Nlp::jacobian_pattern() const { return empty_pattern_; }

void Nlp::jacobian_values(ConstVectorRef, VectorRef) {}

void Nlp::hessian(ConstVectorRef x, double sigma, ConstVectorRef lambda, Projection projection, VectorRef values)
{
    if (!supports(projection))
        throw std::logic_error(name() + " does not support Hessian projection " + to_string(projection));
    if (projection == Projection::none)
        hessian_values(x, sigma, lambda, values);
    else
        projected_hessian_values(x, sigma, lambda, values);
}

void Nlp::projected_hessian_values(ConstVectorRef, double, ConstVectorRef, VectorRef)
{
    throw std::logic_error(name() + " offers no projected Hessian");
}

NlpCapabilities capabilities_of(const Nlp& nlp)
{
    NlpCapabilities kind;
    kind.exact_hessian = nlp.exact_hessian();
    kind.projected_hessian = nlp.supports(Projection::clamp);
    const int n = nlp.num_variables();
    const int m = nlp.num_constraints();
    Eigen::VectorXd xl(n), xu(n), gl(m), gu(m);
    nlp.variable_bounds(xl, xu);
    for (int i = 0; i < n; ++i)
        if (is_finite_bound(xl[i]) || is_finite_bound(xu[i]))
            kind.has_bounds = true;
    nlp.constraint_bounds(gl, gu);
    for (int i = 0; i < m; ++i) {
        if (gl[i] == gu[i])
            ++kind.num_equalities;
        else
            ++kind.num_inequalities;
    }
    kind.has_equalities = kind.num_equalities > 0;
    kind.has_inequalities = kind.num_inequalities > 0;
    return kind;
}

std::string NlpCapabilities::describe() const
{
    if (unconstrained())
        return "unconstrained";
    std::ostringstream out;
    const char* separator = "";
    if (has_bounds) {
        out << "bounds";
        separator = ", ";
    }
    if (has_equalities) {
        out << separator << num_equalities << (num_equalities == 1 ? " equality" : " equalities");
        separator = ", ";
    }
    if (has_inequalities)
        out << separator << num_inequalities << (num_inequalities == 1 ? " inequality" : " inequalities");
    return out.str();
}

double max_constraint_violation(Nlp& nlp, Nlp::ConstVectorRef x)
{
    const int n = nlp.num_variables();
    const int m = nlp.num_constraints();
    Eigen::VectorXd xl(n), xu(n);
    nlp.variable_bounds(xl, xu);
    double violation = 0.0;
    for (int i = 0; i < n; ++i)
        violation = std::max({violation, xl[i] - x[i], x[i] - xu[i]});
    if (m > 0) {
        Eigen::VectorXd gl(m), gu(m), c(m);
        nlp.constraint_bounds(gl, gu);
        nlp.constraints(x, c);
        for (int i = 0; i < m; ++i) {
            if (!std::isfinite(c[i]))
                return kInfinity;
            violation = std::max({violation, gl[i] - c[i], c[i] - gu[i]});
        }
    }
    return violation;
}

} // namespace sinew
