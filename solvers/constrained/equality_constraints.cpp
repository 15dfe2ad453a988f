#include "sinew/solvers/constrained/equality_constraints.hpp"

namespace sinew {

EqualityConstraints::EqualityConstraints(Nlp& nlp) : nlp_(nlp), target_(nlp.num_constraints())
{
    Eigen::VectorXd upper(target_.size());
    nlp.constraint_bounds(target_, upper);
}

void EqualityConstraints::residuals(const Eigen::VectorXd& x, Eigen::VectorXd& c)
{
    nlp_.constraints(x, c);
    c -= target_;
}

void EqualityConstraints::jacobian(const Eigen::VectorXd& x, Eigen::VectorXd& values)
{
    nlp_.jacobian_values(x, values);
}

void EqualityConstraints::transpose_times(const Eigen::VectorXd& values, const Eigen::VectorXd& v,
                                          Eigen::VectorXd& out) const
{
    const SparsityPattern& J = pattern();
    out.setZero();
    for (int k = 0; k < J.nonzeros(); ++k)
        out[J.cols[k]] += values[k] * v[J.rows[k]];
}

std::optional<std::string> refuse_inequalities(const std::string& solver, const Nlp& nlp)
{
    const NlpCapabilities kind = capabilities_of(nlp);
    if (kind.unconstrained())
        return solver + " is a strategy for constraints and bounds, and this problem has neither; use "
                        "projected-newton";
    if (kind.has_inequalities)
        return solver + " takes equality constraints and bounds only (this problem has " + kind.describe() +
               "); use ipopt for inequality constraints";
    return std::nullopt;
}

} // namespace sinew
