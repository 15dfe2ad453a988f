// The petsc-* linear solvers (built with PETSc only) on an elastic Hessian:
// the near null space (rigid-body modes) is what makes smoothed aggregation
// work, and a near null space of the wrong size is refused.
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/solvers/linear/linear_solver.hpp"

#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <vector>

namespace {

/// The lower triangle of the PSD-projected Hessian of a built-in scene at
/// its starting point, and the scene's near null space there.
struct ElasticSystem {
    sinew::SparseMatrix lower;
    sinew::NearNullSpace modes;
};

ElasticSystem elastic_system(const std::string& scene_name)
{
    sinew::Scene scene = sinew::make_builtin_scene(scene_name);
    sinew::Nlp& nlp = *scene.problem;
    const Eigen::VectorXd x = nlp.starting_point();
    const sinew::SparsityPattern& pattern = nlp.hessian_pattern();
    Eigen::VectorXd values(pattern.nonzeros());
    nlp.hessian(x, 1.0, Eigen::VectorXd::Zero(nlp.num_constraints()), sinew::Projection::clamp, values);
    std::vector<Eigen::Triplet<double>> entries;
    for (int k = 0; k < pattern.nonzeros(); ++k)
        entries.emplace_back(pattern.rows[k], pattern.cols[k], values[k]);
    ElasticSystem system;
    system.lower.resize(nlp.num_variables(), nlp.num_variables());
    system.lower.setFromTriplets(entries.begin(), entries.end());
    system.modes = nlp.near_null_space(x);
    return system;
}

/// CG iterations to a relative residual of 1e-8 for b = A·1, and that residual.
std::pair<int, double> iterations_to_solve(sinew::LinearSolver& solver, const sinew::SparseMatrix& lower)
{
    const sinew::SparseMatrix A = lower.selfadjointView<Eigen::Lower>();
    const Eigen::VectorXd b = A * Eigen::VectorXd::Ones(A.rows());
    REQUIRE(solver.factorize(lower) == sinew::LinearStatus::ok);
    Eigen::VectorXd x;
    REQUIRE(solver.solve(b, x) == sinew::LinearStatus::ok);
    return {solver.stats().last_iterations, (b - A * x).norm() / b.norm()};
}

} // namespace

TEST_CASE("GAMG with the rigid-body modes converges in fewer CG iterations than without", "[linear][petsc]")
{
    const ElasticSystem system = elastic_system("cantilever-6k");
    REQUIRE(system.modes.vectors.cols() == 6);

    const auto with_modes = sinew::make_linear_solver("petsc-cg-gamg", 1e-8);
    with_modes->set_near_null_space(system.modes);
    const auto [iterations_with, residual_with] = iterations_to_solve(*with_modes, system.lower);

    const auto without = sinew::make_linear_solver("petsc-cg-gamg", 1e-8);
    const auto [iterations_without, residual_without] = iterations_to_solve(*without, system.lower);

    CAPTURE(iterations_with, iterations_without);
    CHECK(residual_with <= 1e-8);
    CHECK(residual_without <= 1e-8);
    CHECK(iterations_with < iterations_without);
}

TEST_CASE("an algebraic multigrid refuses a near null space of another size", "[linear][petsc]")
{
    const std::string name = GENERATE(as<std::string>{}, "petsc-cg-gamg", "petsc-cg-hypre");
    CAPTURE(name);
    const ElasticSystem system = elastic_system("cantilever-6k");
    const auto solver = sinew::make_linear_solver(name);
    sinew::NearNullSpace wrong = system.modes;
    wrong.vectors.conservativeResize(wrong.vectors.rows() - 3, Eigen::NoChange);
    solver->set_near_null_space(wrong);
    CHECK(solver->factorize(system.lower) == sinew::LinearStatus::failed);
    CHECK_THAT(solver->last_message(), Catch::Contains("near null space has"));
    Eigen::VectorXd x;
    CHECK(solver->solve(Eigen::VectorXd::Ones(system.lower.rows()), x) == sinew::LinearStatus::failed);
}

namespace {

/// `lower` with σ added to its diagonal.
sinew::SparseMatrix shifted(const sinew::SparseMatrix& lower, double sigma)
{
    sinew::SparseMatrix identity(lower.rows(), lower.cols());
    identity.setIdentity();
    return lower + sigma * identity;
}

/// A GAMG solver with the rigid-body modes, to a relative residual of 1e-8.
std::unique_ptr<sinew::LinearSolver> gamg_with_modes(const sinew::NearNullSpace& modes)
{
    auto solver = sinew::make_linear_solver("petsc-cg-gamg", 1e-8);
    solver->set_near_null_space(modes);
    return solver;
}

} // namespace

TEST_CASE("GAMG solves a sequence of matrices of one pattern to the tolerance on kept prolongators", "[linear][petsc]")
{
    const ElasticSystem system = elastic_system("twisted-cantilever-6k");
    const double diagonal = system.lower.diagonal().cwiseAbs().maxCoeff();
    const auto solver = gamg_with_modes(system.modes);
    for (const double sigma : {0.0, 0.3 * diagonal, 1e-3 * diagonal}) {
        CAPTURE(sigma);
        const auto [iterations, residual] = iterations_to_solve(*solver, shifted(system.lower, sigma));
        CAPTURE(iterations);
        CHECK(residual <= 1e-8);
    }
}

TEST_CASE("GAMG builds new prolongators after CG met an indefinite matrix", "[linear][petsc]")
{
    const ElasticSystem system = elastic_system("twisted-cantilever-6k");
    const double diagonal = system.lower.diagonal().cwiseAbs().maxCoeff();
    const auto solver = gamg_with_modes(system.modes);
    REQUIRE(solver->factorize(shifted(system.lower, -0.5 * diagonal)) == sinew::LinearStatus::ok);
    Eigen::VectorXd x;
    REQUIRE(solver->solve(Eigen::VectorXd::Ones(system.lower.rows()), x) ==
            sinew::LinearStatus::not_positive_definite);

    // After the indefinite matrix, the same iterations as a solver that
    // never saw it: its hierarchy is built from the positive definite matrix.
    const auto [iterations_after, residual_after] = iterations_to_solve(*solver, system.lower);
    const auto fresh = gamg_with_modes(system.modes);
    const auto [iterations_fresh, residual_fresh] = iterations_to_solve(*fresh, system.lower);
    CAPTURE(iterations_after, iterations_fresh);
    CHECK(residual_after <= 1e-8);
    CHECK(iterations_after == iterations_fresh);
}
