#include "sinew/core/input_error.hpp"
#include "sinew/solvers/linear/linear_solver.hpp"
#include "sinew/solvers/linear/petsc_solver.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using sinew::LinearSolver;
using sinew::LinearStatus;
using sinew::SparseMatrix;
using Triplets = std::vector<Eigen::Triplet<double>>;

/// The petsc-* solvers when this build has them.
std::vector<std::string> with_petsc(std::vector<std::string> names)
{
    if (sinew::petsc_linear_solvers_built()) {
        names.emplace_back("petsc-cg-gamg");
        names.emplace_back("petsc-cg-hypre");
    }
    return names;
}

const std::vector<std::string> symmetric_solver_names = with_petsc({"cholmod", "cholmod-ldlt", "pcg-jacobi", "pcg-ichol"});
const std::vector<std::string> iterative_solver_names = with_petsc({"pcg-jacobi", "pcg-ichol"});

double uniform(std::mt19937& rng, double low, double high)
{
    return std::uniform_real_distribution<double>(low, high)(rng);
}

/// Index of grid node (i, j, k) of an m×m×m grid.
int node(int m, int i, int j, int k) { return i + m * (j + m * k); }

/// A matrix on the 7-point stencil of an m×m×m grid (n = m³): for each pair of
/// neighbours i, j the entries a_ij = −w_ij, a_ji = −w_ji with w ∈ [1, 2]
/// (w_ij = w_ji when `symmetric`), and a_ii = Σ_j w_ij + d_i with d_i ∈ [0.1, 1].
/// Every row is strictly diagonally dominant with a positive diagonal, so the
/// matrix is nonsingular, and positive definite when symmetric (Gershgorin:
/// every eigenvalue ≥ min d_i ≥ 0.1). This is a grid Laplacian with random
/// edge weights plus a random positive diagonal; the pattern depends on m only.
/// `extra_couplings` adds that many symmetric couplings between random far
/// nodes (same dominance), which changes the pattern.
SparseMatrix grid_matrix(int m, bool symmetric, std::mt19937& rng, int extra_couplings = 0)
{
    const int n = m * m * m;
    Triplets entries;
    Eigen::VectorXd diagonal(n);
    for (int i = 0; i < n; ++i)
        diagonal[i] = uniform(rng, 0.1, 1.0);
    auto couple = [&](int a, int b) {
        const double w_ab = uniform(rng, 1.0, 2.0);
        const double w_ba = symmetric ? w_ab : uniform(rng, 1.0, 2.0);
        entries.emplace_back(a, b, -w_ab);
        entries.emplace_back(b, a, -w_ba);
        diagonal[a] += w_ab;
        diagonal[b] += w_ba;
    };
    for (int k = 0; k < m; ++k)
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                if (i + 1 < m)
                    couple(node(m, i, j, k), node(m, i + 1, j, k));
                if (j + 1 < m)
                    couple(node(m, i, j, k), node(m, i, j + 1, k));
                if (k + 1 < m)
                    couple(node(m, i, j, k), node(m, i, j, k + 1));
            }
    std::uniform_int_distribution<int> any_node(0, n - 1);
    for (int c = 0; c < extra_couplings; ++c) {
        const int a = any_node(rng);
        int b = any_node(rng);
        while (std::abs(a - b) <= m * m)  // not a grid neighbour, and not a duplicate of one
            b = any_node(rng);
        couple(a, b);
    }
    for (int i = 0; i < n; ++i)
        entries.emplace_back(i, i, diagonal[i]);
    SparseMatrix A(n, n);
    A.setFromTriplets(entries.begin(), entries.end());
    return A;
}

SparseMatrix lower_triangle(const SparseMatrix& A) { return A.triangularView<Eigen::Lower>(); }

/// A with every entry strictly above the diagonal replaced by a random value:
/// a solver that reads only the lower triangle cannot tell it from A.
SparseMatrix with_garbage_above_diagonal(const SparseMatrix& A, std::mt19937& rng)
{
    SparseMatrix garbage = A;
    for (int j = 0; j < garbage.outerSize(); ++j)
        for (SparseMatrix::InnerIterator entry(garbage, j); entry; ++entry)
            if (entry.row() < entry.col())
                entry.valueRef() = uniform(rng, -5.0, 5.0);
    return garbage;
}

