#include "sinew/solvers/newton/active_bounds.hpp"

#include <algorithm>

namespace sinew {

ActiveBounds::ActiveBounds(const Nlp& nlp)
    : lower_(nlp.num_variables()), upper_(nlp.num_variables()), fixed_(static_cast<size_t>(nlp.num_variables()), 0)
{
    nlp.variable_bounds(lower_, upper_);
    for (Eigen::Index i = 0; i < lower_.size(); ++i) {
        if (!is_finite_bound(lower_[i]))
            lower_[i] = -kInfinity;
        if (!is_finite_bound(upper_[i]))
            upper_[i] = kInfinity;
        any_ = any_ || std::isfinite(lower_[i]) || std::isfinite(upper_[i]);
    }
}

void ActiveBounds::project(Eigen::VectorXd& x) const
{
    if (any_)
        x = x.cwiseMax(lower_).cwiseMin(upper_);
}

double ActiveBounds::projected_gradient_norm(const Eigen::VectorXd& x, const Eigen::VectorXd& g) const
{
    if (!any_)
        return g.cwiseAbs().maxCoeff();
    return (x - (x - g).cwiseMax(lower_).cwiseMin(upper_)).cwiseAbs().maxCoeff();
}

void ActiveBounds::update(const Eigen::VectorXd& x, const Eigen::VectorXd& g)
{
    if (!any_)
        return;
    const double epsilon = std::min(1e-3, projected_gradient_norm(x, g));
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        const bool at_lower = x[i] <= lower_[i] + epsilon && g[i] > 0.0;
        const bool at_upper = x[i] >= upper_[i] - epsilon && g[i] < 0.0;
        fixed_[static_cast<size_t>(i)] = at_lower || at_upper;
    }
}

void ActiveBounds::multipliers(const Eigen::VectorXd& x, const Eigen::VectorXd& g, Eigen::VectorXd& z_lower,
                               Eigen::VectorXd& z_upper) const
{
    z_lower = Eigen::VectorXd::Zero(x.size());
    z_upper = Eigen::VectorXd::Zero(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        if (x[i] <= lower_[i] && g[i] > 0.0)
            z_lower[i] = g[i];
        else if (x[i] >= upper_[i] && g[i] < 0.0)
            z_upper[i] = -g[i];
    }
}

} // namespace sinew
