// interior-point (issue 32): the published optimum of every Hock-Schittkowski
// problem under both barrier rules, iterations against Ipopt, honest statuses
// (infeasible, diverging, singular), the restoration phase on the Wächter-
// Biegler example, and the pieces: slack formulation derivatives, filter,
// fraction to the boundary, barrier parameter.
#include "sinew/bench/reference_check.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/solvers/interior/barrier_bounds.hpp"
#include "sinew/solvers/interior/barrier_parameter.hpp"
#include "sinew/solvers/interior/filter.hpp"
#include "sinew/solvers/interior/slack_formulation.hpp"
#include "sinew/solvers/solver.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace sinew;

namespace {

std::vector<const BuiltinProblem*> hock_schittkowski_problems()
{
    std::vector<const BuiltinProblem*> problems;
    for (const BuiltinProblem& p : builtin_problems())
        if ((p.suite == "classic" || p.suite == "constrained") && p.name.rfind("hs", 0) == 0)
            problems.push_back(&p);
    return problems;
}

SolverOptions with_option(const std::string& key, const std::string& value)
{
    SolverOptions options;
    options.backend[key] = value;
    return options;
}

/// A problem of one variable and one constraint given by lambdas:
/// f, f', f'', c, c', c'' with bounds on x and on c.
class OneVariable final : public Nlp {
public:
    struct Functions {
        double (*f)(double), (*df)(double), (*d2f)(double), (*c)(double), (*dc)(double), (*d2c)(double);
    };
    OneVariable(Functions fn, double start, double x_lower, double x_upper, double c_lower, double c_upper)
        : fn_(fn), start_(start), x_lower_(x_lower), x_upper_(x_upper), c_lower_(c_lower), c_upper_(c_upper)
    {
        jacobian_.add(0, 0);
        hessian_.add(0, 0);
    }
    std::string name() const override { return "one-variable"; }
    int num_variables() const override { return 1; }
    int num_constraints() const override { return 1; }
    void variable_bounds(VectorRef lower, VectorRef upper) const override
    {
        lower[0] = x_lower_;
        upper[0] = x_upper_;
    }
    void constraint_bounds(VectorRef lower, VectorRef upper) const override
    {
        lower[0] = c_lower_;
        upper[0] = c_upper_;
    }
    Vector starting_point() const override { return Vector::Constant(1, start_); }
    double objective(ConstVectorRef x) override { return fn_.f(x[0]); }
    void gradient(ConstVectorRef x, VectorRef g) override { g[0] = fn_.df(x[0]); }
    void constraints(ConstVectorRef x, VectorRef c) override { c[0] = fn_.c(x[0]); }
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef v) override { v[0] = fn_.dc(x[0]); }
    const SparsityPattern& hessian_pattern() const override { return hessian_; }

protected:
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef v) override
    {
        v[0] = sigma * fn_.d2f(x[0]) + lambda[0] * fn_.d2c(x[0]);
    }

private:
    Functions fn_;
    double start_, x_lower_, x_upper_, c_lower_, c_upper_;
    SparsityPattern jacobian_, hessian_;
};

/// Wächter & Biegler, "Failure of global convergence for a class of interior
/// point methods for nonlinear programming", Math. Program. 88 (2000): from
/// (−2, 3, 1) many interior-point methods stall at an infeasible point;
///     minimize x₀  subject to  x₀² − x₁ − 1 = 0,  x₀ − x₂ − ½ = 0,  x₁, x₂ ≥ 0,
/// solution (1, 0, ½), f* = 1.
class WaechterBieglerExample final : public Nlp {
public:
    WaechterBieglerExample()
    {
        jacobian_.add(0, 0);
        jacobian_.add(0, 1);
        jacobian_.add(1, 0);
        jacobian_.add(1, 2);
        hessian_.add(0, 0);
    }
    std::string name() const override { return "waechter-biegler-2000"; }
    int num_variables() const override { return 3; }
    int num_constraints() const override { return 2; }
    void variable_bounds(VectorRef lower, VectorRef upper) const override
    {
        lower << -kInfinity, 0.0, 0.0;
        upper.setConstant(kInfinity);
    }
    void constraint_bounds(VectorRef lower, VectorRef upper) const override
    {
        lower.setZero();
        upper.setZero();
    }
    Vector starting_point() const override { return (Vector(3) << -2.0, 3.0, 1.0).finished(); }
    double objective(ConstVectorRef x) override { return x[0]; }
    void gradient(ConstVectorRef, VectorRef g) override { g << 1.0, 0.0, 0.0; }
    void constraints(ConstVectorRef x, VectorRef c) override { c << x[0] * x[0] - x[1] - 1.0, x[0] - x[2] - 0.5; }
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef v) override { v << 2.0 * x[0], -1.0, 1.0, -1.0; }
    const SparsityPattern& hessian_pattern() const override { return hessian_; }

