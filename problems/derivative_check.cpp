#include "sinew/problems/derivative_check.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/problems/difference_study.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <vector>

namespace sinew {
namespace {

/// One entry of a derivative: the analytic value, its central difference,
/// the relative error (below) and, when studied, how it was settled.
struct Entry {
    int row, col;
    double analytic, fd;
    double error = 0.0;
    StudyOutcome outcome = StudyOutcome::disagrees;
};

/// kRelativeErrorFloor·(the largest |a| of this derivative, or the largest
/// |fd| when every a is 0): entries far below the derivative's scale (where
/// central differences carry only round-off) are measured against a
/// thousandth of it. The analytic values set the scale, not a central
/// difference straddling a jump, which would inflate it.
double error_floor(const std::vector<Entry>& entries)
{
    double analytic_scale = 0.0, difference_scale = 0.0;
    for (const Entry& e : entries) {
        if (std::isfinite(e.analytic))
            analytic_scale = std::max(analytic_scale, std::abs(e.analytic));
        if (std::isfinite(e.fd))
            difference_scale = std::max(difference_scale, std::abs(e.fd));
    }
    const double scale = analytic_scale > 0.0 ? analytic_scale : difference_scale;
    return scale > 0.0 ? kRelativeErrorFloor * scale : 1.0;
}

/// Each entry's |a − fd| / max(|fd|, floor); a non-finite error counts as infinite.
void set_errors(std::vector<Entry>& entries, double floor)
{
    for (Entry& e : entries) {
        const double error = std::abs(e.analytic - e.fd) / std::max(std::abs(e.fd), floor);
        e.error = std::isfinite(error) ? error : std::numeric_limits<double>::infinity();
    }
}

/// Studies the entries above `tolerance` column by column (study_column()):
/// entry (row, col) is ∂F_row/∂x_col, or with `transposed` ∂F_col/∂x_row.
void study(std::vector<Entry>& entries, const PointFunction& F, const Eigen::VectorXd& x, const Eigen::VectorXd& F_at_x,
           double step, double floor, double tolerance, bool transposed)
{
    std::map<int, std::vector<size_t>> by_column;
    for (size_t k = 0; k < entries.size(); ++k)
        if (entries[k].outcome == StudyOutcome::disagrees && entries[k].error > tolerance)
            by_column[transposed ? entries[k].row : entries[k].col].push_back(k);
    for (const auto& [j, members] : by_column) {
        std::vector<EntryToStudy> column;
        for (size_t k : members)
            column.push_back({transposed ? entries[k].col : entries[k].row, entries[k].analytic, entries[k].fd});
        const double h = step * std::max(1.0, std::abs(x[j]));
        const std::vector<StudiedEntry> settled = study_column(F, x, j, h, F_at_x, column, floor, tolerance);
        for (size_t m = 0; m < members.size(); ++m) {
            Entry& e = entries[members[m]];
            if (settled[m].outcome != StudyOutcome::disagrees) {
                e.outcome = settled[m].outcome;
                e.error = settled[m].relative_error;
                e.fd = settled[m].estimate;
            }
        }
    }
}

/// The worst of `entries` by their errors, with the counts of settled ones.
DerivativeDiscrepancy worst_of(const std::vector<Entry>& entries, double floor)
{
    DerivativeDiscrepancy worst;
    worst.entries_compared = static_cast<int>(entries.size());
    worst.error_floor = floor;
    for (const Entry& e : entries) {
        worst.within_noise += e.outcome == StudyOutcome::noise;
        worst.at_kink += e.outcome == StudyOutcome::kink;
        worst.both_sides_agree += e.outcome == StudyOutcome::both_sides;
        if (worst.row < 0 || e.error > worst.worst_relative_error) {
            worst.worst_relative_error = e.error;
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

/// "448 MB": three significant digits, decimal units.
std::string format_bytes(std::uint64_t bytes)
{
    const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB"};
    double value = static_cast<double>(bytes);
    int unit = 0;
    while (value >= 1000.0 && unit < 5) {
        value /= 1000.0;
        ++unit;
    }
    std::ostringstream out;
    out << std::setprecision(3) << value << " " << units[unit];
    return out.str();
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
    if (d.within_noise + d.at_kink + d.both_sides_agree > 0)
        out << "; settled by a closer study: " << d.within_noise << " within round-off noise, " << d.at_kink
            << " at a kink (one side agrees), " << d.both_sides_agree
            << " where both one-sided differences agree";
    return out.str();
}

/// Studies the entries central differences disagree with (study()) and
/// fills the report: f for the gradient, c for the Jacobian, ∇L for the
/// Hessian, whose entry (i, j) is studied along x_j, then along x_i.
void settle(Nlp& nlp, const Eigen::VectorXd& x, const DerivativeCheckOptions& options, const Eigen::VectorXd& lambda,
            std::vector<Entry>& gradient, std::vector<Entry>& jacobian, std::vector<Entry>& hessian,
            DerivativeCheckReport& report)
{
    const PointFunction objective = [&](const Eigen::VectorXd& y) {
        return Eigen::VectorXd::Constant(1, nlp.objective(y));
    };
    const PointFunction constraints = [&](const Eigen::VectorXd& y) {
        Eigen::VectorXd c(nlp.num_constraints());
        nlp.constraints(y, c);
        return c;
    };
    const PointFunction lagrangian = [&](const Eigen::VectorXd& y) {
        return lagrangian_gradient(nlp, y, options.sigma, lambda);
    };
    const std::pair<std::vector<Entry>*, const PointFunction*> derivatives[] = {
        {&gradient, &objective}, {&jacobian, &constraints}, {&hessian, &lagrangian}};
    DerivativeDiscrepancy* reported[] = {&report.gradient, &report.jacobian, &report.hessian};
    for (int d = 0; d < 3; ++d) {
        std::vector<Entry>& entries = *derivatives[d].first;
        const PointFunction& F = *derivatives[d].second;
        const double floor = error_floor(entries);
        set_errors(entries, floor);
        if (!entries.empty()) {
            const Eigen::VectorXd F_at_x = F(x);
            if (d == 0)  // gradient entries are (j, 0): ∂f/∂x_j
                study(entries, F, x, F_at_x, options.step, floor, options.tolerance, true);
            else
                study(entries, F, x, F_at_x, options.step, floor, options.tolerance, false);
            if (d == 2)
                study(entries, F, x, F_at_x, options.step, floor, options.tolerance, true);
        }
        *reported[d] = worst_of(entries, floor);
    }
}

} // namespace

std::uint64_t dense_check_bytes(int n, int m)
{
    const auto N = static_cast<std::uint64_t>(std::max(n, 0));
    const auto M = static_cast<std::uint64_t>(std::max(m, 0));
    const std::uint64_t matrices = (2 * N * N + M * N) * sizeof(double);
    const std::uint64_t entries = (N * (N + 1) / 2 + M * N + N) * sizeof(Entry);
    return matrices + entries;
}

std::string dense_check_refusal(const Nlp& nlp)
{
    const int n = nlp.num_variables();
    const int m = nlp.num_constraints();
    const std::uint64_t bytes = dense_check_bytes(n, m);
    if (n <= kMaxCheckedVariables && bytes <= kMaxDenseCheckBytes)
        return {};
    const bool too_many = n > kMaxCheckedVariables, too_large = bytes > kMaxDenseCheckBytes;
    const std::string variables = std::to_string(kMaxCheckedVariables) + " variables";
    const std::string memory = format_bytes(kMaxDenseCheckBytes);
    const std::string limits = too_many && too_large ? "limits of " + variables + " and " + memory
                               : too_many            ? "limit of " + variables
                                                     : "limit of " + memory;
    return "the entrywise derivative check of " + nlp.name() + " is dense: with n = " + std::to_string(n) +
           " variables and m = " + std::to_string(m) + " constraints it would hold " + format_bytes(bytes) +
           " (two n x n and one m x n matrices of doubles plus the compared entries), over its " + limits +
           "; the Taylor test (taylor_test.hpp) is sparse and has no such limit";
}

std::string find_pattern_problem(const Nlp& nlp)
{
    const int n = nlp.num_variables();
    const std::string jacobian =
        find_pattern_problem("jacobian", nlp.jacobian_pattern(), nlp.num_constraints(), n, false);
    return jacobian.empty() ? find_pattern_problem("hessian", nlp.hessian_pattern(), n, n, true) : jacobian;
}

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
    if (const std::string refusal = dense_check_refusal(nlp); !refusal.empty())
        throw InputError(refusal);
    if (!(options.step > 0.0 && std::isfinite(options.step)))
        throw InputError("derivative check: step = " + format_number(options.step) +
                         " is invalid; it must be a positive finite number");
    if (!std::isfinite(options.sigma))
        throw InputError("derivative check: sigma = " + format_number(options.sigma) + " is not finite");
    if (!(options.tolerance > 0.0 && std::isfinite(options.tolerance)))
        throw InputError("derivative check: tolerance = " + format_number(options.tolerance) +
                         " is invalid; it must be a positive finite number");
    const Eigen::VectorXd x = x_in;
    if (!x.allFinite())
        throw InputError("derivative check of " + nlp.name() + ": the point x is not finite");
    DerivativeCheckReport report;

    std::mt19937 rng(options.seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd lambda(m);
    for (int i = 0; i < m; ++i)
        lambda[i] = uniform(rng);

    report.pattern_problem = find_pattern_problem(nlp);
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
    nlp.hessian(x, options.sigma, lambda, Projection::none, hessian_values);
    const Eigen::MatrixXd hessian = densify(nlp.hessian_pattern(), hessian_values, n, n);

    // Central differences along each coordinate: f gives ∇f, c gives column j
    // of J, and ∇L gives column j of ∇²L.
    Eigen::MatrixXd hessian_fd(n, n);
    Eigen::VectorXd c_plus(m), c_minus(m);
    std::vector<Entry> gradient_entries, jacobian_entries, hessian_entries;
    gradient_entries.reserve(n);  // as dense_check_bytes() counts them
    jacobian_entries.reserve(static_cast<std::size_t>(m) * n);
    hessian_entries.reserve(static_cast<std::size_t>(n) * (n + 1) / 2);
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
    settle(nlp, x, options, lambda, gradient_entries, jacobian_entries, hessian_entries, report);
    return report;
}

} // namespace sinew
