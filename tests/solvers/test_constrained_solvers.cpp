// The constrained Newton strategies (issue 12) on the equality- and
// bound-constrained Hock-Schittkowski problems and on small problems built to
// break them: published optima, quadratic convergence of kkt-newton, the 1/κ
// violation of relaxed KKT, the equivalence of its two linear systems and of
// the penalty, inertia correction, and honest statuses on infeasible input.
// Penalty and augmented Lagrangian also on the HS problems with inequalities
// and on a circle constraint inactive, active on its upper and on its lower
// side (signs of the multipliers), with the PHR function's derivatives.
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/taylor_test.hpp"
#include "sinew/solvers/constrained/augmented_lagrangian_function.hpp"
#include "sinew/solvers/constrained/constraint_residuals.hpp"
#include "sinew/solvers/solver.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

using namespace sinew;

namespace {

/// hs006, hs028 and every problem of suite "constrained": equalities and bounds only.
std::vector<const BuiltinProblem*> equality_and_bound_problems()
{
    std::vector<const BuiltinProblem*> problems;
    for (const BuiltinProblem& p : builtin_problems()) {
        if (p.suite != "classic" && p.suite != "constrained")
            continue;
        const NlpCapabilities kind = capabilities_of(*p.make());
        if (!kind.has_inequalities && !kind.unconstrained())
            problems.push_back(&p);
    }
    return problems;
}

Result solve_named(const std::string& problem, const std::string& solver, SolverOptions options)
{
    auto nlp = find_builtin_problem(problem).make();
    return solve(*nlp, solver, options);
}

/// minimize x₀² + x₁² subject to x₀ + x₁ = 1 and x₀ + x₁ = b: inconsistent
/// for b ≠ 1, two copies of one constraint (J rank-deficient) for b = 1.
class TwoParallelConstraints final : public Nlp {
public:
    explicit TwoParallelConstraints(double b) : b_(b)
    {
        for (int row = 0; row < 2; ++row)
            for (int col = 0; col < 2; ++col)
                jacobian_.add(row, col);
        hessian_.add(0, 0);
        hessian_.add(1, 1);
    }
    std::string name() const override { return "two-parallel-constraints"; }
    int num_variables() const override { return 2; }
    int num_constraints() const override { return 2; }
    void constraint_bounds(VectorRef lower, VectorRef upper) const override
    {
        lower << 1.0, b_;
        upper = lower;
    }
    Vector starting_point() const override { return Vector::Constant(2, 3.0); }
    double objective(ConstVectorRef x) override { return x.squaredNorm(); }
    void gradient(ConstVectorRef x, VectorRef g) override { g = 2.0 * x; }
    void constraints(ConstVectorRef x, VectorRef c) override { c.setConstant(x.sum()); }
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef, VectorRef values) override { values.setOnes(); }
    const SparsityPattern& hessian_pattern() const override { return hessian_; }

protected:
    void hessian_values(ConstVectorRef, double sigma, ConstVectorRef, VectorRef values) override
    {
        values.setConstant(2.0 * sigma);
    }

private:
    double b_;
    SparsityPattern jacobian_, hessian_;
};

/// KKT residual plus violation per history row, the quantity whose ratio test shows the rate.
std::vector<double> kkt_errors(const Result& r)
{
    std::vector<double> errors;
    for (const HistoryRow& row : r.history)
        errors.push_back(row.dual_residual + row.constraint_violation);
    return errors;
}

} // namespace

TEST_CASE("kkt-newton and augmented-lagrangian reach the published optimum of every equality or bound HS problem",
          "[constrained]")
{
    SolverOptions options;
    options.constraint_tolerance = 1e-8;
    const auto problems = equality_and_bound_problems();
    REQUIRE(problems.size() >= 20);
    for (const BuiltinProblem* problem : problems) {
        for (const std::string solver : {"kkt-newton", "augmented-lagrangian"}) {
            const Result r = solve_named(problem->name, solver, options);
            const double f_star = *problem->reference_objective;
            CAPTURE(problem->name, solver, r.message, r.objective, f_star, r.constraint_violation, r.iterations);
            CHECK(r.status == Status::converged);
            CHECK(std::abs(r.objective - f_star) <= 1e-6 * std::max(1.0, std::abs(f_star)));
            CHECK(r.constraint_violation <= 1e-8);
        }
    }
}

