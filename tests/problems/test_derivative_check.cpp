// The derivative checker must find, and name, a wrong derivative entry, and
// the Taylor test must tell a right derivative (slope 2) from a wrong one (1).
#include "sinew/core/input_error.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/classic/hs071.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/taylor_test.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

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

namespace {

/// Hs071 with a constant 0.05 added to one entry of ∇f, J or ∇²L.
class WrongHs071 : public sinew::Hs071 {
public:
    enum class Part { gradient, jacobian, hessian };
    static constexpr double kError = 0.05;

    WrongHs071(Part part, int row, int col) : part_(part), row_(row), col_(col) {}
    std::string name() const override { return "wrong-hs071"; }
    void gradient(ConstVectorRef x, VectorRef g) override
    {
        Hs071::gradient(x, g);
        if (part_ == Part::gradient)
            g[row_] += kError;
    }
    void jacobian_values(ConstVectorRef x, VectorRef v) override
    {
        Hs071::jacobian_values(x, v);
        if (part_ == Part::jacobian)
            v[index_of(jacobian_pattern())] += kError;
    }
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef v) override
    {
        Hs071::hessian_values(x, sigma, lambda, v);
        if (part_ == Part::hessian)
            v[index_of(hessian_pattern())] += kError;
    }

private:
    int index_of(const sinew::SparsityPattern& pattern) const
    {
        for (int k = 0; k < pattern.nonzeros(); ++k)
            if (pattern.rows[k] == row_ && pattern.cols[k] == col_)
                return k;
        throw std::logic_error("no pattern entry (" + std::to_string(row_) + ", " + std::to_string(col_) + ")");
    }
    Part part_;
    int row_, col_;
};

/// f = Σ (i + 1)/2 · xᵢ² + quartic · Σ xᵢ⁴ with a diagonal Hessian, n free.
/// f is +inf farther than `radius` (∞-norm) from `centre` when radius > 0;
/// radius = 0 puts every point but the centre itself outside.
class Separable : public Nlp {
public:
    Separable(int n, double quartic, double radius = -1.0) : n_(n), quartic_(quartic), radius_(radius)
    {
        for (int i = 0; i < n; ++i)
            hessian_.add(i, i);
    }
    std::string name() const override { return "separable"; }
    int num_variables() const override { return n_; }
    Vector starting_point() const override { return Vector::LinSpaced(n_, -0.8, 0.9); }
    double objective(ConstVectorRef x) override
    {
        if (radius_ >= 0.0 && (x - starting_point()).cwiseAbs().maxCoeff() > radius_)
            return std::numeric_limits<double>::infinity();
        return 0.5 * weights().dot(x.cwiseAbs2()) + quartic_ * x.array().pow(4).sum();
    }
    void gradient(ConstVectorRef x, VectorRef g) override
    {
        g = weights().cwiseProduct(x) + 4 * quartic_ * x.cwiseProduct(x.cwiseAbs2());
    }
    const sinew::SparsityPattern& hessian_pattern() const override { return hessian_; }
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef v) override
    {
        v = sigma * (weights() + 12 * quartic_ * x.cwiseAbs2());
    }

private:
    Vector weights() const { return Vector::LinSpaced(n_, 1.0, n_); }
    int n_;
    double quartic_, radius_;
    sinew::SparsityPattern hessian_;
};

using sinew::TaylorVerdict;

} // namespace

TEST_CASE("Taylor test measures slope 2 on every classic problem")
{
    for (const sinew::BuiltinProblem& problem : sinew::builtin_problems()) {
        if (problem.suite != "classic")
            continue;
        const auto nlp = problem.make();
        const auto report = sinew::taylor_test(*nlp, nlp->starting_point());
        CAPTURE(problem.name, report.to_text());
        CHECK(report.passed());
        for (const sinew::TaylorResult* result : {&report.gradient, &report.jacobian, &report.hessian}) {
            if (!result->tested)
                continue;
            const sinew::TaylorSeries& worst = result->worst;
            CHECK((worst.verdict == TaylorVerdict::passed || worst.verdict == TaylorVerdict::exact));
            if (worst.verdict == TaylorVerdict::passed)
                CHECK(worst.slope == Approx(2.0).margin(0.1));
        }
        CHECK(report.jacobian.tested == (nlp->num_constraints() > 0));
    }
}