Eigen::VectorXd random_vector(int n, std::mt19937& rng)
{
    Eigen::VectorXd v(n);
    for (int i = 0; i < n; ++i)
        v[i] = uniform(rng, -1.0, 1.0);
    return v;
}

/// ‖A x − b‖ / ‖b‖ with the full matrix A.
double relative_residual(const SparseMatrix& A, const Eigen::VectorXd& x, const Eigen::VectorXd& b)
{
    REQUIRE(x.size() == A.cols());
    REQUIRE(x.allFinite());
    REQUIRE(b.norm() > 0);
    return (A * x - b).norm() / b.norm();
}

/// Factorizes A, solves A x = b and returns x; both steps must succeed.
Eigen::VectorXd factorize_and_solve(LinearSolver& solver, const SparseMatrix& A, const Eigen::VectorXd& b)
{
    const LinearStatus factorized = solver.factorize(A);
    INFO(solver.last_message());
    REQUIRE(factorized == LinearStatus::ok);
    Eigen::VectorXd x;
    const LinearStatus solved = solver.solve(b, x);
    INFO(solver.last_message());
    REQUIRE(solved == LinearStatus::ok);
    return x;
}

bool is_iterative(const std::string& name) { return sinew::is_iterative_linear_solver(name); }

/// The quasi-definite KKT matrix [H Jᵀ; J −δI] with H a symmetric positive
/// definite grid matrix (n = m³) and J a random num_constraints × n matrix of
/// full row rank: row r has 10 in column r·stride and four entries in [−1, 1]
/// in columns that are not multiples of stride, so J restricted to the columns
/// r·stride is 10·I.
SparseMatrix kkt_matrix(int m, int num_constraints, double delta, std::mt19937& rng)
{
    const SparseMatrix H = grid_matrix(m, true, rng);
    const int n = static_cast<int>(H.rows());
    const int stride = n / num_constraints;
    Triplets entries;
    for (int j = 0; j < n; ++j)
        for (SparseMatrix::InnerIterator entry(H, j); entry; ++entry)
            entries.emplace_back(static_cast<int>(entry.row()), j, entry.value());
    std::uniform_int_distribution<int> any_column(0, n - 1);
    for (int r = 0; r < num_constraints; ++r) {
        std::vector<std::pair<int, double>> row = {{r * stride, 10.0}};
        while (row.size() < 5) {
            const int column = any_column(rng);
            bool fresh = column % stride != 0;
            for (const auto& taken : row)
                fresh = fresh && taken.first != column;
            if (fresh)
                row.emplace_back(column, uniform(rng, -1.0, 1.0));
        }
        for (const auto& [column, value] : row) {
            entries.emplace_back(n + r, column, value);  // J
            entries.emplace_back(column, n + r, value);  // Jᵀ
        }
        entries.emplace_back(n + r, n + r, -delta);
    }
    SparseMatrix K(n + num_constraints, n + num_constraints);
    K.setFromTriplets(entries.begin(), entries.end());
    return K;
}

} // namespace

TEST_CASE("linear solver names, factory and status names", "[linear]")
{
    const std::vector<std::string> expected =
        with_petsc({"cholmod", "cholmod-ldlt", "mumps-ldlt", "umfpack", "pcg-jacobi", "pcg-ichol"});
    REQUIRE(sinew::linear_solver_names() == expected);
    for (const std::string& name : expected)
        CHECK(sinew::make_linear_solver(name)->name() == name);

    CHECK(sinew::to_string(LinearStatus::ok) == "ok");
    CHECK(sinew::to_string(LinearStatus::not_positive_definite) == "not_positive_definite");
    CHECK(sinew::to_string(LinearStatus::singular) == "singular");
    CHECK(sinew::to_string(LinearStatus::not_converged) == "not_converged");
    CHECK(sinew::to_string(LinearStatus::failed) == "failed");
}