TEST_CASE("relaxed-kkt and penalty report the violation they reach and converge only within constr_tol",
          "[constrained]")
{
    for (const BuiltinProblem* problem : equality_and_bound_problems()) {
        for (const std::string solver : {"relaxed-kkt", "penalty"}) {
            const Result r = solve_named(problem->name, solver, SolverOptions{});
            CAPTURE(problem->name, solver, r.message, r.constraint_violation);
            auto nlp = problem->make();
            CHECK(r.constraint_violation == max_constraint_violation(*nlp, r.x));
            if (r.status == Status::converged)
                CHECK(r.constraint_violation <= SolverOptions{}.constraint_tolerance);
            else
                CHECK(r.status != Status::failed);
        }
    }
}

TEST_CASE("kkt-newton converges quadratically near the solution", "[constrained]")
{
    // e_{k+1} ≤ max(C e_k², 1e-14) (C = 1e3) over the steps with
    // 1e-12 < e_k < 1e-4: a linear rate ρ > 0.1 would give e_{k+1} > 0.1 e_k,
    // above both bounds there (a step that lands at round-off counts too).
    for (const std::string problem : {"hs005", "hs007", "hs039", "hs056", "hs077"}) {
        const Result r = solve_named(problem, "kkt-newton", SolverOptions{});
        REQUIRE(r.status == Status::converged);
        const std::vector<double> e = kkt_errors(r);
        int ratios = 0;
        for (size_t k = 0; k + 1 < e.size(); ++k) {
            if (!(e[k] < 1e-4) || !(e[k] > 1e-12))
                continue;
            CAPTURE(problem, k, e[k], e[k + 1]);
            CHECK(e[k + 1] <= std::max(1e3 * e[k] * e[k], 1e-14));
            ++ratios;
        }
        CAPTURE(problem);
        CHECK(ratios >= 1);
    }
}

TEST_CASE("relaxed KKT's final violation falls as 1 over kappa", "[constrained]")
{
    for (const std::string problem : {"hs040", "hs053"}) {
        std::vector<double> log_kappa, log_violation;
        for (const double kappa : {1e3, 1e4, 1e5, 1e6}) {
            SolverOptions options;
            options.tolerance = 1e-12;
            options.backend = {{"kappa", std::to_string(kappa)}};
            const Result r = solve_named(problem, "relaxed-kkt", options);
            CAPTURE(problem, kappa, r.message);
            REQUIRE(r.constraint_violation > 0.0);
            log_kappa.push_back(std::log(kappa));
            log_violation.push_back(std::log(r.constraint_violation));
        }
        // Least-squares slope of log violation against log κ.
        const double n = static_cast<double>(log_kappa.size());
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (size_t i = 0; i < log_kappa.size(); ++i) {
            sx += log_kappa[i];
            sy += log_violation[i];
            sxx += log_kappa[i] * log_kappa[i];
            sxy += log_kappa[i] * log_violation[i];
        }
        const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
        CAPTURE(problem, slope);
        CHECK(std::abs(slope + 1.0) <= 0.1);
    }
}

TEST_CASE("relaxed KKT and penalty Newton reach the same point for the same kappa", "[constrained]")
{
    for (const std::string problem : {"hs040", "hs053", "hs077"}) {
        SolverOptions options;
        options.tolerance = 1e-13;
        options.backend = {{"kappa", "1e4"}};
        const Result relaxed = solve_named(problem, "relaxed-kkt", options);
        options.backend = {{"kappa", "1e4"}, {"kappa_growth", "1"}};
        const Result penalty = solve_named(problem, "penalty", options);
        CAPTURE(problem, relaxed.message, penalty.message);
        const double scale = std::max(1.0, relaxed.x.cwiseAbs().maxCoeff());
        CHECK((relaxed.x - penalty.x).cwiseAbs().maxCoeff() <= 1e-10 * scale);
    }
}

