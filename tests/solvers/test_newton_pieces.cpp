// The shared pieces of the Newton core (solvers/newton/): the line search's
// statuses, the KKT matrix and Schur complement against dense assembly, the
// inertia correction, and the active bounds.
#include "sinew/solvers/linear/linear_solver.hpp"
#include "sinew/solvers/newton/active_bounds.hpp"
#include "sinew/solvers/newton/kkt_matrix.hpp"
#include "sinew/solvers/newton/line_search.hpp"
#include "sinew/solvers/newton/regularized_factorization.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace sinew;

namespace {

/// A random lower-triangle pattern on n variables (diagonal included, one
/// entry repeated) and a random m × n Jacobian pattern with a repeated entry.
struct RandomPatterns {
    int n = 7, m = 3;
    SparsityPattern hessian, jacobian;
    Eigen::VectorXd h, j;
    explicit RandomPatterns(unsigned seed)
    {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (int i = 0; i < n; ++i)
            for (int k = 0; k <= i; ++k)
                if (i == k || u(rng) > 0.3)
                    hessian.add(i, k);
        hessian.add(n - 1, 0);  // repeated: summed
        for (int r = 0; r < m; ++r)
            for (int c = 0; c < n; ++c)
                if (u(rng) > 0.2)
                    jacobian.add(r, c);
        jacobian.add(0, 2);  // repeated: summed
        h.resize(hessian.nonzeros());
        j.resize(jacobian.nonzeros());
        for (Eigen::Index k = 0; k < h.size(); ++k)
            h[k] = u(rng);
        for (Eigen::Index k = 0; k < j.size(); ++k)
            j[k] = u(rng);
    }
    Eigen::MatrixXd dense_hessian() const
    {
        Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
        for (int k = 0; k < hessian.nonzeros(); ++k) {
            H(hessian.rows[k], hessian.cols[k]) += h[k];
            if (hessian.rows[k] != hessian.cols[k])
                H(hessian.cols[k], hessian.rows[k]) += h[k];
        }
        return H;
    }
    Eigen::MatrixXd dense_jacobian() const
    {
        Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, n);
        for (int k = 0; k < jacobian.nonzeros(); ++k)
            J(jacobian.rows[k], jacobian.cols[k]) += j[k];
        return J;
    }
};

/// The full symmetric matrix of a lower triangle.
Eigen::MatrixXd symmetric(const SparseMatrix& lower)
{
    const Eigen::MatrixXd L = Eigen::MatrixXd(lower).triangularView<Eigen::Lower>();
    return L + L.transpose() - Eigen::MatrixXd(L.diagonal().asDiagonal());
}

} // namespace

TEST_CASE("KKT matrix equals its dense assembly for both signs, with held variables", "[newton-pieces]")
{
    for (unsigned seed = 1; seed <= 3; ++seed) {
        const RandomPatterns p(seed);
        KktMatrix kkt(p.hessian, p.jacobian, p.n, p.m);
        for (const double sign : {1.0, -1.0}) {
            Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(p.n + p.m, p.n + p.m);
            expected.topLeftCorner(p.n, p.n) = p.dense_hessian() + 0.25 * Eigen::MatrixXd::Identity(p.n, p.n);
            expected.bottomLeftCorner(p.m, p.n) = sign * p.dense_jacobian();
            expected.topRightCorner(p.n, p.m) = sign * p.dense_jacobian().transpose();
            expected.bottomRightCorner(p.m, p.m) = -0.5 * Eigen::MatrixXd::Identity(p.m, p.m);
            CHECK((symmetric(kkt.fill(p.h, p.j, sign, 0.25, 0.5, {})) - expected).cwiseAbs().maxCoeff() <= 1e-15);

            // Variable 2 held: its row and column become the identity's.
            std::vector<char> fixed(static_cast<size_t>(p.n), 0);
            fixed[2] = 1;
            expected.row(2).setZero();
            expected.col(2).setZero();
            expected(2, 2) = 1.0;
            CHECK((symmetric(kkt.fill(p.h, p.j, sign, 0.25, 0.5, fixed)) - expected).cwiseAbs().maxCoeff() <= 1e-15);
        }
    }
}

