// Inexact Newton on a reused factorization (issue 14): preconditioned CG's
// three ways to stop, why a reuse was refused, the Eisenstat-Walker forcing terms, and projected
// Newton with reuse on against reuse off.
#include "sinew/core/input_error.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/solvers/linear/linear_solver.hpp"
#include "sinew/solvers/newton/factorization_reuse.hpp"
#include "sinew/solvers/newton/forcing_term.hpp"
#include "sinew/solvers/newton/preconditioned_cg.hpp"
#include "sinew/solvers/newton/regularized_factorization.hpp"
#include "sinew/solvers/solver.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace sinew;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

/// A random symmetric positive definite n × n matrix with eigenvalues in [1, condition].
MatrixXd random_spd(int n, double condition, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    MatrixXd G(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            G(i, j) = normal(rng);
    const Eigen::HouseholderQR<MatrixXd> qr(G);
    const MatrixXd Q = qr.householderQ();
    VectorXd eigenvalues(n);
    for (int i = 0; i < n; ++i)
        eigenvalues[i] = std::pow(condition, static_cast<double>(i) / (n - 1));
    return Q * eigenvalues.asDiagonal() * Q.transpose();
}

VectorXd random_vector(int n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    VectorXd v(n);
    for (int i = 0; i < n; ++i)
        v[i] = normal(rng);
    return v;
}

/// The full lower-triangle pattern of an n × n matrix, given the values of dense ones.
SparsityPattern dense_lower_pattern(int n)
{
    SparsityPattern pattern;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j <= i; ++j)
            pattern.add(i, j);
    return pattern;
}

/// M's entries at the pattern's positions, in its order.
VectorXd lower_values(const SparsityPattern& pattern, const MatrixXd& M)
{
    VectorXd values(pattern.nonzeros());
    for (int k = 0; k < pattern.nonzeros(); ++k)
        values[k] = M(pattern.rows[k], pattern.cols[k]);
    return values;
}

/// A 30 × 30 matrix A (dense lower pattern) starting as I, a CHOLMOD
/// factorization, and reuse whose CG may take 3 iterations.
struct SmallReuse {
    static constexpr int n = 30;
    SmallReuse() { fill(MatrixXd::Identity(n, n)); }
    void fill(const MatrixXd& M) { A.fill(lower_values(pattern, M)); }
    /// Factorizes A and keeps it as the preconditioner of later solves.
    void factorize_and_keep(const VectorXd& b)
    {
        double shift = 0.0;
        VectorXd d;
        REQUIRE(factorization.solve_shifted(A, shift, 1.0, b, d));
        reuse.keep();
    }

    const SparsityPattern pattern = dense_lower_pattern(n);
    PatternMatrix A{pattern, n};
    RegularizedFactorization factorization{make_linear_solver("cholmod")};
    FactorizationReuse reuse{factorization, ReuseSettings{true, 3}};
};

} // namespace

TEST_CASE("preconditioned CG reaches the relative residual it is asked for")
{
    const int n = 40;
    const MatrixXd A = random_spd(n, 1e4, 1);
    const VectorXd b = random_vector(n, 2);
    auto multiply = [&](const VectorXd& v, VectorXd& Av) { Av = A * v; };
    auto identity = [](const VectorXd& r, VectorXd& z) {
        z = r;
        return true;
    };
    for (double eta : {0.5, 1e-3, 1e-10}) {
        CAPTURE(eta);
        VectorXd d;
        const CgOutcome outcome = preconditioned_cg(multiply, identity, b, eta, 1000, d);
        REQUIRE(outcome.status == CgStatus::converged);
        const double residual = (b - A * d).norm() / b.norm();
        CHECK(residual <= eta * (1.0 + 1e-6));
        // The recurrence r ← r − αAp drifts from b − Ad by round-off, about
        // ε·κ(A) = 2e-12 of ‖b‖ here: visible only at the smallest η.
        CHECK(outcome.relative_residual == Approx(residual).epsilon(1e-4).margin(1e-11));
        // dᵀ(Ad − b) = 0 in exact arithmetic, so Newton's predicted decrease
        // −½∇fᵀd is the model's ½dᵀAd; round-off (CG's lost orthogonality
        // over tens of iterations at condition 1e4) leaves a small fraction.
        CHECK(std::abs(d.dot(A * d - b)) <= 1e-3 * d.dot(A * d));
    }
}