TEST_CASE("relaxed KKT's LDLT and Schur complement paths give the same iterates for linear constraints",
          "[constrained]")
{
    // hs041 (cubic f, bounds) and hs062 (logarithmic f, bounds): linear constraints.
    for (const std::string problem : {"hs041", "hs062"}) {
        SolverOptions options;
        options.backend = {{"linear_system", "ldlt"}};
        const Result ldlt = solve_named(problem, "relaxed-kkt", options);
        options.backend = {{"linear_system", "schur"}};
        const Result schur = solve_named(problem, "relaxed-kkt", options);
        CAPTURE(problem, ldlt.message, schur.message);
        // The two stopping tests see ‖∇φ‖ at round-off level differently, so
        // one may take one more (round-off) iteration than the other.
        const size_t common = std::min(ldlt.history.size(), schur.history.size());
        CHECK(std::max(ldlt.history.size(), schur.history.size()) - common <= 1);
        REQUIRE(common >= 3);
        for (size_t k = 0; k < common; ++k) {
            CAPTURE(k);
            CHECK(ldlt.history[k].objective == Approx(schur.history[k].objective).epsilon(1e-10).margin(1e-12));
            CHECK(ldlt.history[k].step_length == schur.history[k].step_length);
        }
        CHECK((ldlt.x - schur.x).cwiseAbs().maxCoeff() <= 1e-10 * std::max(1.0, ldlt.x.cwiseAbs().maxCoeff()));
    }
}

TEST_CASE("kkt-newton's inertia correction engages on hs005 and hs056 and the solve converges", "[constrained]")
{
    // hs005: f = sin(x₀ + x₁) + (x₀ − x₁)² − 1.5x₀ + 2.5x₁ + 1 is indefinite at
    // x₀ = (0, 0); hs056's Lagrangian Hessian is indefinite on J's null space
    // at its start. Both need δw > 0 (Ipopt's schedule: 1e-4, then ×100).
    for (const std::string problem : {"hs005", "hs056"}) {
        const Result r = solve_named(problem, "kkt-newton", SolverOptions{});
        const double delta_w = r.statistics.at("max_delta_w");
        CAPTURE(problem, delta_w, r.message);
        CHECK(delta_w >= 1e-4);
        CHECK(r.status == Status::converged);
    }
}

TEST_CASE("inconsistent constraints never end converged and dependent ones still converge", "[constrained]")
{
    SECTION("x0 + x1 = 1 and x0 + x1 = 2")
    {
        for (const std::string solver : {"kkt-newton", "augmented-lagrangian", "penalty", "relaxed-kkt"}) {
            TwoParallelConstraints again(2.0);
            const Result r = solve(again, solver, SolverOptions{});
            CAPTURE(solver, r.message);
            CHECK(r.status != Status::converged);
            CHECK_FALSE(r.message.empty());
            CHECK(r.constraint_violation >= 0.49);
        }
    }
    SECTION("x0 + x1 = 1 twice")
    {
        for (const std::string solver : {"kkt-newton", "augmented-lagrangian"}) {
            TwoParallelConstraints dependent(1.0);
            const Result r = solve(dependent, solver, SolverOptions{});
            CAPTURE(solver, r.message);
            CHECK(r.status == Status::converged);
            CHECK(r.x[0] == Approx(0.5).margin(1e-8));
            CHECK(r.x[1] == Approx(0.5).margin(1e-8));
        }
    }
}

TEST_CASE("the augmented Lagrangian function passes the shared derivative checks at random multipliers and stiffness",
          "[constrained]")
{
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    for (const std::string name : {"hs039", "hs056", "hs077", "hs063"}) {
        auto problem = find_builtin_problem(name).make();
        AugmentedLagrangianFunction function(*problem);
        Eigen::VectorXd lambda(problem->num_constraints());
        for (Eigen::Index i = 0; i < lambda.size(); ++i)
            lambda[i] = 3.0 * u11(rng);
        function.set_parameters(lambda, 50.0);
        Eigen::VectorXd x = problem->starting_point();
        for (Eigen::Index i = 0; i < x.size(); ++i)
            x[i] += 0.1 * u11(rng);
        const DerivativeCheckReport entrywise = check_derivatives(function, x);
        CAPTURE(name, entrywise.to_text());
        CHECK(entrywise.passed(1e-6));
        const TaylorReport taylor = taylor_test(function, x);
        CAPTURE(taylor.to_text());
        CHECK(taylor.passed());
    }
}