TEST_CASE("an unknown solver name or bad iteration limits are input errors", "[linear]")
{
    CHECK_THROWS_AS(sinew::make_linear_solver("nope"), sinew::InputError);
    CHECK_THROWS_WITH(sinew::make_linear_solver("nope"), Catch::Contains("nope") && Catch::Contains("cholmod") &&
                                                             Catch::Contains("umfpack") &&
                                                             Catch::Contains("pcg-ichol"));
    CHECK_THROWS_AS(sinew::make_linear_solver("pcg-jacobi", 0.0), sinew::InputError);
    CHECK_THROWS_AS(sinew::make_linear_solver("pcg-ichol", std::nan("")), sinew::InputError);
    CHECK_THROWS_AS(sinew::make_linear_solver("pcg-ichol", 1e-8, 0), sinew::InputError);
}

TEST_CASE("every solver solves a random symmetric positive definite system", "[linear]")
{
    const std::string name = GENERATE(from_range(sinew::linear_solver_names()));
    const unsigned seed = 11;
    CAPTURE(name, seed);
    std::mt19937 rng(seed);
    const SparseMatrix A = grid_matrix(12, true, rng);  // n = 1728
    const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);

    // Direct solvers: backward stable, κ(A) ≤ 25 / 0.1 here (Gershgorin), so
    // the residual is a few ε; 1e-10 is the contract. PCG is asked for 1e-10
    // (the default), and the true residual differs from the recursive one it
    // stops on by rounding of order ε·κ ≪ 1e-10.
    const auto solver = sinew::make_linear_solver(name, 1e-10);
    const Eigen::VectorXd x = factorize_and_solve(*solver, A, b);
    CHECK(relative_residual(A, x, b) <= 1e-10);

    CHECK(solver->stats().symbolic_analyses == 1);
    CHECK(solver->stats().numeric_factorizations == 1);
    CHECK(solver->stats().solves == 1);
    if (is_iterative(name))
        CHECK(solver->stats().last_iterations > 0);
    if (name.rfind("cholmod", 0) == 0) {
        CHECK(solver->inertia().positive == A.rows());
        CHECK(solver->inertia().negative == 0);
        CHECK(solver->inertia().zero == 0);
    }
}

TEST_CASE("symmetric solvers read only the lower triangle", "[linear]")
{
    const std::string name = GENERATE(from_range(symmetric_solver_names));
    const unsigned seed = 12;
    CAPTURE(name, seed);
    std::mt19937 rng(seed);
    const SparseMatrix A = grid_matrix(10, true, rng);
    const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);
    const auto solver = sinew::make_linear_solver(name);

    const Eigen::VectorXd x_full = factorize_and_solve(*solver, A, b);
    const Eigen::VectorXd x_lower = factorize_and_solve(*solver, lower_triangle(A), b);
    const Eigen::VectorXd x_garbage = factorize_and_solve(*solver, with_garbage_above_diagonal(A, rng), b);
    // The same lower triangle gives the same ordering and the same arithmetic:
    // the answers agree bit for bit.
    CHECK(x_lower == x_full);
    CHECK(x_garbage == x_full);
    CHECK(relative_residual(A, x_full, b) <= 1e-10);
    // The lower triangle alone has another pattern; the garbage matrix has the full one.
    CHECK(solver->stats().symbolic_analyses == 3);
}

TEST_CASE("symbolic analysis is reused while the pattern holds and redone when it changes", "[linear]")
{
    const std::string name = GENERATE(from_range(sinew::linear_solver_names()));
    const bool symmetric = name != "umfpack";
    const unsigned seed = 13;
    CAPTURE(name, seed);
    std::mt19937 rng(seed);
    const auto solver = sinew::make_linear_solver(name);
    const int m = 10;

    // Same pattern, new values: each factorization must use the new values,
    // so each solve is checked against its own matrix.
    for (int k = 1; k <= 3; ++k) {
        CAPTURE(k);
        const SparseMatrix A = grid_matrix(m, symmetric, rng);
        const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);
        const Eigen::VectorXd x = factorize_and_solve(*solver, A, b);
        CHECK(relative_residual(A, x, b) <= 1e-10);
        CHECK(solver->stats().symbolic_analyses == 1);
        CHECK(solver->stats().numeric_factorizations == k);
        CHECK(solver->stats().solves == k);
    }

    const SparseMatrix changed = grid_matrix(m, symmetric, rng, 20);
    const Eigen::VectorXd b = random_vector(static_cast<int>(changed.rows()), rng);
    const Eigen::VectorXd x = factorize_and_solve(*solver, changed, b);
    CHECK(relative_residual(changed, x, b) <= 1e-10);
    CHECK(solver->stats().symbolic_analyses == 2);

    // An uncompressed copy of the same matrix has the same pattern once compressed.
    SparseMatrix uncompressed = changed;
    uncompressed.uncompress();
    REQUIRE_FALSE(uncompressed.isCompressed());
    const Eigen::VectorXd x_uncompressed = factorize_and_solve(*solver, uncompressed, b);
    CHECK(x_uncompressed == x);
    CHECK(solver->stats().symbolic_analyses == 2);
    CHECK(solver->stats().numeric_factorizations == 5);
}