protected:
    void hessian_values(ConstVectorRef, double, ConstVectorRef lambda, VectorRef v) override { v[0] = 2.0 * lambda[0]; }

private:
    SparsityPattern jacobian_, hessian_;
};

} // namespace

TEST_CASE("interior-point reaches the published optimum of every Hock-Schittkowski problem under both barrier rules")
{
    const std::string rule = GENERATE("monotone", "adaptive");
    for (const BuiltinProblem* problem : hock_schittkowski_problems()) {
        auto nlp = problem->make();
        const Result r = solve(*nlp, "interior-point", with_option("mu_strategy", rule));
        CAPTURE(rule, problem->name, r.message, r.objective, r.constraint_violation, r.kkt_residual, r.iterations);
        CHECK(r.status == Status::converged);
        CHECK(reaches_reference(*problem, r, ReferenceTolerances{}));
        // Converged by its own test, not downgraded by solve()'s measurement.
        CHECK(r.message.find("but") == std::string::npos);
    }
}

TEST_CASE("interior-point needs no more iterations than Ipopt on at least half the Hock-Schittkowski problems")
{
    int at_most = 0, total = 0;
    for (const BuiltinProblem* problem : hock_schittkowski_problems()) {
        auto ours = problem->make();
        auto theirs = problem->make();
        const Result a = solve(*ours, "interior-point", SolverOptions{});
        const Result b = solve(*theirs, "ipopt", SolverOptions{});
        if (b.status != Status::converged)
            continue;
        ++total;
        at_most += a.iterations <= b.iterations ? 1 : 0;
        UNSCOPED_INFO(problem->name << ": interior-point " << a.iterations << ", ipopt " << b.iterations);
    }
    CAPTURE(at_most, total);
    REQUIRE(total >= 20);
    CHECK(2 * at_most >= total);
}

TEST_CASE("the restoration phase takes interior-point to the solution of the Waechter-Biegler example")
{
    WaechterBieglerExample nlp;
    const Result r = solve(nlp, "interior-point", SolverOptions{});
    CAPTURE(r.message, r.iterations, r.x.transpose());
    REQUIRE(r.status == Status::converged);
    CHECK(r.objective == Approx(1.0).epsilon(1e-8));
    CHECK(r.x[1] == Approx(0.0).margin(1e-7));
    CHECK(r.x[2] == Approx(0.5).epsilon(1e-7));
    CHECK(r.statistics.at("restoration_phases") >= 1.0);
}

TEST_CASE("interior-point calls a locally infeasible problem infeasible")
{
    SECTION("x^2 + 1 = 0")
    {
        OneVariable nlp({[](double x) { return x * x; }, [](double x) { return 2.0 * x; }, [](double) { return 2.0; },
                         [](double x) { return x * x + 1.0; }, [](double x) { return 2.0 * x; },
                         [](double) { return 2.0; }},
                        1.5, -kInfinity, kInfinity, 0.0, 0.0);
        const Result r = solve(nlp, "interior-point", SolverOptions{});
        CAPTURE(r.message, r.x.transpose());
        CHECK(r.status == Status::infeasible);
        CHECK(r.x[0] == Approx(0.0).margin(1e-6));
    }
    SECTION("x >= 0 and x + 1 <= 0")
    {
        OneVariable nlp({[](double x) { return (x - 2.0) * (x - 2.0); }, [](double x) { return 2.0 * (x - 2.0); },
                         [](double) { return 2.0; }, [](double x) { return x + 1.0; }, [](double) { return 1.0; },
                         [](double) { return 0.0; }},
                        3.0, 0.0, kInfinity, -kInfinity, 0.0);
        const Result r = solve(nlp, "interior-point", SolverOptions{});
        CAPTURE(r.message, r.x.transpose());
        CHECK(r.status == Status::infeasible);
    }
}

TEST_CASE("interior-point reports diverging iterates of a problem unbounded below")
{
    // minimize −x² − x subject to x ≥ −1 (as an inequality): no minimum.
    OneVariable nlp({[](double x) { return -x * x - x; }, [](double x) { return -2.0 * x - 1.0; },
                     [](double) { return -2.0; }, [](double x) { return x; }, [](double) { return 1.0; },
                     [](double) { return 0.0; }},
                    0.0, -kInfinity, kInfinity, -1.0, kInfinity);
    const Result r = solve(nlp, "interior-point", SolverOptions{});
    CAPTURE(r.message, r.iterations);
    CHECK(r.status != Status::converged);
    CHECK(r.message.find("unbounded") != std::string::npos);
}

