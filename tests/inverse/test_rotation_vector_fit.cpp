#include "sinew/core/input_error.hpp"
#include "sinew/core/rotation_vector.hpp"
#include "sinew/inverse/rotation_vector_fit_problem.hpp"
#include "sinew/solvers/solver.hpp"

#include "inverse/rig_test_support.hpp"

#include <catch2/catch.hpp>

using namespace sinew;
using namespace sinew::test;

namespace {

Eigen::VectorXd landmarks_at(MuscleRig& rig, const RigParameters& theta)
{
    REQUIRE(rig.evaluate(theta).ok);
    return rig.landmark_positions();
}

} // namespace

TEST_CASE("rotation-vector fit: the gradient matches central differences of re-solves", "[inverse][rig][rotation]")
{
    MuscleRig rig(slab_rig(), tight_settings());
    const Eigen::VectorXd targets = landmarks_at(rig, moved_parameters(10.0));
    RigFitSettings settings;
    settings.tikhonov = 1e-5;
    RotationVectorFitProblem problem(rig, targets, settings, moved_parameters(4.0));
    const Eigen::VectorXd phi = problem.starting_point();
    REQUIRE(phi.size() == 14);
    CHECK((problem.affine_parameters(phi) - moved_parameters(4.0).packed()).cwiseAbs().maxCoeff() < 1e-14);
    REQUIRE(std::isfinite(problem.objective(phi)));
    Eigen::VectorXd gradient(phi.size());
    problem.gradient(phi, gradient);
    const Eigen::VectorXd differences = objective_differences(problem, phi);
    CAPTURE(gradient.transpose(), differences.transpose());
    REQUIRE(differences.norm() > 0.0);
    CHECK((gradient - differences).norm() <= 1e-6 * differences.norm());
}

TEST_CASE("rotation-vector fit: noise-free targets are recovered without constraints", "[inverse][rig][rotation]")
{
    const RigParameters truth = moved_parameters(8.0);
    MuscleRig rig(slab_rig(), tight_settings());
    const Eigen::VectorXd targets = landmarks_at(rig, truth);
    RotationVectorFitProblem problem(rig, targets, {});
    SolverOptions options;
    options.tolerance = 1e-14;
    options.max_iterations = 200;
    const Result result = solve(problem, "projected-newton", options);
    CAPTURE(to_string(result.status), result.message, result.iterations);
    const Eigen::VectorXd theta = problem.affine_parameters(result.x);
    const double rms = std::sqrt(problem.affine_problem().residual(theta).squaredNorm() / rig.num_landmarks());
    CHECK(rms <= 1e-6 * rig.size());
    CHECK((theta - truth.packed()).cwiseAbs().maxCoeff() <= 1e-5);
    CHECK(problem.affine_problem().cranium_violation(theta) <= 1e-9);
    CHECK(problem.affine_problem().jaw_violation(theta) <= 1e-9);
}

TEST_CASE("rotation-vector fit: a starting map that is no rotation is refused", "[inverse][rig][rotation][errors]")
{
    MuscleRig rig(slab_rig(), tight_settings());
    const Eigen::VectorXd targets = Eigen::VectorXd::Zero(3 * rig.num_landmarks());
    RigParameters start = RigParameters::neutral(2);
    start.jaw_map(0, 0) = 1.1;
    CHECK_THROWS_WITH(RotationVectorFitProblem(rig, targets, {}, start), Catch::Contains("jaw map is not a rotation"));
    start = RigParameters::neutral(2);
    start.cranium_map(2, 2) = -1.0;  // a reflection
    CHECK_THROWS_WITH(RotationVectorFitProblem(rig, targets, {}, start), Catch::Contains("cranium map is not a rotation"));
    RigFitSettings settings;
    settings.orthogonality = OrthogonalityForm::rotation_vectors;
    CHECK_THROWS_AS(RigFitProblem(rig, targets, settings), InputError);
}
