// The constrained Newton strategies (issue 12) on the equality- and
// bound-constrained Hock-Schittkowski problems and on small problems built to
// break them: published optima, quadratic convergence of kkt-newton, the 1/κ
// violation of relaxed KKT, the equivalence of its two linear systems and of
// the penalty, inertia correction, and honest statuses on infeasible input.
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/taylor_test.hpp"
#include "sinew/solvers/constrained/augmented_lagrangian_function.hpp"
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
    // e_{k+1} ≤ C e_k² (C = 1e3) over the steps where e_k < 1e-4 and e_{k+1}
    // is above round-off: a linear rate ρ > 0.1 would give e_{k+1} > 1e3 e_k² there.
    for (const std::string problem : {"hs005", "hs007", "hs039", "hs056", "hs077"}) {
        const Result r = solve_named(problem, "kkt-newton", SolverOptions{});
        REQUIRE(r.status == Status::converged);
        const std::vector<double> e = kkt_errors(r);
        int ratios = 0;
        for (size_t k = 0; k + 1 < e.size(); ++k) {
            if (!(e[k] < 1e-4) || !(e[k + 1] > 1e-14))
                continue;
            CAPTURE(problem, k, e[k], e[k + 1]);
            CHECK(e[k + 1] <= 1e3 * e[k] * e[k]);
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
