// The cantilever scenes of issue 4 solved by projected Newton and by Ipopt:
// the same equilibrium, Newton converging quadratically near it, and the
// elimination and equality-constraint forms of the clamp agreeing.
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/solvers/solver.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace sinew;

namespace {

constexpr double kSceneSize = 1.0;  // the beam's length, m

struct Solved {
    Eigen::VectorXd configuration;  ///< all node coordinates
    double energy = 0.0;
    Result result;
};

Solved solve_cantilever(int cells_across, bool twisted, const std::string& solver,
                        DirichletStrategy dirichlet = DirichletStrategy::eliminate)
{
    auto problem = make_cantilever(cells_across, twisted, dirichlet);
    SolverOptions options;
    options.tolerance = 1e-10;
    Solved solved;
    solved.result = solve(*problem, solver, options);
    solved.configuration = problem->full_configuration(solved.result.x);
    solved.energy = solved.result.objective;
    return solved;
}

double max_nodal_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
    double worst = 0.0;
    for (Eigen::Index i = 0; i < a.size(); i += 3)
        worst = std::max(worst, (a.segment<3>(i) - b.segment<3>(i)).norm());
    return worst;
}

} // namespace

TEST_CASE("projected Newton and Ipopt reach the same cantilever equilibrium")
{
    const bool twisted = GENERATE(false, true);
    CAPTURE(twisted);
    const Solved newton = solve_cantilever(4, twisted, "projected-newton");
    const Solved ipopt = solve_cantilever(4, twisted, "ipopt");
    CAPTURE(newton.result.message, ipopt.result.message, newton.result.iterations, ipopt.result.iterations);
    REQUIRE(newton.result.status == Status::converged);
    REQUIRE(ipopt.result.status == Status::converged);
    CHECK(max_nodal_difference(newton.configuration, ipopt.configuration) <= 1e-6 * kSceneSize);
    CHECK(std::abs(newton.energy - ipopt.energy) <= 1e-9 * std::abs(ipopt.energy));
}

TEST_CASE("eliminated and equality-constrained clamps give the same equilibrium")
{
    const Solved eliminated = solve_cantilever(3, true, "ipopt", DirichletStrategy::eliminate);
    const Solved constrained = solve_cantilever(3, true, "ipopt", DirichletStrategy::equality_constraints);
    CAPTURE(eliminated.result.message, constrained.result.message);
    REQUIRE(eliminated.result.status == Status::converged);
    REQUIRE(constrained.result.status == Status::converged);
    CHECK(max_nodal_difference(eliminated.configuration, constrained.configuration) <= 1e-6 * kSceneSize);
    CHECK(std::abs(eliminated.energy - constrained.energy) <= 1e-9 * std::abs(eliminated.energy));
}

TEST_CASE("projected Newton converges quadratically near the cantilever's equilibrium")
{
    const Solved newton = solve_cantilever(4, false, "projected-newton");
    REQUIRE(newton.result.status == Status::converged);
    const auto& history = newton.result.history;
    const double initial = history.front().dual_residual;
    // r_k = ‖∇f(x_k)‖∞ / ‖∇f(x₀)‖∞. Quadratic convergence: r_{k+1} ≤ C r_k².
    // Judged on full steps taken from r_k ≤ 1e-3 that end above r = 1e-10,
    // where the gradient (a sum of thousands of element forces) is still
    // exact enough to tell; with C = 100, 100 r_k² ≤ 0.1 r_k there, so a
    // linear rate (even 0.1 per iteration) fails the check.
    int judged = 0;
    for (size_t k = 1; k + 1 < history.size(); ++k) {
        const double r = history[k].dual_residual / initial;
        const double next = history[k + 1].dual_residual / initial;
        if (r > 1e-3 || next < 1e-10 || history[k + 1].step_length != 1.0)
            continue;
        CAPTURE(k, r, next, next / (r * r));
        CHECK(next <= 100.0 * r * r);
        ++judged;
    }
    CHECK(judged >= 1);
}