TEST_CASE("Taylor test fails a wrong gradient entry with slope 1")
{
    const int row = GENERATE(0, 1, 3);
    WrongHs071 problem(WrongHs071::Part::gradient, row, 0);
    const auto report = sinew::taylor_test(problem, problem.starting_point());
    CAPTURE(row, report.to_text(), report.series_text());
    CHECK_FALSE(report.passed());
    CHECK(report.gradient.worst.verdict == TaylorVerdict::failed);
    CHECK(report.gradient.worst.slope == Approx(1.0).margin(0.1));
    // A constant error in ∇f cancels in ∇L(x + hd) − ∇L(x): the Hessian passes.
    CHECK(report.hessian.passed());
    CHECK(report.jacobian.passed());
}

TEST_CASE("Taylor test fails a wrong Hessian entry with slope 1")
{
    const auto [row, col] = GENERATE(std::pair{0, 0}, std::pair{2, 1}, std::pair{3, 0});
    WrongHs071 problem(WrongHs071::Part::hessian, row, col);
    const auto report = sinew::taylor_test(problem, problem.starting_point());
    CAPTURE(row, col, report.to_text(), report.series_text());
    CHECK_FALSE(report.passed());
    CHECK(report.hessian.worst.verdict == TaylorVerdict::failed);
    CHECK(report.hessian.worst.slope == Approx(1.0).margin(0.1));
    CHECK(report.gradient.passed());
    CHECK(report.jacobian.passed());
}

TEST_CASE("Taylor test fails a wrong Jacobian entry with slope 1")
{
    WrongHs071 problem(WrongHs071::Part::jacobian, 1, 2);
    const auto report = sinew::taylor_test(problem, problem.starting_point());
    CAPTURE(report.to_text(), report.series_text());
    CHECK_FALSE(report.passed());
    CHECK(report.jacobian.worst.verdict == TaylorVerdict::failed);
    CHECK(report.jacobian.worst.slope == Approx(1.0).margin(0.1));
    CHECK(report.gradient.passed());
}

TEST_CASE("entrywise check names the wrong Hessian entry of the wrapped problem")
{
    const auto [row, col] = GENERATE(std::pair{0, 0}, std::pair{2, 1}, std::pair{3, 0});
    WrongHs071 problem(WrongHs071::Part::hessian, row, col);
    const auto report = sinew::check_derivatives(problem, problem.starting_point());
    CAPTURE(row, col, report.to_text());
    CHECK_FALSE(report.passed(1e-4));
    CHECK(report.hessian.row == row);
    CHECK(report.hessian.col == col);
    CHECK(report.hessian.analytic - report.hessian.finite_difference == Approx(WrongHs071::kError).epsilon(1e-4));
    CHECK(report.gradient.worst_relative_error < 1e-7);
}

TEST_CASE("Taylor test is relative also for derivatives far below 1")
{
    SmallProblem right(-1, -1, false, 1e-6);
    const auto exact = sinew::taylor_test(right, right.starting_point());
    CAPTURE(exact.to_text());
    CHECK(exact.passed());
    SmallProblem wrong(2, 1, false, 1e-6);
    const auto report = sinew::taylor_test(wrong, wrong.starting_point());
    CAPTURE(report.to_text());
    CHECK_FALSE(report.passed());
    CHECK(report.hessian.worst.verdict == TaylorVerdict::failed);
}

TEST_CASE("Taylor test passes a quadratic whose Hessian remainder is round-off")
{
    Separable quadratic(5, 0.0);
    const auto report = sinew::taylor_test(quadratic, quadratic.starting_point());
    CAPTURE(report.to_text(), report.series_text());
    CHECK(report.passed());
    CHECK(report.hessian.worst.verdict == TaylorVerdict::exact);
    CHECK(report.gradient.worst.verdict == TaylorVerdict::passed);
    CHECK_FALSE(report.jacobian.tested);
}