namespace {

/// hs071, hs035, hs043, hs065, hs076, hs100: the HS problems with inequalities.
const std::vector<std::string> kInequalityProblems = {"hs071", "hs035", "hs043", "hs065", "hs076", "hs100"};

/// Every multiplier of an inequality row has the sign of a side it can act on
/// (Ipopt's convention: λ ≤ 0 on g_L, λ ≥ 0 on g_U) and sits on that side:
/// |c − side| ≤ `near` wherever λ ≠ 0.
void check_inequality_multipliers(Nlp& nlp, const Result& r, double near)
{
    const int m = nlp.num_constraints();
    REQUIRE(r.constraint_multipliers.size() == m);
    Eigen::VectorXd lower(m), upper(m), c(m);
    nlp.constraint_bounds(lower, upper);
    nlp.constraints(r.x, c);
    for (int i = 0; i < m; ++i) {
        if (lower[i] == upper[i])
            continue;
        const double lambda = r.constraint_multipliers[i];
        CAPTURE(i, lambda, c[i], lower[i], upper[i]);
        if (lambda > 0.0) {
            CHECK(is_finite_bound(upper[i]));
            CHECK(std::abs(c[i] - upper[i]) <= near);
        } else if (lambda < 0.0) {
            CHECK(is_finite_bound(lower[i]));
            CHECK(std::abs(c[i] - lower[i]) <= near);
        }
    }
}

/// minimize (x₀ − 1)² + (x₁ − 2)² subject to g_L ≤ x₀² + x₁² ≤ g_U: the
/// unconstrained minimizer a = (1, 2) has c = 5. Inactive for g_L < 5 < g_U;
/// for g_U < 5 the solution is a·√(g_U/5) with λ = √(5/g_U) − 1 > 0 (upper
/// side), for g_L > 5 it is a·√(g_L/5) with λ = √(5/g_L) − 1 < 0 (lower side):
/// ∇f + λ∇c = 2(x − a) + 2λx = 0.
class CircleConstraint final : public Nlp {
public:
    CircleConstraint(double lower, double upper) : lower_(lower), upper_(upper)
    {
        jacobian_.add(0, 0);
        jacobian_.add(0, 1);
        hessian_.add(0, 0);
        hessian_.add(1, 1);
    }
    std::string name() const override { return "circle-constraint"; }
    int num_variables() const override { return 2; }
    int num_constraints() const override { return 1; }
    void constraint_bounds(VectorRef lower, VectorRef upper) const override
    {
        lower[0] = lower_;
        upper[0] = upper_;
    }
    Vector starting_point() const override { return Eigen::Vector2d(0.5, -0.5); }
    double objective(ConstVectorRef x) override { return (x[0] - 1.0) * (x[0] - 1.0) + (x[1] - 2.0) * (x[1] - 2.0); }
    void gradient(ConstVectorRef x, VectorRef g) override
    {
        g[0] = 2.0 * (x[0] - 1.0);
        g[1] = 2.0 * (x[1] - 2.0);
    }
    void constraints(ConstVectorRef x, VectorRef c) override { c[0] = x.squaredNorm(); }
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override { values = 2.0 * x; }
    const SparsityPattern& hessian_pattern() const override { return hessian_; }

    /// The solution and its multiplier.
    Eigen::Vector2d solution() const
    {
        const Eigen::Vector2d a(1.0, 2.0);
        if (5.0 > upper_)
            return a * std::sqrt(upper_ / 5.0);
        if (5.0 < lower_)
            return a * std::sqrt(lower_ / 5.0);
        return a;
    }
    double multiplier() const
    {
        if (5.0 > upper_)
            return std::sqrt(5.0 / upper_) - 1.0;
        if (5.0 < lower_)
            return std::sqrt(5.0 / lower_) - 1.0;
        return 0.0;
    }

protected:
    void hessian_values(ConstVectorRef, double sigma, ConstVectorRef lambda, VectorRef values) override
    {
        values.setConstant(2.0 * sigma + 2.0 * lambda[0]);
    }

private:
    double lower_, upper_;
    SparsityPattern jacobian_, hessian_;
};

} // namespace

