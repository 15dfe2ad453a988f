#include "sinew/core/input_error.hpp"
#include "sinew/problems/classic/classic_problems.hpp"
#include "sinew/problems/classic/rosenbrock.hpp"

#include "problems/pattern_checks.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace sinew;
using sinew::test::check_pattern_shape;

namespace {

// Central differences with step h = kStep · max(1, |x_j|). Their truncation
// error is h²/6 · |third derivative| (~1e-9 at most here) and their round-off
// about ε|φ|/h ≤ 2.2e-10 |φ|, φ being the function differenced (f for ∇f, cᵢ
// for row i of the Jacobian, (∇L)ᵢ for row i of ∇²L). An analytic entry a
// passes when |a − fd| ≤ kDerivativeTolerance · max(1, |fd|) + kRoundoffAllowance · |φ|:
// the second term, 45× the round-off estimate, matters only where |φ| is
// large next to the entry, e.g. rosenbrock1000, whose f is ~1e6 at random
// points. Measured worst relative errors |a − fd| / max(1, |fd|) are ~1e-9
// (up to 1.4e-7 for rosenbrock1000's Hessian and 1.6e-5 for its gradient,
// the round-off case); a wrong term or factor shows as 1e-3 or more.
constexpr double kStep = 1e-6;
constexpr double kDerivativeTolerance = 1e-6;
constexpr double kRoundoffAllowance = 1e-8;

// The brief's acceptance for the published solutions: f(x*) within 1e-6
// relative of f* (absolute when f* = 0), and x* feasible within 1e-6. The
// published x* have 7 to 11 significant digits; the tightest case is hs071,
// where x₀x₁x₂x₃ at the published x* falls 8.7e-7 short of 25.
constexpr double kOptimumTolerance = 1e-6;
constexpr double kFeasibilityTolerance = 1e-6;

constexpr int kRandomPoints = 3;
constexpr unsigned kSeed = 20240611;

using Eigen::MatrixXd;
using Eigen::VectorXd;

VectorXd from_list(const std::vector<double>& values)
{
    return Eigen::Map<const VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

/// Published starting point and solution x*, as in the source each problem
/// cites: Moré, Garbow, Hillstrom 1981 problem 21 (start repeated pairwise, x* = 1) and
/// Hock & Schittkowski 1981 (problem number in the name), digits as printed.
struct PublishedPoints {
    VectorXd start;
    VectorXd solution;
};

PublishedPoints published_points(const std::string& name, int n)
{
    if (name.rfind("rosenbrock", 0) == 0) {
        PublishedPoints points{VectorXd(n), VectorXd::Ones(n)};
        for (int i = 0; i < n; ++i)
            points.start[i] = (i % 2 == 0) ? -1.2 : 1.0;
        return points;
    }
    static const std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> table = {
        {"hs006", {{-1.2, 1.0}, {1.0, 1.0}}},
        {"hs028", {{-4.0, 1.0, 1.0}, {0.5, -0.5, 0.5}}},
        {"hs035", {{0.5, 0.5, 0.5}, {4.0 / 3.0, 7.0 / 9.0, 4.0 / 9.0}}},
        {"hs043", {{0.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 2.0, -1.0}}},
        {"hs065", {{-5.0, 5.0, 0.0}, {3.650461821, 3.65046168, 4.6204170507}}},
        {"hs071", {{1.0, 5.0, 5.0, 1.0}, {1.0, 4.7429994, 3.8211503, 1.3794082}}},
        {"hs076", {{0.5, 0.5, 0.5, 0.5}, {0.2727273, 2.090909, -0.26e-10, 0.5454545}}},  // x₂ < 0 as printed
        {"hs100",
         {{1.0, 2.0, 0.0, 4.0, 0.0, 1.0, 1.0},
          {2.330499, 1.951372, -0.4775414, 4.365726, -0.6244870, 1.038131, 1.594227}}},
    };
    const auto it = table.find(name);
    if (it == table.end())
        return {};
    return {from_list(it->second.first), from_list(it->second.second)};
}

double step_for(double xj) { return kStep * std::max(1.0, std::abs(xj)); }

/// The entry of `analytic` that is furthest outside its allowance
/// kDerivativeTolerance · max(1, |fd|) + kRoundoffAllowance · row_scale[row].
struct Discrepancy {
    double ratio = 0.0;  ///< |analytic − fd| / allowance; passes at <= 1
    int row = -1;
    int col = -1;
    double analytic = 0.0;
    double finite_difference = 0.0;
};

Discrepancy worst_discrepancy(const MatrixXd& analytic, const MatrixXd& fd, const VectorXd& row_scale)
{
    Discrepancy worst;
    for (int col = 0; col < fd.cols(); ++col)
        for (int row = 0; row < fd.rows(); ++row) {
            const double allowance = kDerivativeTolerance * std::max(1.0, std::abs(fd(row, col))) +
                                     kRoundoffAllowance * std::abs(row_scale[row]);
            const double ratio = std::abs(analytic(row, col) - fd(row, col)) / allowance;
            if (ratio > worst.ratio)
                worst = {ratio, row, col, analytic(row, col), fd(row, col)};
        }
    return worst;
}

VectorXd analytic_gradient(Nlp& nlp, const VectorXd& x)
{
    VectorXd grad(nlp.num_variables());
    nlp.gradient(x, grad);
    return grad;
}

VectorXd constraint_values(Nlp& nlp, const VectorXd& x)
{
    VectorXd c(nlp.num_constraints());
    nlp.constraints(x, c);
    return c;
}

MatrixXd dense_jacobian(Nlp& nlp, const VectorXd& x)
{
    const SparsityPattern& pattern = nlp.jacobian_pattern();
    VectorXd values(pattern.nonzeros());
    nlp.jacobian_values(x, values);
    MatrixXd J = MatrixXd::Zero(nlp.num_constraints(), nlp.num_variables());
    for (int k = 0; k < pattern.nonzeros(); ++k)
        J(pattern.rows[k], pattern.cols[k]) += values[k];
    return J;
}

/// The full symmetric ∇²L from its lower triangle.
MatrixXd dense_hessian(Nlp& nlp, const VectorXd& x, double sigma, const VectorXd& lambda)
{
    const SparsityPattern& pattern = nlp.hessian_pattern();
    VectorXd values(pattern.nonzeros());
    nlp.hessian(x, sigma, lambda, Projection::none, values);
    const int n = nlp.num_variables();
    MatrixXd H = MatrixXd::Zero(n, n);
    for (int k = 0; k < pattern.nonzeros(); ++k) {
        H(pattern.rows[k], pattern.cols[k]) += values[k];
        if (pattern.rows[k] != pattern.cols[k])
            H(pattern.cols[k], pattern.rows[k]) += values[k];
    }
    return H;
}

/// ∇L = σ∇f + Jᵀλ from the analytic gradient and Jacobian.
VectorXd lagrangian_gradient(Nlp& nlp, const VectorXd& x, double sigma, const VectorXd& lambda)
{
    VectorXd grad = sigma * analytic_gradient(nlp, x);
    if (nlp.num_constraints() > 0)
        grad += dense_jacobian(nlp, x).transpose() * lambda;
    return grad;
}

VectorXd fd_gradient(Nlp& nlp, const VectorXd& x)
{
    VectorXd grad(x.size());
    VectorXd xp = x, xm = x;
    for (int j = 0; j < x.size(); ++j) {
        xp[j] = x[j] + step_for(x[j]);
        xm[j] = x[j] - step_for(x[j]);
        grad[j] = (nlp.objective(xp) - nlp.objective(xm)) / (xp[j] - xm[j]);
        xp[j] = xm[j] = x[j];
    }
    return grad;
}

MatrixXd fd_jacobian(Nlp& nlp, const VectorXd& x)
{
    MatrixXd J(nlp.num_constraints(), x.size());
    VectorXd xp = x, xm = x;
    for (int j = 0; j < x.size(); ++j) {
        xp[j] = x[j] + step_for(x[j]);
        xm[j] = x[j] - step_for(x[j]);
        J.col(j) = (constraint_values(nlp, xp) - constraint_values(nlp, xm)) / (xp[j] - xm[j]);
        xp[j] = xm[j] = x[j];
    }
    return J;
}

/// Central differences of the analytic ∇L, column by column.
MatrixXd fd_hessian(Nlp& nlp, const VectorXd& x, double sigma, const VectorXd& lambda)
{
    MatrixXd H(x.size(), x.size());
    VectorXd xp = x, xm = x;
    for (int j = 0; j < x.size(); ++j) {
        xp[j] = x[j] + step_for(x[j]);
        xm[j] = x[j] - step_for(x[j]);
        H.col(j) = (lagrangian_gradient(nlp, xp, sigma, lambda) - lagrangian_gradient(nlp, xm, sigma, lambda)) /
                   (xp[j] - xm[j]);
        xp[j] = xm[j] = x[j];
    }
    return H;
}

/// Checks ∇f, ∂c/∂x and ∇²L (with the given σ, λ) at x against central differences.
void check_derivatives_at(Nlp& nlp, const VectorXd& x, double sigma, const VectorXd& lambda)
{
    const int n = nlp.num_variables();
    const double f = nlp.objective(x);
    const VectorXd grad = analytic_gradient(nlp, x);
    const VectorXd grad_fd = fd_gradient(nlp, x);
    REQUIRE(std::isfinite(f));
    REQUIRE(grad.allFinite());
    REQUIRE(grad_fd.allFinite());
    REQUIRE(grad_fd.norm() > 0);
    {
        const Discrepancy d = worst_discrepancy(grad, grad_fd, VectorXd::Constant(n, f));
        INFO("gradient entry " << d.row << ": analytic " << d.analytic << ", central difference "
                               << d.finite_difference);
        CHECK(d.ratio <= 1.0);
    }

    if (nlp.num_constraints() > 0) {
        const MatrixXd J = dense_jacobian(nlp, x);
        const MatrixXd J_fd = fd_jacobian(nlp, x);
        REQUIRE(J.allFinite());
        REQUIRE(J_fd.allFinite());
        REQUIRE(J_fd.norm() > 0);
        const Discrepancy d = worst_discrepancy(J, J_fd, constraint_values(nlp, x));
        INFO("Jacobian entry (" << d.row << ", " << d.col << "): analytic " << d.analytic
                                << ", central difference " << d.finite_difference);
        CHECK(d.ratio <= 1.0);
    }

    const MatrixXd H = dense_hessian(nlp, x, sigma, lambda);
    const MatrixXd H_fd = fd_hessian(nlp, x, sigma, lambda);
    REQUIRE(H.allFinite());
    REQUIRE(H_fd.allFinite());
    REQUIRE(H_fd.norm() > 0);
    // A pattern entry missing or misplaced shows here too: the dense FD
    // Hessian is compared everywhere, including outside the pattern.
    const Discrepancy d = worst_discrepancy(H, H_fd, lagrangian_gradient(nlp, x, sigma, lambda));
    INFO("Hessian entry (" << d.row << ", " << d.col << "): analytic " << d.analytic << ", central difference "
                           << d.finite_difference);
    CHECK(d.ratio <= 1.0);
}

/// The box random points are drawn from: the variable bounds where finite,
/// otherwise one unit beyond the published start and solution.
std::pair<VectorXd, VectorXd> sampling_box(Nlp& nlp, const PublishedPoints& points)
{
    const int n = nlp.num_variables();
    VectorXd lower(n), upper(n);
    nlp.variable_bounds(lower, upper);
    for (int i = 0; i < n; ++i) {
        if (!is_finite_bound(lower[i]))
            lower[i] = std::min(points.start[i], points.solution[i]) - 1.0;
        if (!is_finite_bound(upper[i]))
            upper[i] = std::max(points.start[i], points.solution[i]) + 1.0;
    }
    return {lower, upper};
}

/// classic_problems() of suite "classic"; those of suite "constrained" are
/// tested in test_constrained_problems.cpp.
std::vector<BuiltinProblem> classic_suite()
{
    std::vector<BuiltinProblem> problems;
    for (auto& problem : classic_problems())
        if (problem.suite == "classic")
            problems.push_back(std::move(problem));
    return problems;
}

} // namespace

TEST_CASE("classic registry: names, order, suite, descriptions and references", "[problems][classic]")
{
    const std::vector<BuiltinProblem> problems = classic_suite();
    REQUIRE(problems.size() >= 6);
    CHECK(problems[0].name == "rosenbrock2");
    CHECK(problems[1].name == "rosenbrock1000");
    CHECK(problems[2].name == "hs071");

    std::set<std::string> names;
    for (const auto& problem : problems) {
        CAPTURE(problem.name);
        CHECK(names.insert(problem.name).second);
        CHECK(problem.suite == "classic");
        REQUIRE(problem.make);
        const auto nlp = problem.make();
        REQUIRE(nlp);
        CHECK(nlp->name() == problem.name);
        // The description states the size and the kind, and they are the true ones.
        const std::string size = std::to_string(nlp->num_variables()) + " variables";
        CHECK(problem.description.find(size) != std::string::npos);
        CHECK(problem.description.find(capabilities_of(*nlp).describe()) != std::string::npos);
        REQUIRE(problem.reference_objective.has_value());
        CHECK(std::isfinite(*problem.reference_objective));
        CHECK_FALSE(problem.reference_source.empty());
        if (problem.name.rfind("hs", 0) == 0) {
            const std::string number = std::to_string(std::stoi(problem.name.substr(2)));
            CHECK(problem.description.rfind("HS " + number + ":", 0) == 0);
            CHECK(problem.reference_source.find("Hock") != std::string::npos);
            CHECK(problem.reference_source.find("problem " + number) != std::string::npos);
        }
    }
}

TEST_CASE("classic problems: the published starting point, consistent bounds", "[problems][classic]")
{
    for (const auto& problem : classic_suite()) {
        DYNAMIC_SECTION(problem.name)
        {
            const auto nlp = problem.make();
            const int n = nlp->num_variables();
            const int m = nlp->num_constraints();
            const PublishedPoints points = published_points(problem.name, n);
            REQUIRE(points.start.size() == n);  // every problem has published data in this test
            REQUIRE(points.solution.size() == n);
            const VectorXd start = nlp->starting_point();
            REQUIRE(start.size() == n);
            CHECK((start - points.start).cwiseAbs().maxCoeff() == 0.0);

            VectorXd x_lower(n), x_upper(n), g_lower(m), g_upper(m);
            nlp->variable_bounds(x_lower, x_upper);
            nlp->constraint_bounds(g_lower, g_upper);
            for (int i = 0; i < n; ++i)
                CHECK(x_lower[i] <= x_upper[i]);
            for (int i = 0; i < m; ++i)
                CHECK(g_lower[i] <= g_upper[i]);
        }
    }
}

TEST_CASE("classic problems: sparsity patterns are in range, lower triangular, without duplicates",
          "[problems][classic]")
{
    for (const auto& problem : classic_suite()) {
        DYNAMIC_SECTION(problem.name)
        {
            check_pattern_shape(*problem.make());
        }
    }
}

TEST_CASE("classic problems: gradient, Jacobian and Hessian agree with central differences",
          "[problems][classic][derivatives]")
{
    std::mt19937 rng(kSeed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& problem : classic_suite()) {
        DYNAMIC_SECTION(problem.name)
        {
            const auto nlp = problem.make();
            const int n = nlp->num_variables();
            const int m = nlp->num_constraints();
            const PublishedPoints points = published_points(problem.name, n);
            REQUIRE(points.solution.size() == n);
            const auto [lower, upper] = sampling_box(*nlp, points);

            // The starting point, then random points in the box, each with a
            // random σ ∈ [0.5, 2] and random λ ∈ [−1, 1]ᵐ.
            for (int sample = 0; sample <= kRandomPoints; ++sample) {
                VectorXd x = points.start;
                if (sample > 0)
                    for (int i = 0; i < n; ++i)
                        x[i] = lower[i] + (upper[i] - lower[i]) * unit(rng);
                const double sigma = 0.5 + 1.5 * unit(rng);
                VectorXd lambda(m);
                for (int i = 0; i < m; ++i)
                    lambda[i] = -1.0 + 2.0 * unit(rng);
                // Small points are printed whole; rosenbrock1000's is identified by seed and sample.
                std::ostringstream point;
                if (n <= 10)
                    point << "x = " << x.transpose() << ", lambda = " << lambda.transpose();
                CAPTURE(kSeed, sample, sigma, point.str());
                check_derivatives_at(*nlp, x, sigma, lambda);
            }
        }
    }
}

TEST_CASE("classic problems: the published solution gives the published optimum and is feasible",
          "[problems][classic]")
{
    for (const auto& problem : classic_suite()) {
        DYNAMIC_SECTION(problem.name)
        {
            const auto nlp = problem.make();
            const PublishedPoints points = published_points(problem.name, nlp->num_variables());
            REQUIRE(points.solution.size() == nlp->num_variables());
            REQUIRE(problem.reference_objective.has_value());
            const double f_star = *problem.reference_objective;
            const double f = nlp->objective(points.solution);
            REQUIRE(std::isfinite(f));
            CAPTURE(f, f_star);
            CHECK(std::abs(f - f_star) <= kOptimumTolerance * std::max(1.0, std::abs(f_star)));
            const double violation = max_constraint_violation(*nlp, points.solution);
            CAPTURE(violation);
            CHECK(violation <= kFeasibilityTolerance);
        }
    }
}

TEST_CASE("classic problems: evaluations fill pre-sized outputs in place, the same each time",
          "[problems][classic]")
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const auto& problem : classic_suite()) {
        DYNAMIC_SECTION(problem.name)
        {
            const auto nlp = problem.make();
            const int n = nlp->num_variables();
            const int m = nlp->num_constraints();
            const VectorXd x = nlp->starting_point();
            const VectorXd lambda = VectorXd::LinSpaced(m, -1.0, 1.0);

            // Outputs start as NaN so that an entry left unwritten shows.
            VectorXd grad = VectorXd::Constant(n, nan);
            VectorXd c = VectorXd::Constant(m, nan);
            VectorXd jacobian = VectorXd::Constant(nlp->jacobian_pattern().nonzeros(), nan);
            VectorXd hessian = VectorXd::Constant(nlp->hessian_pattern().nonzeros(), nan);
            const double* grad_data = grad.data();
            const double* c_data = c.data();
            const double* jacobian_data = jacobian.data();
            const double* hessian_data = hessian.data();

            const double f = nlp->objective(x);
            nlp->gradient(x, grad);
            nlp->constraints(x, c);
            nlp->jacobian_values(x, jacobian);
            nlp->hessian(x, 1.5, lambda, Projection::none, hessian);

            CHECK(std::isfinite(f));
            CHECK(grad.size() == n);
            CHECK(c.size() == m);
            CHECK(jacobian.size() == nlp->jacobian_pattern().nonzeros());
            CHECK(hessian.size() == nlp->hessian_pattern().nonzeros());
            CHECK(grad.data() == grad_data);
            CHECK(c.data() == c_data);
            CHECK(jacobian.data() == jacobian_data);
            CHECK(hessian.data() == hessian_data);
            CHECK(grad.allFinite());
            CHECK(c.allFinite());
            CHECK(jacobian.allFinite());
            CHECK(hessian.allFinite());

            // No hidden state: a second evaluation gives bitwise the same values.
            VectorXd grad_again(n), c_again(m), jacobian_again(jacobian.size()), hessian_again(hessian.size());
            CHECK(nlp->objective(x) == f);
            nlp->gradient(x, grad_again);
            nlp->constraints(x, c_again);
            nlp->jacobian_values(x, jacobian_again);
            nlp->hessian(x, 1.5, lambda, Projection::none, hessian_again);
            CHECK(grad_again == grad);
            CHECK(c_again == c);
            CHECK(jacobian_again == jacobian);
            CHECK(hessian_again == hessian);
        }
    }
}

TEST_CASE("rosenbrock: 2x2 block-diagonal Hessian pattern, zero at the optimum, rejects odd or small n", "[problems][classic]")
{
    for (int n : {2, 4, 8}) {
        CAPTURE(n);
        Rosenbrock rosenbrock(n);
        CHECK(rosenbrock.hessian_pattern().nonzeros() == 3 * n / 2);
        CHECK(rosenbrock.objective(VectorXd::Ones(n)) == 0.0);
        VectorXd grad(n);
        rosenbrock.gradient(VectorXd::Ones(n), grad);
        CHECK(grad.cwiseAbs().maxCoeff() == 0.0);
    }
    CHECK_THROWS_AS(Rosenbrock(1), InputError);
    CHECK_THROWS_AS(Rosenbrock(0), InputError);
    CHECK_THROWS_AS(Rosenbrock(-3), InputError);
    CHECK_THROWS_AS(Rosenbrock(7), InputError);
}