TEST_CASE("Taylor test shrinks the step and the perturbation where f is infinite")
{
    Separable problem(3, 1.0, /*radius=*/1e-4);
    const auto report = sinew::taylor_test(problem, problem.starting_point());
    CAPTURE(report.to_text(), report.series_text());
    CHECK(report.passed());
    // h0 = 1e-2 halved until x + h0 d is within 1e-4 of the centre (the
    // perturbed points lie up to 1e-3/16 from it, and ‖d‖∞ = 1).
    CHECK(report.gradient.worst.steps.front() < 2e-4);
    CHECK(report.gradient.worst.slope == Approx(2.0).margin(0.1));
}

TEST_CASE("Taylor test reports not measurable when f is infinite along every direction")
{
    Separable problem(3, 1.0, /*radius=*/0.0);
    const auto report = sinew::taylor_test(problem, problem.starting_point());
    CAPTURE(report.to_text());
    CHECK_FALSE(report.passed());
    CHECK(report.gradient.worst.verdict == TaylorVerdict::not_measurable);
    CHECK_FALSE(report.gradient.worst.note.empty());
    CHECK(report.to_text().find("not measurable") != std::string::npos);
}

TEST_CASE("Taylor test runs where the dense check refuses and names the memory it would need")
{
    Separable problem(5000, 0.1);
    CHECK(sinew::dense_check_bytes(5000, 0) == 900'300'000u);  // 2·5000²·8 + (5000·5001/2 + 5000)·40
    const std::string refusal = sinew::dense_check_refusal(problem);
    CAPTURE(refusal);
    CHECK(refusal.find("n = 5000") != std::string::npos);
    CHECK(refusal.find("900 MB") != std::string::npos);
    CHECK(refusal.find("4000 variables") != std::string::npos);
    CHECK_THROWS_WITH(sinew::check_derivatives(problem, problem.starting_point()),
                      Catch::Matchers::Contains("900 MB") && Catch::Matchers::Contains("n = 5000"));
    CHECK(sinew::dense_check_refusal(Separable(4000, 0.1)).empty());
    CHECK(sinew::dense_check_bytes(3000, 20000) > sinew::kMaxDenseCheckBytes);  // few variables, many constraints

    sinew::TaylorOptions options;
    options.points = 2;
    options.directions = 1;
    const auto report = sinew::taylor_test(problem, problem.starting_point(), options);
    CAPTURE(report.to_text());
    CHECK(report.passed());
    CHECK(report.hessian.worst.slope == Approx(2.0).margin(0.1));
}

TEST_CASE("Taylor test refuses invalid options and a non-finite point")
{
    SmallProblem problem;
    const Nlp::Vector x = problem.starting_point();
    auto with = [](auto change) {
        sinew::TaylorOptions options;
        change(options);
        return options;
    };
    using O = sinew::TaylorOptions;
    CHECK_THROWS_AS(sinew::taylor_test(problem, x, with([](O& o) { o.points = 0; })), sinew::InputError);
    CHECK_THROWS_AS(sinew::taylor_test(problem, x, with([](O& o) { o.directions = -1; })), sinew::InputError);
    CHECK_THROWS_AS(sinew::taylor_test(problem, x, with([](O& o) { o.steps = 2; })), sinew::InputError);
    CHECK_THROWS_AS(sinew::taylor_test(problem, x, with([](O& o) { o.initial_step = 0.0; })), sinew::InputError);
    CHECK_THROWS_AS(sinew::taylor_test(problem, x, with([](O& o) { o.perturbation = std::nan(""); })),
                    sinew::InputError);
    CHECK_THROWS_AS(sinew::taylor_test(problem, x, with([](O& o) { o.min_slope = HUGE_VAL; })), sinew::InputError);
    Nlp::Vector bad = x;
    bad[1] = std::nan("");
    CHECK_THROWS_AS(sinew::taylor_test(problem, bad), sinew::InputError);
    CHECK_THROWS_AS(sinew::taylor_test(problem, Nlp::Vector::Zero(2)), sinew::InputError);
}