TEST_CASE("preconditioned CG with a nearby factorization as preconditioner needs few iterations")
{
    const int n = 60;
    const MatrixXd A = random_spd(n, 1e6, 3);
    const MatrixXd nearby = A + 1e-3 * random_spd(n, 10.0, 4);  // the matrix factorized "earlier"
    const Eigen::LLT<MatrixXd> factors(nearby);
    const VectorXd b = random_vector(n, 5);
    auto multiply = [&](const VectorXd& v, VectorXd& Av) { Av = A * v; };
    auto factorized = [&](const VectorXd& r, VectorXd& z) {
        z = factors.solve(r);
        return true;
    };
    auto identity = [](const VectorXd& r, VectorXd& z) {
        z = r;
        return true;
    };
    VectorXd d;
    const CgOutcome with_factors = preconditioned_cg(multiply, factorized, b, 1e-10, 1000, d);
    const CgOutcome without = preconditioned_cg(multiply, identity, b, 1e-10, 1000, d);
    CAPTURE(with_factors.iterations, without.iterations);
    REQUIRE(with_factors.status == CgStatus::converged);
    CHECK(with_factors.iterations <= 6);
    CHECK(without.iterations > 5 * with_factors.iterations);
}

TEST_CASE("preconditioned CG stops on non-positive curvature, at its limit, and on a failed preconditioner")
{
    auto identity = [](const VectorXd& r, VectorXd& z) {
        z = r;
        return true;
    };
    VectorXd d;
    SECTION("indefinite")
    {
        const MatrixXd A = Eigen::Vector3d(1.0, -2.0, 3.0).asDiagonal();
        auto multiply = [&](const VectorXd& v, VectorXd& Av) { Av = A * v; };
        const CgOutcome outcome = preconditioned_cg(multiply, identity, VectorXd::Ones(3), 1e-12, 100, d);
        CHECK(outcome.status == CgStatus::negative_curvature);
    }
    SECTION("iteration limit")
    {
        const MatrixXd A = random_spd(30, 1e8, 6);
        auto multiply = [&](const VectorXd& v, VectorXd& Av) { Av = A * v; };
        const CgOutcome outcome = preconditioned_cg(multiply, identity, random_vector(30, 7), 1e-12, 3, d);
        CHECK(outcome.status == CgStatus::iteration_limit);
        CHECK(outcome.iterations == 3);
        CHECK(outcome.relative_residual > 1e-12);
    }
    SECTION("failed preconditioner")
    {
        auto multiply = [](const VectorXd& v, VectorXd& Av) { Av = v; };
        auto failing = [](const VectorXd&, VectorXd&) { return false; };
        const CgOutcome outcome = preconditioned_cg(multiply, failing, VectorXd::Ones(4), 1e-8, 10, d);
        CHECK(outcome.status == CgStatus::preconditioner_failed);
    }
    SECTION("zero right-hand side")
    {
        auto multiply = [](const VectorXd& v, VectorXd& Av) { Av = v; };
        const CgOutcome outcome = preconditioned_cg(multiply, identity, VectorXd::Zero(4), 1e-8, 10, d);
        CHECK(outcome.status == CgStatus::converged);
        CHECK(outcome.iterations == 0);
        CHECK(d.isZero(0.0));
    }
}