TEST_CASE("the slack formulation has the derivatives of the problem it rewrites")
{
    const std::string name = GENERATE("hs071", "hs043", "hs076", "hs100");
    auto problem = find_builtin_problem(name).make();
    SlackFormulation slacks(*problem);
    REQUIRE(slacks.num_slacks() > 0);
    std::mt19937 random(11);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (int trial = 0; trial < 4; ++trial) {
        Eigen::VectorXd w = slacks.starting_point();
        for (int i = 0; i < w.size(); ++i)
            w[i] += 0.3 * normal(random) * std::max(1.0, std::abs(w[i]));
        const DerivativeCheckReport report = check_derivatives(slacks, w);
        CAPTURE(name, trial, report.to_text());
        CHECK(report.passed(1e-5));
    }
    // The residual of an inequality row is c_I(x) − s: zero at the starting point.
    Eigen::VectorXd r(slacks.num_constraints());
    slacks.constraints(slacks.starting_point(), r);
    Eigen::VectorXd lower(slacks.num_constraints()), upper(slacks.num_constraints());
    problem->constraint_bounds(lower, upper);
    for (int i = 0; i < r.size(); ++i)
        if (lower[i] != upper[i])
            CHECK(r[i] == 0.0);
}

TEST_CASE("the filter rejects what an entry dominates and keeps only undominated entries")
{
    Filter filter;
    CHECK(filter.accepts(1.0, 1.0));
    filter.add(1.0, 1.0);
    CHECK_FALSE(filter.accepts(1.0, 1.0));   // the margins exclude the entry itself
    CHECK_FALSE(filter.accepts(2.0, 2.0));   // worse in both
    CHECK(filter.accepts(0.5, 5.0));         // better in θ
    CHECK(filter.accepts(5.0, 0.5));         // better in φ
    filter.add(0.1, 0.1);                    // dominates the first entry, which goes
    CHECK(filter.accepts(0.5, 5.0) == false);
    CHECK(improves_on(0.5, 10.0, 1.0, 1.0));
    CHECK_FALSE(improves_on(1.0, 1.0, 1.0, 1.0));
}

TEST_CASE("the fraction to the boundary keeps iterates strictly inside the relaxed bounds")
{
    WaechterBieglerExample nlp;
    const BarrierBounds bounds(nlp, 1e-8);
    Eigen::VectorXd w(3), dw(3);
    w << 0.0, 1.0, 2.0;
    dw << -100.0, -10.0, -4.0;
    const double alpha = bounds.max_step(w, dw, 0.99);
    // x₁ reaches 1% of its distance to 0 at α = 0.099 (bound relaxed by 1e-8).
    CHECK(alpha == Approx(0.99 * (1.0 + 1e-8) / 10.0).epsilon(1e-12));
    const Eigen::VectorXd next = w + alpha * dw;
    CHECK(std::isfinite(bounds.barrier(next, 0.1)));
    CHECK_FALSE(std::isfinite(bounds.barrier(w + 1.01 * alpha / 0.99 * dw, 0.1)));
}

TEST_CASE("the monotone barrier rule falls as min(0.2 mu, mu^1.5) once each barrier problem is solved")
{
    BarrierParameter mu(BarrierParameter::Rule::monotone, 0.1, 1e-9);
    BarrierMeasures solved;
    solved.barrier_error = [](double) { return 0.0; };
    BarrierMeasures unsolved;
    unsolved.barrier_error = [](double mu_value) { return 11.0 * mu_value; };
    CHECK_FALSE(mu.update(unsolved));
    CHECK(mu.mu() == 0.1);
    CHECK(mu.update(solved));  // E_μ = 0 at every μ: falls to the floor at once
    CHECK(mu.mu() == 1e-9);
    CHECK(mu.at_floor());
    BarrierParameter step(BarrierParameter::Rule::monotone, 0.1, 1e-9);
    BarrierMeasures once;
    once.barrier_error = [](double mu_value) { return mu_value < 0.05 ? 1.0 : 0.0; };
    CHECK(step.update(once));
    CHECK(step.mu() == Approx(0.02));  // min(0.2 · 0.1, 0.1^1.5 = 0.0316)
    CHECK(step.fraction_to_boundary() == Approx(0.99));
}
