#include "sinew/inverse/rig_fit_run.hpp"
#include "sinew/inverse/rig_identifiability.hpp"

#include "inverse/rig_test_support.hpp"

#include <catch2/catch.hpp>

using namespace sinew;
using namespace sinew::test;

TEST_CASE("rig identifiability: the slab's top-face landmarks determine all parameters", "[inverse][rig][identifiability]")
{
    MuscleRig rig(slab_rig(), tight_settings());
    RigFitProblem problem(rig, Eigen::VectorXd::Zero(3 * rig.num_landmarks()), {});
    for (const RigParameters& theta : {RigParameters::neutral(2), moved_parameters(8.0)}) {
        const RigIdentifiability result = rig_identifiability(problem, theta.packed());
        CAPTURE(result.message);
        CHECK(result.determined());
        CHECK(result.rank == 26);
        CHECK(result.singular_value_ratio > 1e-6);
        CHECK(result.undetermined.empty());
    }
}

TEST_CASE("rig identifiability: too few landmarks are reported and the fit refuses with the reason",
          "[inverse][rig][identifiability]")
{
    RigDefinition definition = slab_rig();
    definition.landmarks.resize(2);  // 6 rows + 12 constraints for 26 parameters
    MuscleRig rig(definition, tight_settings());
    RigFitProblem problem(rig, Eigen::VectorXd::Zero(6), {});
    const RigIdentifiability result = rig_identifiability(problem, problem.starting_point());
    CAPTURE(result.message);
    CHECK(result.rank <= 18);
    CHECK_FALSE(result.determined());
    CHECK_FALSE(result.undetermined.empty());
    CHECK_THAT(result.message, Catch::Contains("the landmarks do not determine"));

    SolverOptions options;
    options.max_iterations = 5;
    const RigFitOutcome outcome =
        run_rig_fit(definition, tight_settings(), targets_at(definition, moved_parameters(8.0)),
                    {"ipopt", "ipopt", OrthogonalityForm::constraints, options}, {});
    CHECK(outcome.result.status == Status::failed);
    CHECK_THAT(outcome.result.message, Catch::Contains("rank"));
    CHECK(outcome.result.iterations == 0);
    CHECK(outcome.equilibrium_solves == 1);
}

TEST_CASE("rig identifiability: landmarks fixed to the cranium leave the muscles and the jaw undetermined",
          "[inverse][rig][identifiability]")
{
    // Many rows, yet no landmark moves with an activation or the jaw: their
    // Jacobian columns vanish, and each is named.
    RigDefinition definition = slab_rig();
    definition.landmarks = definition.cranium_nodes;
    MuscleRig rig(definition, tight_settings());
    REQUIRE(3 * rig.num_landmarks() + 12 >= rig.num_parameters());
    RigFitProblem problem(rig, Eigen::VectorXd::Zero(3 * rig.num_landmarks()), {});
    const RigIdentifiability result = rig_identifiability(problem, moved_parameters(8.0).packed());
    CAPTURE(result.message);
    CHECK_FALSE(result.determined());
    CHECK_THAT(result.message, Catch::Contains("activation of diagonal") && Catch::Contains("activation of transverse"));
    CHECK_THAT(result.message, Catch::Contains("M_j("));
}

TEST_CASE("rig identifiability: a Tikhonov term determines activations no landmark sees", "[inverse][rig][identifiability]")
{
    RigDefinition definition = slab_rig();
    definition.landmarks = definition.cranium_nodes;
    definition.landmarks.insert(definition.landmarks.end(), definition.jaw_nodes.begin(), definition.jaw_nodes.end());
    MuscleRig rig(definition, tight_settings());
    RigFitSettings plain, regularized;
    regularized.tikhonov = 1e-6;
    RigFitProblem without(rig, Eigen::VectorXd::Zero(3 * rig.num_landmarks()), plain);
    RigFitProblem with(rig, Eigen::VectorXd::Zero(3 * rig.num_landmarks()), regularized);
    const Eigen::VectorXd theta = moved_parameters(8.0).packed();
    const RigIdentifiability bones_only = rig_identifiability(without, theta);
    CAPTURE(bones_only.message);
    CHECK(bones_only.rank == 24);
    CHECK(bones_only.undetermined.size() == 2);
    const RigIdentifiability regularized_result = rig_identifiability(with, theta);
    CAPTURE(regularized_result.message);
    CHECK(regularized_result.determined());
}
