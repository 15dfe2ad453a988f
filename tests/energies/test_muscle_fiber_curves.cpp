// The fiber curves of the muscle model (energies/models/muscle_fiber_curves):
// published values, C¹ at every break point, exact primitives.
#include "sinew/energies/models/muscle_fiber_curves.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace {

using sinew::ActiveFiberCurve;
using sinew::FiberCurvePoint;
using sinew::PassiveFiberCurve;

struct CurveParameters {
    double sigma_max;
    double lambda_opt;
    double P1;
    double P2;
    double lambda_star;
};

// PhysBAM's face-model values (λ_opt = 1, σ_max = 3e5 Pa, P1 = 0.05, P2 = 6.6,
// λ* = 1.4), a longer optimal stretch and a small-scale set.
const std::vector<CurveParameters> kParameterSets = {
    {3e5, 1.0, 0.05, 6.6, 1.4}, {3e5, 1.2, 0.05, 6.6, 1.6}, {2.0, 0.9, 0.25, 4.0, 1.3}};

template <typename Breaks>
bool near_any(const Breaks& breaks, double lambda, double margin)
{
    for (double b : breaks)
        if (std::abs(lambda - b) < margin)
            return true;
    return false;
}

} // namespace

TEST_CASE("muscle fiber curves: published values", "[energies][muscle]")
{
    const double sigma_max = 3e5;
    const ActiveFiberCurve active(sigma_max, 1.0);
    const PassiveFiberCurve passive(sigma_max, 0.05, 6.6, 1.0, 1.4);

    // Active, PhysBAM's face model (λ_opt = 1): σ_max(1 − (25/6)s²) for |s| ≤ 0.4,
    // σ_max(25/3)(|s| − 0.6)² out to |s| = 0.6, s = λ − 1.
    CHECK(active.evaluate(1.0).stress == Approx(sigma_max).epsilon(1e-15));
    CHECK(active.evaluate(1.0).stiffness == 0.0);
    CHECK(active.evaluate(1.2).stress == Approx(sigma_max * (1.0 - 25.0 / 6.0 * 0.04)).epsilon(1e-14));
    CHECK(active.evaluate(0.8).stress == Approx(sigma_max * (1.0 - 25.0 / 6.0 * 0.04)).epsilon(1e-14));
    CHECK(active.evaluate(1.5).stress == Approx(sigma_max * 25.0 / 3.0 * 0.01).epsilon(1e-12));
    CHECK(active.evaluate(0.45).stress == Approx(sigma_max * 25.0 / 3.0 * 0.0025).epsilon(1e-12));
    CHECK(active.evaluate(0.35).stress == 0.0);
    CHECK(active.evaluate(1.65).stress == 0.0);
    CHECK(active.evaluate(1.0).energy == 0.0);
    // Whole area under the bell: σ_max ∫ g = (2/3)σ_max.
    CHECK(active.evaluate(2.0).energy - active.evaluate(0.3).energy == Approx(2.0 / 3.0 * sigma_max).epsilon(1e-14));

    // Passive: zero at and below slack, P1(e^{P2 s} − 1 − P2 s) up to λ* = 1.4, then
    // PhysBAM's line P3 λ + P4, P3 = P1P2(e^{P2(λ*−1)} − 1), P4 = P1(e^{P2(λ*−1)}(1 − P2λ*) + P2 − 1).
    CHECK(passive.evaluate(0.9).stress == 0.0);
    CHECK(passive.evaluate(1.0).stress == 0.0);
    CHECK(passive.evaluate(1.0).energy == 0.0);
    CHECK(passive.evaluate(0.7).energy == 0.0);
    const double s = 0.2;
    CHECK(passive.evaluate(1.2).stress ==
          Approx(sigma_max * 0.05 * (std::exp(6.6 * s) - 1.0 - 6.6 * s)).epsilon(1e-13));
    const double e = std::exp(6.6 * 0.4);
    const double P3 = 0.05 * 6.6 * (e - 1.0);
    const double P4 = 0.05 * (e * (1.0 - 6.6 * 1.4) + 6.6 - 1.0);
    for (double lambda : {1.5, 2.0, 3.0}) {
        CAPTURE(lambda);
        CHECK(passive.evaluate(lambda).stress == Approx(sigma_max * (P3 * lambda + P4)).epsilon(1e-13));
        CHECK(passive.evaluate(lambda).stiffness == Approx(sigma_max * P3).epsilon(1e-13));
    }
}

