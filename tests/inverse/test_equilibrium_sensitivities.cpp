#include "sinew/core/input_error.hpp"
#include "sinew/inverse/equilibrium_sensitivities.hpp"
#include "sinew/inverse/muscle_rig.hpp"

#include "inverse/rig_test_support.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

/// Central differences of the landmark positions in θ_k, each side a full re-solve
/// (warm-started from the equilibrium at θ, as the rig does).
Eigen::VectorXd landmark_difference(MuscleRig& rig, const RigParameters& theta, int k, double h)
{
    Eigen::VectorXd plus = theta.packed(), minus = theta.packed();
    plus[k] += h;
    minus[k] -= h;
    REQUIRE(rig.evaluate(RigParameters::unpacked(plus, theta.num_muscles())).ok);
    const Eigen::VectorXd x_plus = rig.landmark_positions();
    REQUIRE(rig.evaluate(RigParameters::unpacked(minus, theta.num_muscles())).ok);
    const Eigen::VectorXd x_minus = rig.landmark_positions();
    return (x_plus - x_minus) / (2 * h);
}

} // namespace

TEST_CASE("rig: landmark sensitivities match central differences of re-solves for every parameter",
          "[inverse][rig][sensitivities]")
{
    // Seed 000 §3: activations (§3.1), cranium (§3.2) and jaw (§3.3–3.4), at a
    // state with the muscles active and both maps away from the identity.
    MuscleRig rig(slab_rig(), tight_settings());
    const RigParameters theta = moved_parameters(8.0);
    const RigEvaluation at_theta = rig.evaluate(theta);
    REQUIRE(at_theta.ok);
    const Eigen::MatrixXd J = rig.landmark_jacobian();
    REQUIRE(J.rows() == 3 * rig.num_landmarks());
    REQUIRE(J.cols() == theta.size());
    CHECK(rig.sensitivity_factorizations() == 1);
    for (int k = 0; k < theta.size(); ++k) {
        CAPTURE(k);
        const double h = k < theta.num_muscles() ? 1e-4 : 1e-5;
        const Eigen::VectorXd differences = landmark_difference(rig, theta, k, h);
        REQUIRE(differences.norm() > 0.0);
        CHECK((J.col(k) - differences).norm() <= 1e-6 * differences.norm());
    }
}

TEST_CASE("rig with contact: landmark sensitivities match central differences of re-solves while a ball presses in",
          "[inverse][rig][sensitivities][contact]")
{
    // The equilibrium's Hessian holds the contact term ε(∇φ∇φᵀ − δ∇²φ) of
    // the touching nodes.
    const RigDefinition definition = slab_rig_pressed_by_ball();
    MuscleRig rig(definition, tight_settings());
    MuscleRig free_rig(slab_rig(), tight_settings());
    const RigParameters theta = moved_parameters(8.0);
    REQUIRE(rig.evaluate(theta).ok);
    REQUIRE(free_rig.evaluate(theta).ok);
    CAPTURE(rig.max_penetration(), rig.contact_force().transpose());
    REQUIRE(rig.max_penetration() > 0.0);
    CHECK(rig.max_penetration() < 1e-4);  // the ball's 1 mm mostly pushed out
    CHECK(rig.contact_force().z() < 0.0);  // the ball pushes the top face down
    const Eigen::MatrixXd J = rig.landmark_jacobian();
    // Contact changes the sensitivities: the test below sees its term.
    CHECK((J - free_rig.landmark_jacobian()).norm() > 1e-3 * J.norm());
    for (int k = 0; k < theta.size(); ++k) {
        CAPTURE(k);
        // The contact's stiffness makes x(θ) curve fast (the central
        // differences' O(h²) error is 4e-6 at h = 1e-5 for the jaw's
        // translation, falling as h²): Richardson's extrapolation of h and
        // h/2 cancels it.
        const double h = k < theta.num_muscles() ? 1e-4 : 1e-5;
        const Eigen::VectorXd coarse = landmark_difference(rig, theta, k, h);
        const Eigen::VectorXd fine = landmark_difference(rig, theta, k, 0.5 * h);
        const Eigen::VectorXd differences = (4.0 * fine - coarse) / 3.0;
        REQUIRE(differences.norm() > 0.0);
        CHECK((J.col(k) - differences).norm() <= 1e-6 * differences.norm());
    }
}

TEST_CASE("rig with a body the jaw carries: landmark sensitivities match differences of re-solves in every parameter",
          "[inverse][rig][sensitivities][contact]")
{
    // The ball moves with M_j and t_j, so the jaw's columns need the contact
    // term's mixed derivative ∂(∇E_c)/∂θ_jaw besides the jaw nodes' motion.
    MuscleRig rig(slab_rig_pressed_by_ball_on_jaw(), tight_settings());
    const RigParameters theta = moved_parameters(8.0);
    REQUIRE(rig.evaluate(theta).ok);
    CAPTURE(rig.max_penetration(), rig.contact_force().transpose());
    REQUIRE(rig.max_penetration() > 0.0);
    CHECK(rig.contact_force().z() < 0.0);
    const Eigen::MatrixXd J = rig.landmark_jacobian();
    CHECK(rig.sensitivity_factorizations() == 1);
    for (int k = 0; k < theta.size(); ++k) {
        CAPTURE(k);
        const double h = k < theta.num_muscles() ? 1e-4 : 1e-5;
        const Eigen::VectorXd coarse = landmark_difference(rig, theta, k, h);
        const Eigen::VectorXd fine = landmark_difference(rig, theta, k, 0.5 * h);
        const Eigen::VectorXd differences = (4.0 * fine - coarse) / 3.0;  // Richardson, as above
        REQUIRE(differences.norm() > 0.0);
        CHECK((J.col(k) - differences).norm() <= 1e-6 * differences.norm());
    }
    // The adjoint path uses the same directions.
    REQUIRE(rig.evaluate(theta).ok);
    const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(3 * rig.num_landmarks(), -1.0, 2.0);
    CHECK((rig.landmark_gradient(w) - rig.landmark_jacobian().transpose() * w).norm() <=
          1e-10 * (rig.landmark_jacobian().transpose() * w).norm());
}

