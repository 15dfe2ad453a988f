// The derivative checker must find, and name, a wrong derivative entry.
#include "sinew/core/input_error.hpp"
#include "sinew/problems/derivative_check.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace {

using sinew::Nlp;

/// f = Σ xᵢ⁴ + x₀x₁x₂,  c₀ = x₀² + x₁x₂ (equality),  n = 3, m = 1.
/// `wrong_row`, `wrong_col` put a deliberate error into one Hessian value;
/// `scale` multiplies f and c (and so every derivative).
class SmallProblem : public Nlp {
public:
    SmallProblem(int wrong_row = -1, int wrong_col = -1, bool drop_entry = false, double scale = 1.0)
        : wrong_row_(wrong_row), wrong_col_(wrong_col), scale_(scale)
    {
        jacobian_.add(0, 0);
        jacobian_.add(0, 1);
        jacobian_.add(0, 2);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j <= i; ++j)
                if (!(drop_entry && i == 2 && j == 0))
                    hessian_.add(i, j);
    }
    std::string name() const override { return "small"; }
    int num_variables() const override { return 3; }
    int num_constraints() const override { return 1; }
    void constraint_bounds(VectorRef l, VectorRef u) const override { l[0] = u[0] = scale_; }
    Vector starting_point() const override { return Vector::LinSpaced(3, 0.3, 1.1); }
    double objective(ConstVectorRef x) override { return scale_ * (x.array().pow(4).sum() + x[0] * x[1] * x[2]); }
    void gradient(ConstVectorRef x, VectorRef g) override
    {
        g = 4 * x.array().cube();
        g[0] += x[1] * x[2];
        g[1] += x[0] * x[2];
        g[2] += x[0] * x[1];
        g *= scale_;
    }
    void constraints(ConstVectorRef x, VectorRef c) override { c[0] = scale_ * (x[0] * x[0] + x[1] * x[2]); }
    const sinew::SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef v) override
    {
        v[0] = scale_ * 2 * x[0];
        v[1] = scale_ * x[2];
        v[2] = scale_ * x[1];
    }
    const sinew::SparsityPattern& hessian_pattern() const override { return hessian_; }
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef v) override
    {
        Eigen::Matrix3d H = sigma * 12 * x.array().square().matrix().asDiagonal().toDenseMatrix();
        H(1, 0) = sigma * x[2];
        H(2, 0) = sigma * x[1];
        H(2, 1) = sigma * x[0];
        H(0, 0) += lambda[0] * 2;
        H(2, 1) += lambda[0];
        for (int k = 0; k < hessian_.nonzeros(); ++k) {
            const int i = hessian_.rows[k], j = hessian_.cols[k];
            v[k] = scale_ * (H(i, j) + ((i == wrong_row_ && j == wrong_col_) ? 0.05 : 0.0));
        }
    }

private:
    int wrong_row_, wrong_col_;
    double scale_;
    sinew::SparsityPattern jacobian_, hessian_;
};

} // namespace

TEST_CASE("derivative checker passes exact derivatives")
{
    SmallProblem problem;
    const auto report = sinew::check_derivatives(problem, problem.starting_point());
    CAPTURE(report.to_text());
    CHECK(report.gradient.entries_compared == 3);
    CHECK(report.jacobian.entries_compared == 3);
    CHECK(report.hessian.entries_compared == 6);
    CHECK(report.passed(1e-7));
}

TEST_CASE("derivative checker names one deliberately wrong Hessian entry")
{
    const auto [row, col] = GENERATE(std::pair{2, 1}, std::pair{0, 0}, std::pair{1, 0});
    SmallProblem problem(row, col);
    const auto report = sinew::check_derivatives(problem, problem.starting_point());
    CAPTURE(row, col, report.to_text());
    CHECK_FALSE(report.passed(1e-4));
    CHECK(report.hessian.row == row);
    CHECK(report.hessian.col == col);
    CHECK(report.hessian.analytic - report.hessian.finite_difference == Approx(0.05).epsilon(1e-4));
    CHECK(report.gradient.worst_relative_error < 1e-7);
    CHECK(report.to_text().find("(" + std::to_string(row) + ", " + std::to_string(col) + ")") != std::string::npos);
}

TEST_CASE("derivative checker finds a Hessian entry missing from the pattern")
{
    SmallProblem problem(-1, -1, /*drop_entry=*/true);
    const auto report = sinew::check_derivatives(problem, problem.starting_point());
    CAPTURE(report.to_text());
    CHECK_FALSE(report.passed(1e-4));
    CHECK(report.hessian.row == 2);
    CHECK(report.hessian.col == 0);
}

TEST_CASE("derivative checker errors are relative also for derivatives far below 1")
{
    // The same wrong entry (5% of the entry's own scale) with every derivative
    // scaled by 1e-6: an absolute error of 5e-8 that |a - fd| / max(1, |fd|)
    // passed at tolerance 1e-4, and a relative one that must fail.
    SmallProblem wrong(2, 1, false, 1e-6);
    const auto report = sinew::check_derivatives(wrong, wrong.starting_point());
    CAPTURE(report.to_text());
    CHECK_FALSE(report.passed(1e-4));
    CHECK(report.hessian.row == 2);
    CHECK(report.hessian.col == 1);
    CHECK(report.hessian.error_floor > 0.0);
    CHECK(report.hessian.error_floor < 1e-7);  // a thousandth of the largest entry, ~1.5e-5
    SmallProblem right(-1, -1, false, 1e-6);
    const auto exact = sinew::check_derivatives(right, right.starting_point());
    CAPTURE(exact.to_text());
    CHECK(exact.passed(1e-6));
}

TEST_CASE("derivative checker refuses a zero, negative or non-finite step")
{
    SmallProblem problem;
    for (const double step : {0.0, -1e-6, std::nan(""), HUGE_VAL}) {
        CAPTURE(step);
        sinew::DerivativeCheckOptions options;
        options.step = step;
        CHECK_THROWS_AS(sinew::check_derivatives(problem, problem.starting_point(), options), sinew::InputError);
    }
}
