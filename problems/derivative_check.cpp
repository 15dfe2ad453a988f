#include "sinew/problems/derivative_check.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <vector>

namespace sinew {
namespace {

/// One entry of a derivative: the analytic value and its central difference.
struct Entry {
    int row, col;
    double analytic, fd;
};

/// The worst of `entries` by |a − fd| / max(|fd|, floor), floor =
/// kRelativeErrorFloor·(the largest |a| or |fd| of this derivative): relative
/// for every entry that matters, and entries far below the derivative's scale
/// (where central differences carry only round-off) are measured against a
/// thousandth of it. A non-finite error counts as infinite.
DerivativeDiscrepancy worst_of(const std::vector<Entry>& entries)
{
    double scale = 0.0;
    for (const Entry& e : entries)
        for (const double v : {e.analytic, e.fd})
            if (std::isfinite(v))
                scale = std::max(scale, std::abs(v));
    const double floor = scale > 0.0 ? kRelativeErrorFloor * scale : 1.0;
    DerivativeDiscrepancy worst;
    worst.entries_compared = static_cast<int>(entries.size());
    worst.error_floor = floor;
    for (const Entry& e : entries) {
        double error = std::abs(e.analytic - e.fd) / std::max(std::abs(e.fd), floor);
        if (!std::isfinite(error))
            error = std::numeric_limits<double>::infinity();
        if (worst.row < 0 || error > worst.worst_relative_error) {
            worst.worst_relative_error = error;
            worst.row = e.row;
            worst.col = e.col;
            worst.analytic = e.analytic;
            worst.finite_difference = e.fd;
        }
    }
    return worst;
}

/// Empty when every pattern entry is inside the matrix (and in the lower
/// triangle, for the Hessian); otherwise says which entry is not.
std::string find_pattern_problem(const char* what, const SparsityPattern& pattern, int rows, int cols, bool lower)
{
    for (int k = 0; k < pattern.nonzeros(); ++k) {
        const int r = pattern.rows[k], c = pattern.cols[k];
        if (r < 0 || r >= rows || c < 0 || c >= cols || (lower && r < c))
            return std::string(what) + " pattern entry " + std::to_string(k) + " at (" + std::to_string(r) + ", " +
                   std::to_string(c) + ") is outside the " + (lower ? "lower triangle" : "matrix");
    }
    return {};
}

/// Dense matrix from a triplet pattern and its values; duplicates add up.
Eigen::MatrixXd densify(const SparsityPattern& pattern, const Eigen::VectorXd& values, int rows, int cols)
{
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(rows, cols);
    for (int k = 0; k < pattern.nonzeros(); ++k)
        dense(pattern.rows[k], pattern.cols[k]) += values[k];
    return dense;
}

/// ∇L = σ∇f + Jᵀλ at x.
Eigen::VectorXd lagrangian_gradient(Nlp& nlp, const Eigen::VectorXd& x, double sigma, const Eigen::VectorXd& lambda)
{
    const int n = nlp.num_variables();
    const int m = nlp.num_constraints();
    Eigen::VectorXd g(n);
    nlp.gradient(x, g);
    g *= sigma;
    if (m > 0) {
        const SparsityPattern& pattern = nlp.jacobian_pattern();
        Eigen::VectorXd values(pattern.nonzeros());
        nlp.jacobian_values(x, values);
        for (int k = 0; k < pattern.nonzeros(); ++k)
            g[pattern.cols[k]] += values[k] * lambda[pattern.rows[k]];
    }
    return g;
}

std::string describe(const char* what, const DerivativeDiscrepancy& d, bool two_indices)
{
    std::ostringstream out;
    out << what << ": ";
    if (d.entries_compared == 0) {
        out << "nothing to compare";
        return out.str();
    }
    out << "worst relative error " << d.worst_relative_error << " (floor " << d.error_floor << ") at ";
    if (two_indices)
        out << "(" << d.row << ", " << d.col << ")";
    else
        out << "[" << d.row << "]";
    out << " (analytic " << d.analytic << ", finite difference " << d.finite_difference << "), "
        << d.entries_compared << " entries compared";
    return out.str();
}

} // namespace

bool DerivativeCheckReport::passed(double tolerance) const
{
    if (!pattern_problem.empty())
        return false;
    for (const auto* d : {&gradient, &jacobian, &hessian})
        if (d->entries_compared > 0 && !(d->worst_relative_error <= tolerance))
            return false;
    return true;
}

std::string DerivativeCheckReport::to_text() const
{
    return (pattern_problem.empty() ? "" : pattern_problem + "\n") + describe("gradient", gradient, false) + "\n" + describe("jacobian", jacobian, true) + "\n" +
           describe("hessian ", hessian, true);
}

DerivativeCheckReport check_derivatives(Nlp& nlp, Nlp::ConstVectorRef x_in, const DerivativeCheckOptions& options)
{
    const int n = nlp.num_variables();
    const int m = nlp.num_constraints();
    if (n > kMaxCheckedVariables)
        throw InputError("derivative check of " + nlp.name() + ": " + std::to_string(n) +
                         " variables; the check compares dense n x n matrices and takes at most " +
                         std::to_string(kMaxCheckedVariables));
    if (!(options.step > 0.0 && std::isfinite(options.step)))
        throw InputError("derivative check: step = " + format_number(options.step) +
                         " is invalid; it must be a positive finite number");
    if (!std::isfinite(options.sigma))
        throw InputError("derivative check: sigma = " + format_number(options.sigma) + " is not finite");
    const Eigen::VectorXd x = x_in;
    if (!x.allFinite())
        throw InputError("derivative check of " + nlp.name() + ": the point x is not finite");
    DerivativeCheckReport report;

    std::mt19937 rng(options.seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd lambda(m);
    for (int i = 0; i < m; ++i)
        lambda[i] = uniform(rng);

    report.pattern_problem = find_pattern_problem("jacobian", nlp.jacobian_pattern(), m, n, false);
    if (report.pattern_problem.empty())
        report.pattern_problem = find_pattern_problem("hessian", nlp.hessian_pattern(), n, n, true);
    if (!report.pattern_problem.empty())
        return report;

    Eigen::VectorXd grad(n);
    nlp.gradient(x, grad);
    Eigen::MatrixXd jacobian;
    if (m > 0) {
        Eigen::VectorXd values(nlp.jacobian_pattern().nonzeros());
        nlp.jacobian_values(x, values);
        jacobian = densify(nlp.jacobian_pattern(), values, m, n);
    }
    Eigen::VectorXd hessian_values(nlp.hessian_pattern().nonzeros());
    nlp.hessian_values(x, options.sigma, lambda, hessian_values);
    const Eigen::MatrixXd hessian = densify(nlp.hessian_pattern(), hessian_values, n, n);

    // Central differences along each coordinate: f gives ∇f, c gives column j
    // of J, and ∇L gives column j of ∇²L.
    Eigen::MatrixXd hessian_fd(n, n);
    Eigen::VectorXd c_plus(m), c_minus(m);
    std::vector<Entry> gradient_entries, jacobian_entries, hessian_entries;
    for (int j = 0; j < n; ++j) {
        const double h = options.step * std::max(1.0, std::abs(x[j]));
        Eigen::VectorXd xp = x, xm = x;
        xp[j] += h;
        xm[j] -= h;
        gradient_entries.push_back({j, 0, grad[j], (nlp.objective(xp) - nlp.objective(xm)) / (2 * h)});
        if (m > 0) {
            nlp.constraints(xp, c_plus);
            nlp.constraints(xm, c_minus);
            for (int i = 0; i < m; ++i)
                jacobian_entries.push_back({i, j, jacobian(i, j), (c_plus[i] - c_minus[i]) / (2 * h)});
        }
        hessian_fd.col(j) = (lagrangian_gradient(nlp, xp, options.sigma, lambda) -
                             lagrangian_gradient(nlp, xm, options.sigma, lambda)) / (2 * h);
    }
    // Symmetrize the differenced Hessian and compare its lower triangle, so an
    // entry missing from the pattern shows as a discrepancy too.
    for (int j = 0; j < n; ++j)
        for (int i = j; i < n; ++i)
            hessian_entries.push_back({i, j, hessian(i, j), 0.5 * (hessian_fd(i, j) + hessian_fd(j, i))});
    report.gradient = worst_of(gradient_entries);
    report.jacobian = worst_of(jacobian_entries);
    report.hessian = worst_of(hessian_entries);
    return report;
}

} // namespace sinew