TEST_CASE("constraint residuals give the violation and the PHR shift of equality and inequality rows alike",
          "[constrained]")
{
    // Rows: c = 1 (equality), c >= 0, c <= 2, 0 <= c <= 1, free.
    class Rows final : public Nlp {
    public:
        std::string name() const override { return "rows"; }
        int num_variables() const override { return 1; }
        int num_constraints() const override { return 5; }
        void constraint_bounds(VectorRef lower, VectorRef upper) const override
        {
            lower << 1.0, 0.0, -kInfinity, 0.0, -1e20;
            upper << 1.0, kInfinity, 2.0, 1.0, 1e20;
        }
        Vector starting_point() const override { return Vector::Zero(1); }
        double objective(ConstVectorRef) override { return 0.0; }
        void gradient(ConstVectorRef, VectorRef g) override { g.setZero(); }
        const SparsityPattern& hessian_pattern() const override { return pattern_; }

    protected:
        void hessian_values(ConstVectorRef, double, ConstVectorRef, VectorRef) override {}

    private:
        SparsityPattern pattern_;
    } nlp;
    ConstraintResiduals rows(nlp);
    CHECK(rows.is_equality(0));
    CHECK_FALSE(rows.is_equality(3));

    Eigen::VectorXd c(5), v(5);
    c << 3.0, -0.5, 2.5, 0.5, 7.0;
    rows.violations(c, v);
    CHECK(v[0] == 2.0);   // c − g_L on an equality
    CHECK(v[1] == -0.5);  // below g_L
    CHECK(v[2] == 0.5);   // above g_U
    CHECK(v[3] == 0.0);   // inside
    CHECK(v[4] == 0.0);   // no side
    CHECK(rows.max_violation(c) == 2.0);

    // κ = 10, λ chosen so that rows 1 and 3 cross a side when shifted
    // (s = c + λ/κ), row 2 does not although c violates it, row 4 never.
    Eigen::VectorXd lambda(5), r(5), mu(5), active(5);
    lambda << 1.0, -2.0, -10.0, 8.0, 3.0;
    rows.shifted(c, lambda, 10.0, r, mu, active);
    CHECK(r[0] == 2.0);
    CHECK(mu[0] == Approx(21.0));
    CHECK(active[0] == 1.0);
    CHECK(r[1] == -0.5);  // s = −0.7 below g_L = 0
    CHECK(mu[1] == Approx(-7.0));
    CHECK(active[1] == 1.0);
    CHECK(r[2] == Approx(1.0));  // s = 1.5 inside: r = −λ/κ, μ = 0
    CHECK(mu[2] == 0.0);
    CHECK(active[2] == 0.0);
    CHECK(r[3] == Approx(-0.5));  // s = 1.3 above g_U = 1: r = c − g_U
    CHECK(mu[3] == Approx(3.0));
    CHECK(active[3] == 1.0);
    CHECK(mu[4] == 0.0);
    CHECK(active[4] == 0.0);
}

TEST_CASE("kkt-newton and relaxed-kkt refuse inequalities naming the strategies that take them", "[constrained]")
{
    auto hs071 = find_builtin_problem("hs071").make();
    for (const std::string solver : {"kkt-newton", "relaxed-kkt"}) {
        const auto why = find_solver(solver).refusal(*hs071);
        REQUIRE(why);
        CAPTURE(*why);
        CHECK(why->find("use interior-point, penalty, augmented-lagrangian or ipopt") != std::string::npos);
    }
    for (const std::string solver : {"penalty", "augmented-lagrangian"})
        CHECK_FALSE(find_solver(solver).refusal(*hs071));
}

TEST_CASE("augmented-lagrangian reaches the published optimum of every inequality HS problem with signed multipliers",
          "[constrained]")
{
    SolverOptions options;
    options.constraint_tolerance = 1e-8;
    for (const std::string& name : kInequalityProblems) {
        const BuiltinProblem& problem = find_builtin_problem(name);
        const Result r = solve_named(name, "augmented-lagrangian", options);
        const double f_star = *problem.reference_objective;
        CAPTURE(name, r.message, r.objective, f_star, r.constraint_violation, r.kkt_residual, r.iterations);
        CHECK(r.status == Status::converged);
        CHECK(std::abs(r.objective - f_star) <= 1e-6 * std::max(1.0, std::abs(f_star)));
        CHECK(r.constraint_violation <= 1e-8);
        // The multipliers are the method's own (solve() estimates none) and
        // pass solve()'s KKT measure, signs and complementarity included.
        CHECK_FALSE(r.multipliers_estimated);
        auto nlp = problem.make();
        check_inequality_multipliers(*nlp, r, 1e-8);
    }
}