TEST_CASE("Eisenstat-Walker forcing terms: loose at first, safeguarded, O(gradient) near the solution")
{
    ForcingTerm forcing;
    // η₀ = η_max
    CHECK(forcing.next(1.0) == ForcingTerm::eta_max);
    // ‖g‖ 1 → 0.95: γ·0.95² ≈ 0.81 above η_max = 0.5
    CHECK(forcing.next(0.95) == ForcingTerm::eta_max);
    // 0.95 → 0.3: γ·(0.3/0.95)² ≈ 0.090, but the safeguard γ·0.5² = 0.225 > 0.1 holds it up
    CHECK(forcing.next(0.3) == Approx(0.225));
    // 0.3 → 0.03: γ·0.1² = 0.009; the safeguard γ·0.225² ≈ 0.046 < 0.1 is off; ‖g‖/‖g₀‖ = 0.03 is above
    CHECK(forcing.next(0.03) == Approx(0.009));
    // 0.03 → 0.02: γ·(2/3)² = 0.4, capped by ‖g‖/‖g₀‖ = 0.02
    CHECK(forcing.next(0.02) == Approx(0.02));
}

TEST_CASE_METHOD(SmallReuse, "a refused reuse says whether CG found the matrix indefinite or only ran out of iterations")
{
    const VectorXd b = random_vector(n, 5);
    VectorXd d;
    CHECK_FALSE(reuse.solve(A.matrix(), 0.0, b, 0.1, d));  // nothing kept yet
    CHECK_FALSE(reuse.found_indefinite());
    factorize_and_keep(b);
    // Preconditioned by I: an SPD matrix with spread eigenvalues needs more than 3 iterations.
    fill(random_spd(n, 1e4, 6));
    CHECK_FALSE(reuse.solve(A.matrix(), 0.0, b, 1e-8, d));
    CHECK_FALSE(reuse.found_indefinite());
    // An indefinite one: −I meets negative curvature in the first iteration.
    fill(-MatrixXd::Identity(n, n));
    CHECK_FALSE(reuse.solve(A.matrix(), 0.0, b, 1e-8, d));
    CHECK(reuse.found_indefinite());
    // Shifted past its spectrum it is I again: one iteration.
    CHECK(reuse.solve(A.matrix(), 2.0, b, 1e-8, d));
    CHECK_FALSE(reuse.found_indefinite());
    CHECK((d - b).norm() < 1e-10 * b.norm());
    reuse.forget();
    CHECK_FALSE(reuse.solve(A.matrix(), 2.0, b, 1e-8, d));
}

TEST_CASE_METHOD(SmallReuse, "refusals for the iteration limit in a row back off and a delivered step ends the backoff")
{
    const VectorXd b = random_vector(n, 7);
    VectorXd d;
    factorize_and_keep(b);
    // Preconditioned by I, this SPD matrix needs more than 3 CG iterations:
    // every attempt is refused. Record which calls ran CG.
    fill(random_spd(n, 1e4, 8));
    std::vector<int> attempted;
    for (int call = 0; call < 40; ++call) {
        const int before = reuse.cg_iterations();
        CHECK_FALSE(reuse.solve(A.matrix(), 0.0, b, 1e-8, d));
        CHECK_FALSE(reuse.found_indefinite());
        if (reuse.cg_iterations() > before)
            attempted.push_back(call);
    }
    // Skips of 0, 0, 0, 1, 3, 7, 15, 15 calls after the 1st to 8th refusal.
    CHECK(attempted == std::vector<int>{0, 1, 2, 3, 5, 9, 17, 33});
    CHECK(reuse.refused_steps() == 8);
    CHECK(reuse.skipped_steps() == 32);
    // The 15 calls skipped after the 8th refusal run out; I is solved by CG
    // in one iteration, and that ends the backoff: three refusals follow
    // that skip nothing.
    for (int call = 40; call < 49; ++call)
        CHECK_FALSE(reuse.solve(A.matrix(), 0.0, b, 1e-8, d));
    CHECK(reuse.refused_steps() == 8);
    fill(MatrixXd::Identity(n, n));
    CHECK(reuse.solve(A.matrix(), 0.0, b, 1e-8, d));
    fill(random_spd(n, 1e4, 8));
    for (int refusal = 1; refusal <= 4; ++refusal) {
        CHECK_FALSE(reuse.solve(A.matrix(), 0.0, b, 1e-8, d));
        CHECK(reuse.refused_steps() == 8 + refusal);
    }
    // The 4th refusal in a row skips the next call; a refusal for negative
    // curvature after it neither counts nor is skipped.
    fill(-MatrixXd::Identity(n, n));
    const int skipped = reuse.skipped_steps();
    CHECK_FALSE(reuse.solve(A.matrix(), 0.0, b, 1e-8, d));
    CHECK(reuse.skipped_steps() == skipped + 1);
    CHECK_FALSE(reuse.solve(A.matrix(), 0.0, b, 1e-8, d));
    CHECK(reuse.found_indefinite());
    CHECK_FALSE(reuse.solve(A.matrix(), 0.0, b, 1e-8, d));
    CHECK(reuse.found_indefinite());
    CHECK(reuse.skipped_steps() == skipped + 1);
}

