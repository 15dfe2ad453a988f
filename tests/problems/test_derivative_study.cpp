// The derivative checks must tell a kink or round-off noise from a wrong
// derivative: right derivatives at a kink or under noise pass (and say how
// they were settled), the same functions with a wrong entry still fail.
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/taylor_test.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

namespace {

using sinew::Nlp;

/// f = k·max(0, x₀) + max(0, x₀)² + x₀x₁ + x₁⁴ + C, n = 2, unconstrained,
/// started at x₀ = 0: f' jumps by k there (a kink of f), f'' by 2 (a kink of
/// ∇f). The analytic derivatives take the right-hand branch at x₀ = 0,
/// ∂f/∂x₀ = k + x₁ and ∂²f/∂x₀² = 2, unless `wrong_gradient` or
/// `wrong_hessian` replace them with values neither side has. C, constant,
/// only adds round-off to f.
class KinkedProblem : public Nlp {
public:
    KinkedProblem(double k, double C, bool wrong_gradient = false, bool wrong_hessian = false)
        : k_(k), C_(C), wrong_gradient_(wrong_gradient), wrong_hessian_(wrong_hessian)
    {
        hessian_.add(0, 0);
        hessian_.add(1, 0);
        hessian_.add(1, 1);
    }
    std::string name() const override { return "kinked"; }
    int num_variables() const override { return 2; }
    int num_constraints() const override { return 0; }
    void constraint_bounds(VectorRef, VectorRef) const override {}
    Vector starting_point() const override { return Eigen::Vector2d(0.0, 0.7); }
    double objective(ConstVectorRef x) override
    {
        const double p = std::max(0.0, x[0]);
        return k_ * p + p * p + x[0] * x[1] + std::pow(x[1], 4) + C_;
    }
    void gradient(ConstVectorRef x, VectorRef g) override
    {
        const bool right = x[0] >= 0.0;
        g[0] = (right ? k_ : 0.0) + 2.0 * std::max(0.0, x[0]) + x[1];
        if (wrong_gradient_ && x[0] == 0.0)
            g[0] = 0.5 * k_ + 0.3 + x[1];  // off both branches (k + x₁ and x₁)
        g[1] = x[0] + 4.0 * std::pow(x[1], 3);
    }
    void constraints(ConstVectorRef, VectorRef) override {}
    const sinew::SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef, VectorRef) override {}
    const sinew::SparsityPattern& hessian_pattern() const override { return hessian_; }
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef v) override
    {
        v[0] = sigma * (x[0] >= 0.0 ? 2.0 : 0.0) + (wrong_hessian_ ? 0.5 : 0.0);  // 2.5 or 0.5: neither branch
        v[1] = sigma * 1.0;
        v[2] = sigma * 12.0 * x[1] * x[1];
    }

private:
    double k_, C_;
    bool wrong_gradient_, wrong_hessian_;
    sinew::SparsityPattern jacobian_, hessian_;
};

} // namespace

TEST_CASE("entrywise check settles a kink by a one-sided difference and still fails a wrong entry there")
{
    KinkedProblem right(1.0, 0.0);
    const auto report = sinew::check_derivatives(right, right.starting_point());
    CAPTURE(report.to_text());
    CHECK(report.passed(1e-5));
    CHECK(report.gradient.at_kink == 1);  // ∂f/∂x₀: f' jumps at x₀ = 0
    CHECK(report.hessian.at_kink >= 1);   // ∂²f/∂x₀²: ∇f jumps there too
    CHECK(report.to_text().find("at a kink (one side agrees)") != std::string::npos);

    KinkedProblem wrong_gradient(1.0, 0.0, true);
    const auto bad_gradient = sinew::check_derivatives(wrong_gradient, wrong_gradient.starting_point());
    CAPTURE(bad_gradient.to_text());
    CHECK_FALSE(bad_gradient.passed(1e-5));
    CHECK(bad_gradient.gradient.row == 0);
    CHECK(bad_gradient.gradient.worst_relative_error > 0.1);

    KinkedProblem wrong_hessian(1.0, 0.0, false, true);
    const auto bad_hessian = sinew::check_derivatives(wrong_hessian, wrong_hessian.starting_point());
    CAPTURE(bad_hessian.to_text());
    CHECK_FALSE(bad_hessian.passed(1e-5));
    CHECK(bad_hessian.hessian.row == 0);
    CHECK(bad_hessian.hessian.col == 0);
}

TEST_CASE("entrywise check settles a curvature jump where both one-sided differences agree")
{
    // k = 0: f is C¹ at x₀ = 0 and only f'' jumps, which costs the central
    // difference of f its second order (an O(h) error) but not the
    // one-sided differences on either side.
    KinkedProblem right(0.0, 0.0);
    const auto report = sinew::check_derivatives(right, right.starting_point(), {1e-3, 1.0, 7, 1e-5});
    CAPTURE(report.to_text());
    CHECK(report.passed(1e-5));
    CHECK(report.gradient.both_sides_agree == 1);
}

TEST_CASE("entrywise check settles round-off noise it can resolve and no more")
{
    // Away from the kink, ∂f/∂x₀ = x₁ = 1e-6 lies below the floor (1e-3 of
    // |∂f/∂x₁| ≈ 0.7). With C = 1e4, f carries round-off of about 5e-13 and
    // its central differences about 5e-7: the entry fails plainly against
    // the floor (7e-4 relative), and passes within the noise, which is far
    // below a tenth of the floor.
    const Eigen::Vector2d x(-0.7, 1e-6);
    KinkedProblem noisy(1.0, 1e4);
    const auto report = sinew::check_derivatives(noisy, x, {1e-6, 1.0, 7, 1e-5});
    CAPTURE(report.to_text());
    CHECK(report.passed(1e-5));
    CHECK(report.gradient.within_noise == 1);

    // With C = 1e12 the noise (about 40 in the differences) is far above a
    // tenth of the floor: it settles nothing, and the check fails.
    KinkedProblem hopeless(1.0, 1e12);
    const auto blind = sinew::check_derivatives(hopeless, x, {1e-6, 1.0, 7, 1e-5});
    CAPTURE(blind.to_text());
    CHECK_FALSE(blind.passed(1e-5));
}

TEST_CASE("Taylor test calls a point on a kink a kink and passes when the other points pass")
{
    KinkedProblem right(1.0, 0.0);
    sinew::TaylorOptions options;
    options.directions = 4;  // some directions cross x₀ = 0 to the left
    const auto report = sinew::taylor_test(right, right.starting_point(), options);
    CAPTURE(report.to_text());
    CHECK(report.passed());
    CHECK(report.gradient.worst.verdict == sinew::TaylorVerdict::kink);
    CHECK(report.gradient.point == 0);
    CHECK(report.gradient.points_passed == 2);

    // At the kink alone (one point), nothing passes: not a pass.
    options.points = 1;
    const auto alone = sinew::taylor_test(right, right.starting_point(), options);
    CAPTURE(alone.to_text());
    CHECK_FALSE(alone.passed());

    // A wrong Hessian fails off the kink too.
    KinkedProblem wrong_hessian(1.0, 0.0, false, true);
    options.points = 3;
    const auto bad = sinew::taylor_test(wrong_hessian, wrong_hessian.starting_point(), options);
    CAPTURE(bad.to_text());
    CHECK_FALSE(bad.passed());
    CHECK(bad.hessian.worst.verdict == sinew::TaylorVerdict::failed);
}
