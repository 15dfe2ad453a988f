// Projected Newton on problems with known answers: it converges, reuses one
// symbolic analysis, refuses constrained problems, and reports a failed
// start as a status.
#include "sinew/core/input_error.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/solvers/solver.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace sinew;

namespace {

/// f(x) = Σ (x_i − log x_i): convex, defined for x > 0 only (+∞ elsewhere),
/// minimum at x = 1. From x₀ = 2.5 the full Newton step x − x² lands at
/// −1.25, where f is not finite.
class LogBarrier final : public Nlp {
public:
    explicit LogBarrier(int n) : n_(n)
    {
        for (int i = 0; i < n; ++i)
            pattern_.add(i, i);
    }
    std::string name() const override { return "log_barrier"; }
    int num_variables() const override { return n_; }
    Vector starting_point() const override { return Vector::Constant(n_, 2.5); }
    double objective(ConstVectorRef x) override
    {
        if ((x.array() <= 0.0).any())
            return std::numeric_limits<double>::infinity();
        return (x.array() - x.array().log()).sum();
    }
    void gradient(ConstVectorRef x, VectorRef g) override { g = (1.0 - 1.0 / x.array()).matrix(); }
    const SparsityPattern& hessian_pattern() const override { return pattern_; }
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values) override
    {
        values = (sigma / x.array().square()).matrix();
    }

private:
    int n_;
    SparsityPattern pattern_;
};

} // namespace

TEST_CASE("projected Newton converges on extended Rosenbrock with one symbolic analysis")
{
    auto nlp = find_builtin_problem("rosenbrock1000").make();
    SolverOptions options;
    options.backend["reuse_factorization"] = "off";  // one solve per iteration
    const Result r = solve(*nlp, "projected-newton", options);
    CAPTURE(r.message, r.iterations);
    CHECK(r.status == Status::converged);
    CHECK(r.objective < 1e-12);
    CHECK(r.statistics.at("symbolic_analyses") == 1);
    CHECK(r.linear_solves == r.iterations);
    REQUIRE(r.history.size() == static_cast<size_t>(r.iterations) + 1);
    for (size_t k = 1; k < r.history.size(); ++k)
        CHECK(r.history[k].objective <= r.history[k - 1].objective);
}

TEST_CASE("projected Newton backs off where f is not finite")
{
    LogBarrier nlp(50);
    const Result r = solve(nlp, "projected-newton", SolverOptions{});
    CAPTURE(r.message);
    CHECK(r.status == Status::converged);
    CHECK((r.x.array() - 1.0).abs().maxCoeff() < 1e-8);
    REQUIRE(r.history.size() >= 2);
    CHECK(r.history[1].step_length == 0.5);  // the full step leaves x > 0; half of it does not
}

TEST_CASE("projected Newton refuses constrained problems and unknown options")
{
    auto hs071 = find_builtin_problem("hs071").make();
    CHECK(find_solver("projected-newton").refusal(*hs071).has_value());
    CHECK_THROWS_AS(solve(*hs071, "projected-newton", SolverOptions{}), InputError);
    auto rosenbrock = find_builtin_problem("rosenbrock2").make();
    SolverOptions options;
    options.backend["linear_solver"] = "mumps";
    CHECK_THROWS_AS(solve(*rosenbrock, "projected-newton", options), InputError);
    options.backend = {{"armijo", "0.7"}};
    CHECK_THROWS_AS(solve(*rosenbrock, "projected-newton", options), InputError);
}