TEST_CASE("Schur complement pattern gives H + kappa J^T J", "[newton-pieces]")
{
    for (unsigned seed = 4; seed <= 6; ++seed) {
        const RandomPatterns p(seed);
        SchurComplementPattern schur(p.hessian, p.jacobian, p.m);
        PatternMatrix S(schur.pattern(), p.n);
        Eigen::VectorXd values(schur.pattern().nonzeros());
        schur.fill(p.h, p.j, 3.0, values);
        S.fill(values);
        const Eigen::MatrixXd J = p.dense_jacobian();
        const Eigen::MatrixXd expected = p.dense_hessian() + 3.0 * J.transpose() * J;
        CHECK((symmetric(S.matrix()) - expected).cwiseAbs().maxCoeff() <= 1e-14);
    }
}

TEST_CASE("line search: Armijo, back-off on non-finite values, round-off acceptance, stalled and failed",
          "[newton-pieces]")
{
    const LineSearchSettings settings;
    // φ(α) = (α − 0.3)², φ(0) = 0.09, φ'(0) = −0.6: the full step fails Armijo, α = ½ passes.
    auto quadratic = [](double a) { return (a - 0.3) * (a - 0.3); };
    LineSearchOutcome out = backtracking_line_search(quadratic, 0.09, -0.6, settings, {});
    CHECK(out.status == LineSearchStatus::accepted);
    CHECK(out.alpha == 0.5);
    CHECK(out.full_step == Approx(0.49));

    // +∞ and NaN beyond α = 0.1 (an inverted element): backs off to α = 1/16.
    auto walled = [](double a) {
        if (a > 0.1)
            return a > 0.5 ? std::numeric_limits<double>::quiet_NaN() : std::numeric_limits<double>::infinity();
        return -a;
    };
    out = backtracking_line_search(walled, 0.0, -1.0, settings, {});
    CHECK(out.status == LineSearchStatus::accepted);
    CHECK(out.alpha == 0.0625);

    // φ a round-off above φ(0) everywhere: accepted when the second measure
    // improved, stalled otherwise (|φ(α) − φ(0)| ≤ 1e-14 after the last halving).
    auto flat = [](double) { return 1.0 + 1e-15; };
    out = backtracking_line_search(flat, 1.0, -1.0, settings, [](double) { return true; });
    CHECK(out.status == LineSearchStatus::accepted);
    CHECK(out.alpha == 1.0);
    out = backtracking_line_search(flat, 1.0, -1.0, settings, {});
    CHECK(out.status == LineSearchStatus::stalled);
    CHECK(out.backtracks == settings.max_backtracks);

    // φ increases along the direction: failed.
    out = backtracking_line_search([](double a) { return 1.0 + a; }, 1.0, -1.0, settings, {});
    CHECK(out.status == LineSearchStatus::failed);
}

TEST_CASE("a shifted SPD solve: one try reports indefinite, the shift loop raises the shift until Cholesky accepts",
          "[newton-pieces]")
{
    // A = diag(4, −0.5): indefinite; A + σI is positive definite for σ > 0.5.
    SparsityPattern pattern;
    pattern.add(0, 0);
    pattern.add(1, 1);
    PatternMatrix A(pattern, 2);
    const Eigen::Vector2d values(4.0, -0.5);
    const Eigen::Vector2d b(1.0, 1.0);
    Eigen::VectorXd x;
    RegularizedFactorization factorization(make_linear_solver("cholmod"));
    A.fill(values);
    CHECK(factorization.attempt_shifted(A, 0.0, b, x) == ShiftedSolve::indefinite);
    A.fill(values);
    REQUIRE(factorization.attempt_shifted(A, 1.0, b, x) == ShiftedSolve::solved);
    CHECK(x[0] == Approx(1.0 / 5.0));
    CHECK(x[1] == Approx(1.0 / 0.5));
    // The loop from σ = 0 with diagonal scale 4: 4e-8, 4e-7, …, 0.4 are
    // rejected, 4 is the first accepted.
    A.fill(values);
    double shift = 0.0;
    REQUIRE(factorization.solve_shifted(A, shift, 4.0, b, x));
    CHECK(shift == Approx(4.0));
    CHECK(factorization.attempts().size() == 1);
    CHECK(factorization.factorizations() == 2 + 10);
    CHECK(x[1] == Approx(1.0 / 3.5));
    CHECK(next_shift(0.0, 4.0) == Approx(4e-8));
    CHECK(next_shift(1e20, 1.0) == 0.0);
}