TEST_CASE("solve without a successful factorization fails", "[linear]")
{
    const std::string name = GENERATE(from_range(sinew::linear_solver_names()));
    CAPTURE(name);
    const auto solver = sinew::make_linear_solver(name);
    Eigen::VectorXd x;
    CHECK(solver->solve(Eigen::VectorXd::Ones(5), x) == LinearStatus::failed);
    CHECK_THAT(solver->last_message(), Catch::Contains(name));
    CHECK(solver->stats().solves == 0);

    const SparseMatrix rectangular(4, 5);
    CHECK(solver->factorize(rectangular) == LinearStatus::failed);
    CHECK_THAT(solver->last_message(), Catch::Contains("not square"));
    CHECK(solver->solve(Eigen::VectorXd::Ones(4), x) == LinearStatus::failed);

    std::mt19937 rng(14);
    const SparseMatrix A = grid_matrix(4, true, rng);
    REQUIRE(solver->factorize(A) == LinearStatus::ok);
    CHECK(solver->solve(Eigen::VectorXd::Ones(A.rows() + 1), x) == LinearStatus::failed);
    CHECK_THAT(solver->last_message(), Catch::Contains("right-hand side"));
}

TEST_CASE("non-finite entries in what a solver reads fail with a message", "[linear]")
{
    const std::string name = GENERATE(from_range(sinew::linear_solver_names()));
    CAPTURE(name);
    std::mt19937 rng(23);
    const SparseMatrix A = grid_matrix(5, true, rng);
    const auto solver = sinew::make_linear_solver(name);

    // Entry (1, 0) is below the diagonal: every solver reads it.
    SparseMatrix nan_below = A;
    nan_below.coeffRef(1, 0) = std::nan("");
    CHECK(solver->factorize(nan_below) == LinearStatus::failed);
    CHECK_THAT(solver->last_message(), Catch::Contains("(1, 0) is not finite"));

    REQUIRE(solver->factorize(A) == LinearStatus::ok);
    Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);
    b[3] = std::numeric_limits<double>::infinity();
    Eigen::VectorXd x;
    CHECK(solver->solve(b, x) == LinearStatus::failed);
    CHECK_THAT(solver->last_message(), Catch::Contains("not finite"));

    // Entry (0, 1) is above the diagonal: only the general solver reads it.
    SparseMatrix nan_above = A;
    nan_above.coeffRef(0, 1) = std::nan("");
    const LinearStatus expected = name == "umfpack" ? LinearStatus::failed : LinearStatus::ok;
    CHECK(solver->factorize(nan_above) == expected);
}

TEST_CASE("a right-hand side may be solved in place", "[linear]")
{
    const std::string name = GENERATE(from_range(sinew::linear_solver_names()));
    CAPTURE(name);
    std::mt19937 rng(15);
    const SparseMatrix A = grid_matrix(6, true, rng);
    const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);
    const auto solver = sinew::make_linear_solver(name);
    REQUIRE(solver->factorize(A) == LinearStatus::ok);
    Eigen::VectorXd x = b;
    REQUIRE(solver->solve(x, x) == LinearStatus::ok);
    CHECK(relative_residual(A, x, b) <= 1e-10);
}