TEST_CASE("muscle fiber curves: lambda_opt scales the curves", "[energies][muscle]")
{
    // f(λ; λ_opt) = (σ_max/λ_opt) g(λ/λ_opt): the fiber stress λ f peaks at σ_max
    // at λ = λ_opt, and the passive slack moves to λ_opt.
    const double sigma_max = 3e5, lambda_opt = 1.25;
    const ActiveFiberCurve unit(sigma_max, 1.0), active(sigma_max, lambda_opt);
    const PassiveFiberCurve unit_passive(sigma_max, 0.05, 6.6, 1.0, 1.4 / lambda_opt);
    const PassiveFiberCurve passive(sigma_max, 0.05, 6.6, lambda_opt, 1.4);
    CHECK(lambda_opt * active.evaluate(lambda_opt).stress == Approx(sigma_max).epsilon(1e-15));
    CHECK(passive.evaluate(lambda_opt).stress == 0.0);
    for (double x : {0.3, 0.5, 0.7, 1.0, 1.1, 1.45, 1.7}) {
        CAPTURE(x);
        CHECK(active.evaluate(lambda_opt * x).stress == Approx(unit.evaluate(x).stress / lambda_opt).margin(1e-9));
        CHECK(active.evaluate(lambda_opt * x).stiffness ==
              Approx(unit.evaluate(x).stiffness / (lambda_opt * lambda_opt)).margin(1e-9));
        CHECK(passive.evaluate(lambda_opt * x).stress ==
              Approx(unit_passive.evaluate(x).stress / lambda_opt).epsilon(1e-13).margin(1e-9));
    }
    CHECK(active.evaluate(1.0).energy == 0.0);
    CHECK(passive.evaluate(1.0).energy == 0.0);
}

TEST_CASE("muscle fiber curves: value and slope continuous at every break point", "[energies][muscle]")
{
    // One-sided differences over δ = 1e-7 on each side of a break point b:
    // their error is δ|f''|/2 ≤ 1e-7·(30σ_max) ≈ 3e-6σ_max on these curves
    // (|f''| ≤ 2·(25/3)σ_max/λ_opt³ active, P1P2²e^{P2(x*−1)}σ_max passive).
    // A C⁰ kink of the published curves would show as a slope jump of order
    // 0.1σ_max (Blemker's active: 0.4σ_max; passive at slack: P1P2σ_max = 0.33σ_max).
    const double delta = 1e-7;
    auto check_breaks = [&](const auto& curve, const auto& breaks, double scale) {
        for (double b : breaks) {
            CAPTURE(b);
            const FiberCurvePoint left = curve.evaluate(b - delta), at = curve.evaluate(b),
                                  right = curve.evaluate(b + delta);
            // value: |f(b ± δ) − f(b)| ≤ δ|f'| ≤ 1e-7·10σ_max
            CHECK(std::abs(right.stress - at.stress) < 1e-5 * scale);
            CHECK(std::abs(at.stress - left.stress) < 1e-5 * scale);
            const double slope_left = (at.stress - left.stress) / delta;
            const double slope_right = (right.stress - at.stress) / delta;
            CHECK(std::abs(slope_right - slope_left) < 1e-4 * scale);
            CHECK(std::abs(left.stiffness - slope_left) < 1e-4 * scale);
            CHECK(std::abs(right.stiffness - slope_right) < 1e-4 * scale);
            CHECK(std::abs(right.stiffness - left.stiffness) < 1e-4 * scale);
            // energy: Φ' = f on both sides, Φ continuous
            CHECK(std::abs((at.energy - left.energy) / delta - at.stress) < 1e-4 * scale);
            CHECK(std::abs((right.energy - at.energy) / delta - at.stress) < 1e-4 * scale);
        }
    };
    for (const CurveParameters& p : kParameterSets) {
        CAPTURE(p.sigma_max, p.lambda_opt, p.P1, p.P2, p.lambda_star);
        const ActiveFiberCurve active(p.sigma_max, p.lambda_opt);
        const PassiveFiberCurve passive(p.sigma_max, p.P1, p.P2, p.lambda_opt, p.lambda_star);
        check_breaks(active, active.break_points(), p.sigma_max);
        check_breaks(passive, passive.break_points(), p.sigma_max);
    }
}

TEST_CASE("muscle fiber curves: energy and stress and stiffness agree with differences", "[energies][muscle]")
{
    // Central differences with h = 1e-6: truncation h²|f'''|/6 (0 inside the
    // quadratic pieces, ≲ 1e-12·P1P2³e^{P2(x*−1)}σ_max passive) and rounding
    // 1e-16|Φ|/h ≲ 1e-10σ_max·(λ range): 1e-8σ_max for Φ', 1e-7σ_max for f'.
    const double h = 1e-6;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> stretch(0.2, 3.0);
    for (const CurveParameters& p : kParameterSets) {
        const ActiveFiberCurve active(p.sigma_max, p.lambda_opt);
        const PassiveFiberCurve passive(p.sigma_max, p.P1, p.P2, p.lambda_opt, p.lambda_star);
        int checked = 0;
        for (int trial = 0; trial < 1000; ++trial) {
            const double lambda = stretch(rng);
            CAPTURE(p.lambda_opt, lambda);
            if (near_any(active.break_points(), lambda, 1e-4) ||
                near_any(passive.break_points(), lambda, 1e-4))
                continue;
            for (int curve = 0; curve < 2; ++curve) {
                auto at_lambda = [&](double l) { return curve == 0 ? active.evaluate(l) : passive.evaluate(l); };
                const FiberCurvePoint at = at_lambda(lambda), plus = at_lambda(lambda + h), minus = at_lambda(lambda - h);
                CHECK(std::abs((plus.energy - minus.energy) / (2 * h) - at.stress) < 1e-8 * p.sigma_max);
                CHECK(std::abs((plus.stress - minus.stress) / (2 * h) - at.stiffness) < 1e-7 * p.sigma_max);
                CHECK(at.stress >= 0.0);
            }
            ++checked;
        }
        CHECK(checked > 990);
    }
}
