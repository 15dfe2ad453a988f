// The integrators alone, on the scalar oscillator u'' = −ω²u, whose step
// minimizes ½(y − x̃)²/s + ½ω²y² exactly: y = x̃/(1 + sω²). Against the
// closed-form discrete solutions of each scheme (u₀ = 0, v₀ = V):
//   implicit Euler  uₙ = (V/ω) |R|ⁿ sin(nθ),  |R| = (1 + ω²h²)^(−½), θ = atan(ωh)
//   trapezoidal (Newmark β = ¼, γ = ½) and implicit midpoint (the same map on a
//   linear system)  uₙ = (V/ω) sin(nθ),  θ = 2 atan(ωh/2)
// and BDF2 against its textbook recurrence in (u, v).
#include "sinew/core/input_error.hpp"
#include "sinew/time/time_integrator.hpp"
#include "time/bdf2_reference.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <cmath>

namespace {

using sinew::TimeIntegrator;
using sinew::TimeState;

TimeState scalar_state(double u, double v, double a)
{
    TimeState s;
    s.x = Eigen::VectorXd::Constant(1, u);
    s.v = Eigen::VectorXd::Constant(1, v);
    s.a = Eigen::VectorXd::Constant(1, a);
    return s;
}

/// uₙ for n = 0 … steps of the scalar oscillator under `name`.
std::vector<double> oscillate(const std::string& name, double omega, double h, double V, int steps)
{
    auto integrator = sinew::make_integrator(name, h);
    integrator->start(scalar_state(0.0, V, 0.0));  // a₀ = −ω²u₀ = 0
    std::vector<double> u{0.0};
    for (int n = 0; n < steps; ++n) {
        const double y = integrator->predictor()[0] / (1.0 + integrator->force_scaling() * omega * omega);
        integrator->advance(Eigen::VectorXd::Constant(1, y));
        u.push_back(integrator->state().x[0]);
    }
    return u;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b)
{
    double worst = 0.0;
    for (size_t n = 0; n < a.size(); ++n)
        worst = std::max(worst, std::abs(a[n] - b[n]));
    return worst;
}

} // namespace

TEST_CASE("integrators: unknown names and invalid steps are input errors", "[time]")
{
    CHECK_THROWS_AS(sinew::make_integrator("runge-kutta", 0.1), sinew::InputError);
    CHECK_THROWS_WITH(sinew::make_integrator("runge-kutta", 0.1), Catch::Contains("implicit-midpoint"));
    CHECK_THROWS_AS(sinew::make_integrator("bdf2", 0.0), sinew::InputError);
    CHECK_THROWS_AS(sinew::make_integrator("bdf2", -1.0), sinew::InputError);
    CHECK_THROWS_AS(sinew::make_integrator("bdf2", std::nan("")), sinew::InputError);
    for (const std::string& name : sinew::integrator_names())
        CHECK(sinew::make_integrator(name, 0.1)->name() == name);
}

TEST_CASE("integrators: the scalar oscillator follows each scheme's closed-form discrete solution", "[time]")
{
    const double omega = 3.0, V = 2.0;
    const int steps = 500;
    for (const double h : {0.01, 0.1, 0.7}) {
        CAPTURE(h);
        const double amplitude = V / omega;
        std::vector<double> damped(steps + 1), conservative(steps + 1);
        const double R = 1.0 / std::sqrt(1.0 + omega * omega * h * h);
        for (int n = 0; n <= steps; ++n) {
            damped[n] = amplitude * std::pow(R, n) * std::sin(n * std::atan(omega * h));
            conservative[n] = amplitude * std::sin(n * 2.0 * std::atan(omega * h / 2.0));
        }
        CHECK(max_difference(oscillate("implicit-euler", omega, h, V, steps), damped) < 1e-12 * amplitude);
        CHECK(max_difference(oscillate("newmark", omega, h, V, steps), conservative) < 1e-11 * amplitude);
        CHECK(max_difference(oscillate("implicit-midpoint", omega, h, V, steps), conservative) < 1e-11 * amplitude);
        CHECK(max_difference(oscillate("bdf2", omega, h, V, steps), sinew::test::bdf2_recurrence(omega, h, V, steps)) <
              1e-11 * amplitude);
    }
}

TEST_CASE("integrators: temporal order on the scalar oscillator is 1 for implicit Euler and 2 for the others", "[time]")
{
    const double omega = 2.0, V = 1.0, T = 3.0;
    for (const std::string& name : sinew::integrator_names()) {
        CAPTURE(name);
        std::vector<double> errors;
        for (int steps : {400, 800, 1600, 3200}) {
            const std::vector<double> u = oscillate(name, omega, T / steps, V, steps);
            errors.push_back(std::abs(u.back() - V / omega * std::sin(omega * T)));
        }
        const double expected = name == "implicit-euler" ? 1.0 : 2.0;
        for (size_t k = 1; k < errors.size(); ++k) {
            const double order = std::log2(errors[k - 1] / errors[k]);
            CAPTURE(errors[k - 1], errors[k]);
            CHECK(std::abs(order - expected) < 0.1);
        }
    }
}