TEST_CASE("CHOLMOD LLT reports an indefinite matrix and recovers with the same analysis", "[linear]")
{
    const unsigned seed = 16;
    CAPTURE(seed);
    std::mt19937 rng(seed);
    const SparseMatrix A = grid_matrix(10, true, rng);
    const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);
    SparseMatrix indefinite = A;
    indefinite.coeffRef(123, 123) = -1.0;  // e₁₂₃ᵀ A e₁₂₃ < 0; same pattern

    const auto solver = sinew::make_linear_solver("cholmod");
    CHECK(solver->factorize(indefinite) == LinearStatus::not_positive_definite);
    CHECK_THAT(solver->last_message(), Catch::Contains("not positive definite"));
    Eigen::VectorXd x;
    CHECK(solver->solve(b, x) == LinearStatus::failed);

    x = factorize_and_solve(*solver, A, b);
    CHECK(relative_residual(A, x, b) <= 1e-10);
    CHECK(solver->stats().symbolic_analyses == 1);
    CHECK(solver->stats().numeric_factorizations == 2);
}

TEST_CASE("CHOLMOD LDLT solves a quasi-definite KKT system and reports its inertia", "[linear]")
{
    const unsigned seed = 17;
    const int m = 10;  // H is 1000 × 1000
    const int num_constraints = 100;
    const double delta = 1e-6;
    CAPTURE(seed, delta);
    std::mt19937 rng(seed);
    const SparseMatrix K = kkt_matrix(m, num_constraints, delta, rng);
    const int n = static_cast<int>(K.rows()) - num_constraints;
    const Eigen::VectorXd b = random_vector(static_cast<int>(K.rows()), rng);

    const auto ldlt = sinew::make_linear_solver("cholmod-ldlt");
    const Eigen::VectorXd x = factorize_and_solve(*ldlt, K, b);
    // LDLᵀ without pivoting on a quasi-definite matrix is stable up to growth
    // of order ‖J‖²/δ in the worst ordering; 1e-8 is the accuracy we need
    // from a relaxed KKT step at δ = 1e-6.
    CHECK(relative_residual(K, x, b) <= 1e-8);
    // H positive definite and −δI − J H⁻¹ Jᵀ negative definite (Sylvester).
    CHECK(ldlt->inertia().positive == n);
    CHECK(ldlt->inertia().negative == num_constraints);
    CHECK(ldlt->inertia().zero == 0);

    const auto llt = sinew::make_linear_solver("cholmod");
    CHECK(llt->factorize(K) == LinearStatus::not_positive_definite);
}

TEST_CASE("CHOLMOD LDLT reports a zero pivot as singular", "[linear]")
{
    std::mt19937 rng(18);
    SparseMatrix A = grid_matrix(6, true, rng);
    const int zeroed = 40;
    for (int j = 0; j < A.outerSize(); ++j)
        for (SparseMatrix::InnerIterator entry(A, j); entry; ++entry)
            if (entry.row() == zeroed || entry.col() == zeroed)
                entry.valueRef() = 0.0;  // row and column 40 are zero: D has an exact zero

    const auto solver = sinew::make_linear_solver("cholmod-ldlt");
    CHECK(solver->factorize(A) == LinearStatus::singular);
    CHECK_FALSE(solver->last_message().empty());
    Eigen::VectorXd x;
    CHECK(solver->solve(Eigen::VectorXd::Ones(A.rows()), x) == LinearStatus::failed);
}

TEST_CASE("UMFPACK solves a nonsymmetric system", "[linear]")
{
    const unsigned seed = 19;
    CAPTURE(seed);
    std::mt19937 rng(seed);
    const SparseMatrix A = grid_matrix(12, false, rng);
    REQUIRE((A - SparseMatrix(A.transpose())).norm() > 0);
    const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);

    const auto solver = sinew::make_linear_solver("umfpack");
    const Eigen::VectorXd x = factorize_and_solve(*solver, A, b);
    // LU with partial pivoting on a diagonally dominant matrix: a few ε.
    CHECK(relative_residual(A, x, b) <= 1e-10);
}