TEST_CASE("projected Newton reusing factorizations reaches the same minimum with fewer factorizations")
{
    auto nlp = find_builtin_problem("rosenbrock1000").make();
    SolverOptions plain;
    plain.backend["reuse_factorization"] = "off";
    SolverOptions reused;
    reused.backend["reuse_factorization"] = "on";
    const Result off = solve(*nlp, "projected-newton", plain);
    const Result on = solve(*nlp, "projected-newton", reused);
    CAPTURE(off.message, on.message, off.iterations, on.iterations);
    REQUIRE(off.status == Status::converged);
    REQUIRE(on.status == Status::converged);
    CHECK(off.statistics.at("cg_iterations") == 0);
    CHECK(off.statistics.at("factorizations") >= off.iterations);
    CHECK(on.statistics.at("cg_iterations") > 0);
    CHECK(on.statistics.at("reused_factorization_steps") > 0);
    CHECK(on.statistics.at("factorizations") < on.iterations);
    CHECK((on.x - off.x).cwiseAbs().maxCoeff() < 1e-6);
}

TEST_CASE("reuse_factorization on needs a direct linear solver, auto follows the solver")
{
    auto nlp = find_builtin_problem("rosenbrock2").make();
    SolverOptions options;
    options.backend = {{"linear_solver", "pcg-jacobi"}, {"reuse_factorization", "on"}};
    CHECK_THROWS_AS(solve(*nlp, "projected-newton", options), InputError);
    options.backend["reuse_factorization"] = "auto";
    const Result r = solve(*nlp, "projected-newton", options);
    CHECK(r.status == Status::converged);
    CHECK(r.statistics.at("cg_iterations") == 0);
    options.backend = {{"max_cg_iterations", "0"}};
    CHECK_THROWS_AS(solve(*nlp, "projected-newton", options), InputError);
}

TEST_CASE("finishing_step off ends an inexact solve at its target, one iteration before the finishing step")
{
    auto nlp = find_builtin_problem("rosenbrock1000").make();
    SolverOptions finishing;
    finishing.backend["reuse_factorization"] = "on";
    SolverOptions at_target = finishing;
    at_target.backend["finishing_step"] = "off";
    const Result with = solve(*nlp, "projected-newton", finishing);
    const Result without = solve(*nlp, "projected-newton", at_target);
    CAPTURE(with.message, without.message, with.kkt_residual, without.kkt_residual);
    REQUIRE(with.status == Status::converged);
    REQUIRE(without.status == Status::converged);
    CHECK(without.iterations == with.iterations - 1);
    // Same iterates up to the target: the finishing step only moves x closer.
    CHECK(with.kkt_residual < without.kkt_residual);
    CHECK((with.x - without.x).cwiseAbs().maxCoeff() < 1e-6);
}