TEST_CASE("rig: the adjoint gradient equals the forward sensitivities applied to the weights",
          "[inverse][rig][sensitivities]")
{
    MuscleRig rig(slab_rig(), tight_settings());
    const RigParameters theta = moved_parameters(-6.0);
    REQUIRE(rig.evaluate(theta).ok);
    std::mt19937 rng(3);
    std::normal_distribution<double> normal;
    Eigen::VectorXd w(3 * rig.num_landmarks());
    for (Eigen::Index i = 0; i < w.size(); ++i)
        w[i] = normal(rng);
    const Eigen::VectorXd adjoint = rig.landmark_gradient(w);
    const Eigen::VectorXd forward = rig.landmark_jacobian().transpose() * w;
    CHECK(rig.sensitivity_factorizations() == 1);  // one factorization serves both
    CHECK((adjoint - forward).norm() <= 1e-10 * forward.norm());
}

TEST_CASE("rig: an evaluation at the last theta is not repeated, a new theta warm-starts from the last equilibrium",
          "[inverse][rig]")
{
    MuscleRig rig(slab_rig(), tight_settings());
    const RigParameters theta = moved_parameters(5.0);
    REQUIRE(rig.evaluate(theta).ok);
    CHECK(rig.equilibrium_solves() == 1);
    REQUIRE(rig.evaluate(theta).ok);
    CHECK(rig.equilibrium_solves() == 1);
    RigParameters near = theta;
    near.activations[0] += 1e-3;
    const RigEvaluation warm = rig.evaluate(near);
    CAPTURE(warm.failure);
    REQUIRE(warm.ok);
    CHECK(rig.equilibrium_solves() == 2);
    CHECK(warm.inner.iterations <= 4);
}

TEST_CASE("rig: a re-solve a tiny parameter step away is accepted on the force-scaled test",
          "[inverse][rig]")
{
    // The outer solvers' last steps change θ by ~1e-7: one Newton step from the
    // warm start then meets tol × force scale, which the result's KKT check
    // (kkt_tol, here far below it) must not overrule.
    EquilibriumSolveSettings settings = tight_settings();
    settings.options.tolerance = 1e-6;
    settings.options.kkt_tolerance = 1e-14;
    MuscleRig rig(slab_rig(), settings);
    RigParameters theta = moved_parameters(5.0);
    for (int step = 0; step < 4; ++step) {
        CAPTURE(step);
        const RigEvaluation evaluation = rig.evaluate(theta);
        CAPTURE(evaluation.failure);
        CHECK(evaluation.ok);
        theta.activations[step % 2] += 1e-7;
        theta.jaw_translation[1] += 1e-10;
    }
}

TEST_CASE("rig: bad parameters are refused and a failed inner solve is a failed evaluation", "[inverse][rig][errors]")
{
    MuscleRig rig(slab_rig(), tight_settings());
    RigParameters theta = moved_parameters(5.0);
    theta.activations[1] = 1.5;
    CHECK_THROWS_AS(rig.evaluate(theta), InputError);
    theta.activations[1] = 0.5;
    theta.jaw_map(0, 1) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(rig.evaluate(theta), InputError);
    CHECK_THROWS_AS(rig.landmark_jacobian(), std::logic_error);
    CHECK_THROWS_AS(RigParameters::unpacked(Eigen::VectorXd::Zero(5), 2), InputError);

    EquilibriumSolveSettings one_iteration = tight_settings();
    one_iteration.options.max_iterations = 1;
    MuscleRig starved(slab_rig(), one_iteration);
    const RigEvaluation failed = starved.evaluate(moved_parameters(12.0));
    CHECK_FALSE(failed.ok);
    CHECK(failed.failure.find("max_iterations") != std::string::npos);
    CHECK_THROWS_AS(starved.landmark_positions(), std::logic_error);
    CHECK_THROWS_AS(starved.landmark_gradient(Eigen::VectorXd::Zero(3 * starved.num_landmarks())), std::logic_error);

    RigDefinition no_landmarks = slab_rig();
    no_landmarks.landmarks.clear();
    CHECK_THROWS_AS(MuscleRig(no_landmarks, tight_settings()), InputError);
    RigDefinition bad_muscle = slab_rig();
    bad_muscle.muscle_elements[0].push_back(bad_muscle.mesh.num_elements());
    CHECK_THROWS_AS(MuscleRig(bad_muscle, tight_settings()), InputError);
    RigDefinition shared_node = slab_rig();
    shared_node.jaw_nodes.push_back(shared_node.cranium_nodes.front());
    CHECK_THROWS_AS(MuscleRig(shared_node, tight_settings()), InputError);
}