TEST_CASE("UMFPACK reports a singular matrix", "[linear]")
{
    std::mt19937 rng(20);
    const SparseMatrix A = grid_matrix(6, false, rng);
    // P A with row 50 of P equal to e₇ᵀ: rows 7 and 50 of P A are identical.
    SparseMatrix P(A.rows(), A.rows());
    P.setIdentity();
    P.coeffRef(50, 50) = 0.0;
    P.coeffRef(50, 7) = 1.0;
    const SparseMatrix singular = (P * A).pruned();

    const auto solver = sinew::make_linear_solver("umfpack");
    CHECK(solver->factorize(singular) == LinearStatus::singular);
    CHECK_THAT(solver->last_message(), Catch::Contains("singular"));
    Eigen::VectorXd x;
    CHECK(solver->solve(Eigen::VectorXd::Ones(A.rows()), x) == LinearStatus::failed);

    const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);
    x = factorize_and_solve(*solver, A, b);
    CHECK(relative_residual(A, x, b) <= 1e-10);
}

TEST_CASE("PCG stops at its iteration limit with not_converged", "[linear]")
{
    const std::string name = GENERATE(from_range(iterative_solver_names));
    CAPTURE(name);
    std::mt19937 rng(21);
    const SparseMatrix A = grid_matrix(10, true, rng);
    const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);

    const auto solver = sinew::make_linear_solver(name, 1e-12, 2);
    REQUIRE(solver->factorize(A) == LinearStatus::ok);
    Eigen::VectorXd x;
    CHECK(solver->solve(b, x) == LinearStatus::not_converged);
    CHECK(solver->stats().last_iterations == 2);
    CHECK_THAT(solver->last_message(), Catch::Contains("not converged"));
    // The iterate is still returned and is better than x = 0.
    CHECK(relative_residual(A, x, b) < 1.0);
}

TEST_CASE("PCG meets a looser requested tolerance", "[linear]")
{
    const std::string name = GENERATE(from_range(iterative_solver_names));
    const double tolerance = 1e-6;
    CAPTURE(name, tolerance);
    std::mt19937 rng(22);
    const SparseMatrix A = grid_matrix(12, true, rng);
    const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);

    const auto solver = sinew::make_linear_solver(name, tolerance);
    const Eigen::VectorXd x = factorize_and_solve(*solver, A, b);
    const double residual = relative_residual(A, x, b);
    CAPTURE(residual, solver->stats().last_iterations);
    CHECK(residual <= tolerance);
    // It stops near the tolerance rather than running on to machine precision.
    CHECK(residual > 1e-10);
}

TEST_CASE("MUMPS LDLT solves a saddle-point KKT system with a zero block and reports its inertia", "[linear][mumps]")
{
    std::mt19937 rng(23);
    const int num_constraints = 100;
    const SparseMatrix K = kkt_matrix(10, num_constraints, 0.0, rng);  // [H Jᵀ; J 0], H is 1000 × 1000
    const int n = static_cast<int>(K.rows()) - num_constraints;
    const Eigen::VectorXd b = random_vector(static_cast<int>(K.rows()), rng);
    const auto solver = sinew::make_linear_solver("mumps-ldlt");
    const Eigen::VectorXd x = factorize_and_solve(*solver, K, b);
    CHECK(relative_residual(K, x, b) <= 1e-12);
    // H positive definite, J full row rank: inertia (n, m, 0) (Sylvester).
    CHECK(solver->inertia().positive == n);
    CHECK(solver->inertia().negative == num_constraints);
    CHECK(solver->inertia().zero == 0);
}

TEST_CASE("MUMPS LDLT inertia matches the eigenvalues of random indefinite matrices", "[linear][mumps]")
{
    for (unsigned seed = 30; seed < 35; ++seed) {
        CAPTURE(seed);
        std::mt19937 rng(seed);
        const int size = 60;
        Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(size, size);
        for (int i = 0; i < size; ++i)
            for (int j = 0; j <= i; ++j)
                if (i == j || uniform(rng, 0.0, 1.0) < 0.1)
                    dense(i, j) = dense(j, i) = uniform(rng, -1.0, 1.0);
        const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense).eigenvalues();
        REQUIRE(eigenvalues.cwiseAbs().minCoeff() > 1e-6);  // away from singular, so the count is unambiguous
        const SparseMatrix A = dense.sparseView();
        const auto solver = sinew::make_linear_solver("mumps-ldlt");
        REQUIRE(solver->factorize(A) == LinearStatus::ok);
        CHECK(solver->inertia().negative == (eigenvalues.array() < 0.0).count());
        CHECK(solver->inertia().positive == (eigenvalues.array() > 0.0).count());
        Eigen::VectorXd x;
        const Eigen::VectorXd b = random_vector(size, rng);
        REQUIRE(solver->solve(b, x) == LinearStatus::ok);
        CHECK((dense * x - b).norm() <= 1e-10 * (dense.norm() * x.norm() + b.norm()));
    }
}