TEST_CASE("inertia correction regularizes an indefinite KKT matrix until it has n positive and m negative "
          "eigenvalues",
          "[newton-pieces]")
{
    // H = diag(1, −2): indefinite on J's null space (J = [1 0] leaves x₁ free).
    SparsityPattern hessian, jacobian;
    hessian.add(0, 0);
    hessian.add(1, 1);
    jacobian.add(0, 0);
    KktMatrix kkt(hessian, jacobian, 2, 1);
    const Eigen::Vector2d h(1.0, -2.0);
    const Eigen::VectorXd j = Eigen::VectorXd::Ones(1);
    RegularizedFactorization factorization(make_linear_solver("mumps-ldlt"));
    InertiaCorrection schedule;
    auto assemble = [&](double dw, double dc) -> const SparseMatrix& { return kkt.fill(h, j, 1.0, dw, dc, {}); };
    REQUIRE(factorization.factorize_with_inertia(assemble, 2, 1, schedule));
    // δw = 0 fails, then 1e-4 × 100^k until δw > 2: 1e-4, 1e-2, 1, 100.
    const auto& attempts = factorization.attempts();
    CHECK(attempts.size() == 5);
    CHECK(attempts.front().delta_w == 0.0);
    CHECK(attempts.back().delta_w == Approx(100.0));
    CHECK(attempts.back().inertia.positive == 2);
    CHECK(attempts.back().inertia.negative == 1);
    CHECK(schedule.last_delta_w == Approx(100.0));
    // The next iteration starts from ⅓ of it.
    REQUIRE(factorization.factorize_with_inertia(assemble, 2, 1, schedule));
    CHECK(factorization.attempts()[1].delta_w == Approx(100.0 / 3.0));
}

TEST_CASE("active bounds: projection, the eps-active set and bound multipliers", "[newton-pieces]")
{
    class Box final : public Nlp {
    public:
        std::string name() const override { return "box"; }
        int num_variables() const override { return 3; }
        void variable_bounds(VectorRef l, VectorRef u) const override
        {
            l << 0.0, -kInfinity, -1.0;
            u << 1.0, kInfinity, 1.0;
        }
        Vector starting_point() const override { return Vector::Zero(3); }
        double objective(ConstVectorRef) override { return 0.0; }
        void gradient(ConstVectorRef, VectorRef g) override { g.setZero(); }
        const SparsityPattern& hessian_pattern() const override { return pattern_; }

    protected:
        void hessian_values(ConstVectorRef, double, ConstVectorRef, VectorRef) override {}

    private:
        SparsityPattern pattern_;
    } box;
    ActiveBounds bounds(box);
    REQUIRE(bounds.any());
    Eigen::VectorXd x(3);
    x << 2.0, 5.0, -3.0;
    bounds.project(x);
    CHECK(x == Eigen::Vector3d(1.0, 5.0, -1.0));
    // ∇f pushes x₀ up (into its upper bound) and x₂ down (into its lower one): both held; x₁ is free.
    const Eigen::Vector3d g(-2.0, 1.0, 3.0);
    bounds.update(x, g);
    CHECK(bounds.fixed() == std::vector<char>{1, 0, 1});
    CHECK(bounds.projected_gradient_norm(x, g) == 1.0);
    Eigen::VectorXd z_lower, z_upper;
    bounds.multipliers(x, g, z_lower, z_upper);
    CHECK(z_lower == Eigen::Vector3d(0.0, 0.0, 3.0));
    CHECK(z_upper == Eigen::Vector3d(2.0, 0.0, 0.0));
}