TEST_CASE("penalty reaches the published optimum of every inequality HS problem as kappa grows", "[constrained]")
{
    // As on the equality problems: the violation reported is the one measured,
    // converged only within constr_tol, never failed; the optimum is reached
    // to the accuracy the feasibility tolerance allows, after κ has grown
    // past its first value (every one of these has an active inequality).
    const SolverOptions options;
    for (const std::string& name : kInequalityProblems) {
        const BuiltinProblem& problem = find_builtin_problem(name);
        const Result r = solve_named(name, "penalty", options);
        const double f_star = *problem.reference_objective;
        CAPTURE(name, r.message, r.objective, f_star, r.constraint_violation, r.kkt_residual);
        auto nlp = problem.make();
        CHECK(r.constraint_violation == max_constraint_violation(*nlp, r.x));
        if (r.status == Status::converged)
            CHECK(r.constraint_violation <= options.constraint_tolerance);
        else
            CHECK(r.status != Status::failed);
        CHECK(r.status == Status::converged);
        CHECK(std::abs(r.objective - f_star) <= 1e-6 * std::max(1.0, std::abs(f_star)));
        CHECK(r.statistics.at("kappa") > 1e2);
        check_inequality_multipliers(*nlp, r, options.constraint_tolerance);
    }
}

TEST_CASE("an inactive inequality leaves the unconstrained minimizer with multiplier 0", "[constrained]")
{
    for (const auto& [lower, upper] : {std::pair{1.0, 10.0}, std::pair{-kInfinity, 10.0}, std::pair{1.0, kInfinity}}) {
        for (const std::string solver : {"augmented-lagrangian", "penalty"}) {
            CircleConstraint nlp(lower, upper);
            const Result r = solve(nlp, solver, SolverOptions{});
            CAPTURE(solver, lower, upper, r.message, r.x.transpose());
            CHECK(r.status == Status::converged);
            CHECK(r.x[0] == Approx(1.0).margin(1e-8));
            CHECK(r.x[1] == Approx(2.0).margin(1e-8));
            CHECK(r.constraint_multipliers[0] == 0.0);
            CHECK(r.constraint_violation == 0.0);
        }
    }
}

TEST_CASE("an active inequality gives the constrained minimizer and a multiplier of its side's sign",
          "[constrained]")
{
    // Upper side (λ > 0): x₀² + x₁² ≤ 1, one-sided and two-sided; lower side
    // (λ < 0): x₀² + x₁² ≥ 20, one-sided and two-sided.
    for (const auto& [lower, upper] :
         {std::pair{-kInfinity, 1.0}, std::pair{0.5, 1.0}, std::pair{20.0, kInfinity}, std::pair{20.0, 30.0}}) {
        for (const std::string solver : {"augmented-lagrangian", "penalty"}) {
            CircleConstraint nlp(lower, upper);
            const Result r = solve(nlp, solver, SolverOptions{});
            const Eigen::Vector2d x_star = nlp.solution();
            const double lambda_star = nlp.multiplier();
            CAPTURE(solver, lower, upper, r.message, r.x.transpose(), r.constraint_multipliers, lambda_star);
            CHECK(r.status == Status::converged);
            CHECK((r.x - x_star).cwiseAbs().maxCoeff() <= 1e-6);
            CHECK(r.constraint_multipliers[0] == Approx(lambda_star).epsilon(1e-5));
            CHECK((lambda_star > 0.0 ? r.constraint_multipliers[0] > 0.0 : r.constraint_multipliers[0] < 0.0));
            CHECK(r.multipliers_estimated == (solver == "penalty"));
        }
    }
}