TEST_CASE("MUMPS LDLT reports a KKT matrix with dependent constraints as singular", "[linear][mumps]")
{
    // [I Jᵀ; J 0] with J's two rows equal: one null pivot.
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(5, 5);
    dense.topLeftCorner(3, 3).setIdentity();
    const Eigen::RowVector3d row(1.0, 2.0, 3.0);
    dense.block(3, 0, 1, 3) = row;
    dense.block(4, 0, 1, 3) = row;
    dense.block(0, 3, 3, 1) = row.transpose();
    dense.block(0, 4, 3, 1) = row.transpose();
    const SparseMatrix A = dense.sparseView();
    const auto solver = sinew::make_linear_solver("mumps-ldlt");
    CHECK(solver->factorize(A) == LinearStatus::singular);
    CHECK_THAT(solver->last_message(), Catch::Contains("singular"));
    Eigen::VectorXd x;
    CHECK(solver->solve(Eigen::VectorXd::Ones(5), x) == LinearStatus::failed);
}

TEST_CASE("an iterative solver takes a new tolerance for its next solves", "[linear]")
{
    const std::string name = GENERATE(from_range(iterative_solver_names));
    CAPTURE(name);
    std::mt19937 rng(23);
    const SparseMatrix A = grid_matrix(12, true, rng);
    const Eigen::VectorXd b = random_vector(static_cast<int>(A.rows()), rng);
    const auto solver = sinew::make_linear_solver(name, 1e-10);
    REQUIRE(solver->factorize(A) == LinearStatus::ok);
    Eigen::VectorXd x;
    solver->set_tolerance(1e-4);
    REQUIRE(solver->solve(b, x) == LinearStatus::ok);
    const double loose = relative_residual(A, x, b);
    const long loose_iterations = solver->stats().last_iterations;
    CHECK(loose <= 1e-4);
    CHECK(loose > 1e-10);
    solver->set_tolerance(1e-10);
    REQUIRE(solver->solve(b, x) == LinearStatus::ok);
    CHECK(relative_residual(A, x, b) <= 1e-10);
    CHECK(solver->stats().last_iterations > loose_iterations);
    CHECK(solver->stats().total_iterations == loose_iterations + solver->stats().last_iterations);
}

TEST_CASE("the petsc-* solvers: listed when built, a clear input error naming the package otherwise", "[linear]")
{
    const std::vector<std::string> names = sinew::linear_solver_names();
    const bool listed = std::find(names.begin(), names.end(), "petsc-cg-gamg") != names.end();
    CHECK(listed == sinew::petsc_linear_solvers_built());
    const std::vector<std::string> known = sinew::known_linear_solver_names();
    CHECK(std::find(known.begin(), known.end(), "petsc-cg-hypre") != known.end());
    CHECK_NOTHROW(sinew::check_linear_solver_usable("cholmod"));
    if (sinew::petsc_linear_solvers_built()) {
        CHECK(sinew::make_linear_solver("petsc-cg-gamg")->uses_near_null_space());
        CHECK(sinew::make_linear_solver("petsc-cg-hypre")->uses_near_null_space());
        CHECK_FALSE(sinew::make_linear_solver("cholmod")->uses_near_null_space());
    } else {
        CHECK_THROWS_WITH(sinew::make_linear_solver("petsc-cg-gamg"),
                          Catch::Contains("built without") && Catch::Contains("libpetsc-real-dev"));
        CHECK_THROWS_AS(sinew::check_linear_solver_usable("petsc-cg-hypre"), sinew::InputError);
    }
}
