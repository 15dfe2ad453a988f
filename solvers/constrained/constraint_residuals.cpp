#include "sinew/solvers/constrained/constraint_residuals.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {

ConstraintResiduals::ConstraintResiduals(Nlp& nlp)
    : nlp_(nlp), lower_(nlp.num_constraints()), upper_(nlp.num_constraints())
{
    nlp.constraint_bounds(lower_, upper_);
    for (Eigen::Index i = 0; i < lower_.size(); ++i) {
        if (lower_[i] == upper_[i])
            continue;  // an equality, whatever its value
        if (!is_finite_bound(lower_[i]))
            lower_[i] = -kInfinity;
        if (!is_finite_bound(upper_[i]))
            upper_[i] = kInfinity;
    }
}

void ConstraintResiduals::values(const Eigen::VectorXd& x, Eigen::VectorXd& c) { nlp_.constraints(x, c); }

void ConstraintResiduals::residuals(const Eigen::VectorXd& x, Eigen::VectorXd& v)
{
    nlp_.constraints(x, v);
    violations(v, v);
}

void ConstraintResiduals::violations(const Eigen::VectorXd& c, Eigen::VectorXd& v) const
{
    for (Eigen::Index i = 0; i < c.size(); ++i) {
        const double value = c[i];
        if (lower_[i] == upper_[i] || value < lower_[i])
            v[i] = value - lower_[i];
        else if (!(value <= upper_[i]))  // above, or NaN (which stays NaN)
            v[i] = value - upper_[i];
        else
            v[i] = 0.0;
    }
}

double ConstraintResiduals::max_violation(const Eigen::VectorXd& c) const
{
    double worst = 0.0;
    for (Eigen::Index i = 0; i < c.size(); ++i) {
        if (!std::isfinite(c[i]))
            return kInfinity;
        if (lower_[i] == upper_[i])
            worst = std::max(worst, std::abs(c[i] - lower_[i]));
        else
            worst = std::max({worst, lower_[i] - c[i], c[i] - upper_[i]});
    }
    return worst;
}

void ConstraintResiduals::shifted(const Eigen::VectorXd& c, const Eigen::VectorXd& lambda, double kappa,
                                  Eigen::VectorXd& r, Eigen::VectorXd& multipliers, Eigen::VectorXd& active) const
{
    for (Eigen::Index i = 0; i < c.size(); ++i) {
        const double l = lower_[i];
        const double u = upper_[i];
        if (l == u) {
            r[i] = c[i] - l;
            multipliers[i] = lambda[i] + kappa * r[i];
            active[i] = 1.0;
            continue;
        }
        const double s = c[i] + lambda[i] / kappa;  // the shifted value
        if (std::isnan(s)) {  // a non-finite c stays visible in φ, ∇φ
            r[i] = multipliers[i] = s;
            active[i] = 1.0;
        } else if (s >= u) {
            r[i] = c[i] - u;
            multipliers[i] = std::max(0.0, lambda[i] + kappa * r[i]);  // upper side: μ ≥ 0
            active[i] = 1.0;
        } else if (s <= l) {
            r[i] = c[i] - l;
            multipliers[i] = std::min(0.0, lambda[i] + kappa * r[i]);  // lower side: μ ≤ 0
            active[i] = 1.0;
        } else {
            r[i] = -lambda[i] / kappa;
            multipliers[i] = 0.0;
            active[i] = 0.0;
        }
    }
}

void ConstraintResiduals::jacobian(const Eigen::VectorXd& x, Eigen::VectorXd& values)
{
    nlp_.jacobian_values(x, values);
}

void ConstraintResiduals::transpose_times(const Eigen::VectorXd& values, const Eigen::VectorXd& v,
                                          Eigen::VectorXd& out) const
{
    const SparsityPattern& J = pattern();
    out.setZero();
    for (int k = 0; k < J.nonzeros(); ++k)
        out[J.cols[k]] += values[k] * v[J.rows[k]];
}

void ConstraintResiduals::scale_rows(const Eigen::VectorXd& values, const Eigen::VectorXd& row_weight,
                                     Eigen::VectorXd& scaled) const
{
    const SparsityPattern& J = pattern();
    for (int k = 0; k < J.nonzeros(); ++k)
        scaled[k] = values[k] * row_weight[J.rows[k]];
}

} // namespace sinew