TEST_CASE("the augmented Lagrangian function with inequalities passes the shared derivative checks off its switching "
          "surfaces",
          "[constrained]")
{
    // λ is set so that each inequality row's shifted value s = c + λ/κ lies
    // well inside its interval (inactive) or well beyond a side (active),
    // alternately, farther than the checks' steps move c: the function is C²
    // there. Equality rows take random λ. A small κ keeps λ = κ(s − c), and
    // with it φ, moderate where c is far from a side.
    std::mt19937 rng(71);
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    const double kappa = 2.0;
    int active_rows = 0, inactive_rows = 0, row = 0;
    for (const std::string& name : kInequalityProblems) {
        auto problem = find_builtin_problem(name).make();
        const int m = problem->num_constraints();
        const int n = problem->num_variables();
        Eigen::VectorXd x = problem->starting_point();
        for (Eigen::Index i = 0; i < x.size(); ++i)
            x[i] += 0.1 * u11(rng);
        Eigen::VectorXd lower(m), upper(m), c(m), jacobian(problem->jacobian_pattern().nonzeros());
        problem->constraint_bounds(lower, upper);
        problem->constraints(x, c);
        problem->jacobian_values(x, jacobian);
        // How far c may move over the checks' steps (h ≤ 1e-2 · max(1, |x_j|)), with room to spare.
        Eigen::VectorXd reach = Eigen::VectorXd::Ones(m);
        const SparsityPattern& J = problem->jacobian_pattern();
        for (int k = 0; k < J.nonzeros(); ++k)
            reach[J.rows[k]] += 0.1 * std::abs(jacobian[k]) * std::max(1.0, std::abs(x[J.cols[k]]));
        Eigen::VectorXd lambda(m);
        int expected_active = 0;
        for (int i = 0; i < m; ++i) {
            if (lower[i] == upper[i]) {
                lambda[i] = 3.0 * u11(rng);
                continue;
            }
            const bool has_lower = is_finite_bound(lower[i]);
            const bool has_upper = is_finite_bound(upper[i]);
            const bool make_active = row++ % 2 == 0;
            double s = 0.0;  // the shifted value wanted
            if (make_active)
                s = has_upper ? upper[i] + reach[i] : lower[i] - reach[i];
            else if (has_lower && has_upper)
                s = 0.5 * (lower[i] + upper[i]);  // (every row of these problems is one-sided)
            else
                s = has_lower ? lower[i] + reach[i] : upper[i] - reach[i];
            lambda[i] = kappa * (s - c[i]);
            (make_active ? active_rows : inactive_rows) += 1;
            expected_active += make_active;
        }
        AugmentedLagrangianFunction function(*problem);
        function.set_parameters(lambda, kappa);
        Eigen::VectorXd grad(n);
        function.gradient(x, grad);
        int active_here = 0;  // inequality rows with μ ≠ 0
        for (int i = 0; i < m; ++i)
            active_here += lower[i] != upper[i] && function.last_multipliers()[i] != 0.0;
        CAPTURE(name, lambda.transpose(), c.transpose(), function.last_multipliers().transpose());
        CHECK(active_here == expected_active);
        // 1e-5, the check's own tolerance: at hs100's start c is 265 from
        // its side, φ holds terms of 7e4 and its central differences carry
        // relative round-off of 1e-6 in ∇φ.
        const DerivativeCheckReport entrywise = check_derivatives(function, x);
        CAPTURE(entrywise.to_text());
        CHECK(entrywise.passed(1e-5));
        const TaylorReport taylor = taylor_test(function, x);
        CAPTURE(taylor.to_text());
        CHECK(taylor.passed());
    }
    CHECK(active_rows >= 6);
    CHECK(inactive_rows >= 6);
}

namespace {

/// hs071 declaring its Hessian inexact, counting the Hessian calls it gets.
class InexactHessianHs071 final : public Nlp {
public:
    std::string name() const override { return "hs071-inexact"; }
    int num_variables() const override { return inner_->num_variables(); }
    int num_constraints() const override { return inner_->num_constraints(); }
    void variable_bounds(VectorRef l, VectorRef u) const override { inner_->variable_bounds(l, u); }
    void constraint_bounds(VectorRef l, VectorRef u) const override { inner_->constraint_bounds(l, u); }
    Vector starting_point() const override { return inner_->starting_point(); }
    double objective(ConstVectorRef x) override { return inner_->objective(x); }
    void gradient(ConstVectorRef x, VectorRef g) override { inner_->gradient(x, g); }
    void constraints(ConstVectorRef x, VectorRef c) override { inner_->constraints(x, c); }
    const SparsityPattern& jacobian_pattern() const override { return inner_->jacobian_pattern(); }
    void jacobian_values(ConstVectorRef x, VectorRef v) override { inner_->jacobian_values(x, v); }
    const SparsityPattern& hessian_pattern() const override { return inner_->hessian_pattern(); }
    bool exact_hessian() const override { return false; }
    int hessian_calls = 0;

protected:
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override
    {
        ++hessian_calls;
        inner_->hessian(x, sigma, lambda, Projection::none, values);
    }

private:
    std::unique_ptr<Nlp> inner_ = find_builtin_problem("hs071").make();
};

} // namespace

TEST_CASE("Ipopt runs in limited-memory mode on a problem whose Hessian is not exact", "[constrained]")
{
    InexactHessianHs071 nlp;
    CHECK_FALSE(capabilities_of(nlp).exact_hessian);
    const Result r = solve(nlp, "ipopt", SolverOptions{});
    CAPTURE(r.message);
    CHECK(r.status == Status::converged);
    CHECK(r.objective == Approx(17.0140173).epsilon(1e-6));
    CHECK(nlp.hessian_calls == 0);
}
