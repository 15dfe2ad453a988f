#include "sinew/solvers/kkt_measures.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <Eigen/SparseQR>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sinew {
namespace {

struct Bounds {
    Eigen::VectorXd x_lower, x_upper, c_lower, c_upper;
};

Bounds read_bounds(const Nlp& nlp)
{
    const int n = nlp.num_variables();
    const int m = nlp.num_constraints();
    Bounds b{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(m), Eigen::VectorXd(m)};
    nlp.variable_bounds(b.x_lower, b.x_upper);
    nlp.constraint_bounds(b.c_lower, b.c_upper);
    return b;
}

/// Error of a multiplier μ on a two-sided constraint l <= v <= u, where μ > 0
/// acts on the upper bound and μ < 0 on the lower one: a sign with no bound
/// behind it, or the slack it multiplies. A bound v passes has no slack: its
/// violation is measured as infeasibility (max_constraint_violation), not
/// multiplied by μ here (Ipopt and interior-point end 1e-8 past relaxed bounds).
double sign_and_complementarity_error(double mu, double v, double lower, double upper)
{
    if (mu > 0.0)
        return is_finite_bound(upper) ? mu * std::max(0.0, upper - v) : mu;
    if (mu < 0.0)
        return is_finite_bound(lower) ? -mu * std::max(0.0, v - lower) : -mu;
    return 0.0;
}

} // namespace

double kkt_residual(Nlp& nlp, Nlp::ConstVectorRef x, Nlp::ConstVectorRef lambda, Nlp::ConstVectorRef z_lower,
                    Nlp::ConstVectorRef z_upper)
{
    const int n = nlp.num_variables();
    const int m = nlp.num_constraints();
    const Bounds b = read_bounds(nlp);

    // Stationarity: ∇f + Jᵀλ − z_L + z_U.
    Eigen::VectorXd r(n);
    nlp.gradient(x, r);
    r += z_upper - z_lower;
    Eigen::VectorXd c(m);
    if (m > 0) {
        const SparsityPattern& pattern = nlp.jacobian_pattern();
        Eigen::VectorXd values(pattern.nonzeros());
        nlp.jacobian_values(x, values);
        for (int k = 0; k < pattern.nonzeros(); ++k)
            r[pattern.cols[k]] += values[k] * lambda[pattern.rows[k]];
        nlp.constraints(x, c);
    }
    double error = r.cwiseAbs().maxCoeff();
    if (!std::isfinite(error))
        return kInfinity;

    for (int i = 0; i < m; ++i)
        if (b.c_lower[i] != b.c_upper[i])
            error = std::max(error, sign_and_complementarity_error(lambda[i], c[i], b.c_lower[i], b.c_upper[i]));
    for (int j = 0; j < n; ++j) {
        // z_L = −μ on the lower bound, z_U = μ on the upper one.
        error = std::max(error, sign_and_complementarity_error(-z_lower[j], x[j], b.x_lower[j], kInfinity));
        error = std::max(error, sign_and_complementarity_error(z_upper[j], x[j], -kInfinity, b.x_upper[j]));
    }
    return error;
}

void estimate_multipliers(Nlp& nlp, Nlp::ConstVectorRef x, double active_tolerance, Eigen::VectorXd& lambda,
                          Eigen::VectorXd& z_lower, Eigen::VectorXd& z_upper)
{
    const int n = nlp.num_variables();
    const int m = nlp.num_constraints();
    const Bounds b = read_bounds(nlp);
    lambda = Eigen::VectorXd::Zero(m);
    z_lower = Eigen::VectorXd::Zero(n);
    z_upper = Eigen::VectorXd::Zero(n);

    auto near = [&](double value, double bound) {
        return is_finite_bound(bound) && std::abs(value - bound) <= active_tolerance * std::max(1.0, std::abs(bound));
    };
    auto violated = [](double value, double lower, double upper) { return value < lower || value > upper; };

    Eigen::VectorXd c(m);
    if (m > 0)
        nlp.constraints(x, c);

    // Columns of M: ∇cᵢ of each active constraint, then eⱼ of each active bound.
    std::vector<int> active_constraints;
    for (int i = 0; i < m; ++i)
        if (b.c_lower[i] == b.c_upper[i] || near(c[i], b.c_lower[i]) || near(c[i], b.c_upper[i]) ||
            violated(c[i], b.c_lower[i], b.c_upper[i]))
            active_constraints.push_back(i);
    std::vector<int> active_bounds;
    for (int j = 0; j < n; ++j)
        if (near(x[j], b.x_lower[j]) || near(x[j], b.x_upper[j]))
            active_bounds.push_back(j);
    const int columns = static_cast<int>(active_constraints.size() + active_bounds.size());
    if (columns == 0)
        return;

    std::vector<int> column_of_constraint(m, -1);
    for (int a = 0; a < static_cast<int>(active_constraints.size()); ++a)
        column_of_constraint[active_constraints[a]] = a;
    std::vector<Eigen::Triplet<double>> triplets;
    if (m > 0) {
        const SparsityPattern& pattern = nlp.jacobian_pattern();
        Eigen::VectorXd values(pattern.nonzeros());
        nlp.jacobian_values(x, values);
        for (int k = 0; k < pattern.nonzeros(); ++k)
            if (column_of_constraint[pattern.rows[k]] >= 0)
                triplets.emplace_back(pattern.cols[k], column_of_constraint[pattern.rows[k]], values[k]);
    }
    const int first_bound_column = static_cast<int>(active_constraints.size());
    for (int a = 0; a < static_cast<int>(active_bounds.size()); ++a)
        triplets.emplace_back(active_bounds[a], first_bound_column + a, 1.0);
    Eigen::SparseMatrix<double> M(n, columns);
    M.setFromTriplets(triplets.begin(), triplets.end());
    M.makeCompressed();

    Eigen::VectorXd gradient(n);
    nlp.gradient(x, gradient);
    Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr(M);
    if (qr.info() != Eigen::Success)
        return;
    const Eigen::VectorXd mu = qr.solve(Eigen::VectorXd(-gradient));
    if (qr.info() != Eigen::Success || !mu.allFinite())
        return;

    for (int a = 0; a < first_bound_column; ++a)
        lambda[active_constraints[a]] = mu[a];
    for (int a = 0; a < static_cast<int>(active_bounds.size()); ++a) {
        const int j = active_bounds[a];
        const double value = mu[first_bound_column + a];
        // μⱼ = z_U − z_L: a positive μ belongs to an active upper bound.
        const bool at_upper = near(x[j], b.x_upper[j]);
        const bool at_lower = near(x[j], b.x_lower[j]);
        if (at_upper && (value >= 0.0 || !at_lower))
            z_upper[j] = value;
        else
            z_lower[j] = -value;
    }
}

} // namespace sinew
