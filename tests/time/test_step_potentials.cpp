// The time step's own potentials (inertia, mass and stiffness damping):
// derivatives through the shared finite-difference check, over positions in
// every deformation regime, and what they must equal.
#include "energies/deformation_regimes.hpp"
#include "potentials/potential_checks.hpp"
#include "potentials/test_meshes.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/element_model.hpp"
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/inertia_potential.hpp"
#include "sinew/energies/potentials/lumped_mass.hpp"
#include "sinew/energies/potentials/stiffness_damping_potential.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

constexpr double kH = 0.5;

/// x = A X + noise of 0.05·h·σ_min(A): no element inverts.
Eigen::VectorXd deformed_box(const Mesh& mesh, Regime regime, std::mt19937& rng)
{
    const Eigen::Matrix3d A = random_deformation<3, 3>(regime, rng);
    const Eigen::Matrix3d C = A.transpose() * A;
    const double sigma_min = std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).eigenvalues()[0]);
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    Eigen::VectorXd x(3 * mesh.num_nodes());
    for (int i = 0; i < mesh.num_nodes(); ++i) {
        x.segment<3>(3 * i) = A * mesh.nodes.col(i);
        for (int k = 0; k < 3; ++k)
            x[3 * i + k] += 0.05 * kH * sigma_min * u11(rng);
    }
    return x;
}

Eigen::VectorXd random_vector(Eigen::Index n, double scale, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    Eigen::VectorXd v(n);
    for (Eigen::Index i = 0; i < n; ++i)
        v[i] = scale * u11(rng);
    return v;
}

std::shared_ptr<ElasticPotential> neo_hookean_box(const Mesh& mesh)
{
    const ElementModel model =
        make_element_model(ElementKind::tetrahedron, "stable-neo-hookean", {{"mu", 2e4}, {"lambda", 5e4}});
    return std::make_shared<ElasticPotential>(mesh, std::vector<ElementModel>{model});
}

} // namespace

TEST_CASE("inertia potential: derivatives match central differences and the Hessian is M/s", "[time][potentials]")
{
    std::mt19937 rng(31);
    const Mesh mesh = box_of_tets(2, 1, 1, kH);
    const Eigen::VectorXd masses = lumped_masses(mesh, {1000.0});
    auto inertia = std::make_shared<InertiaPotential>("inertia", 3, masses);
    TotalPotential E({inertia});
    for (Regime regime : all_regimes()) {
        CAPTURE(regime_name(regime));
        const Eigen::VectorXd predictor = deformed_box(mesh, regime, rng);
        const double s = 1e-4;
        inertia->set_step(predictor, s);
        const Eigen::VectorXd y = predictor + random_vector(predictor.size(), 0.01, rng);
        const DerivativeErrors errors = derivative_errors(E, y, 1e-5);
        CAPTURE(errors.gradient, errors.hessian);
        REQUIRE(errors.gradient_scale > 0.0);
        CHECK(errors.gradient < 1e-7);
        const Eigen::MatrixXd H = dense_hessian(E, y, Projection::none);
        for (int k = 0; k < H.rows(); ++k)
            CHECK(H(k, k) == Approx(masses[k / 3] / s).epsilon(1e-14));
        CHECK((H - Eigen::MatrixXd(H.diagonal().asDiagonal())).cwiseAbs().maxCoeff() == 0.0);
    }
    CHECK_THROWS_AS(inertia->set_step(Eigen::VectorXd::Zero(3), 1.0), InputError);
    CHECK_THROWS_AS(inertia->set_step(Eigen::VectorXd::Zero(3 * mesh.num_nodes()), 0.0), InputError);
    CHECK_THROWS_AS(InertiaPotential("inertia", 3, Eigen::VectorXd::Constant(2, -1.0)), InputError);
}

TEST_CASE("stiffness damping: derivatives match central differences and the force is beta K v", "[time][potentials]")
{
    std::mt19937 rng(32);
    const Mesh mesh = box_of_tets(2, 1, 1, kH);
    auto elastic = neo_hookean_box(mesh);
    const double beta = 0.02, slope = 50.0;
    auto damping = std::make_shared<StiffnessDampingPotential>(elastic, beta);
    TotalPotential E({damping});
    TotalPotential elastic_only({elastic});
    for (Regime regime : all_regimes()) {
        CAPTURE(regime_name(regime));
        const Eigen::VectorXd start = deformed_box(mesh, regime, rng);
        const Eigen::VectorXd v_bar = random_vector(start.size(), 0.3, rng);
        const Eigen::VectorXd predictor = start + random_vector(start.size(), 0.01, rng);
        damping->set_step(start, v_bar, predictor, slope);
        const Eigen::VectorXd y = predictor + random_vector(start.size(), 0.01, rng);

        const DerivativeErrors errors = derivative_errors(E, y, 1e-5);
        CAPTURE(errors.gradient, errors.hessian);
        REQUIRE(errors.gradient_scale > 0.0);
        REQUIRE(errors.hessian_scale > 0.0);
        CHECK(errors.gradient < 1e-7);
        CHECK(errors.hessian < 1e-7);

        // ∇Ψ = βK(xₙ)v(y) and ∇²Ψ = βgK, K the projected Hessian at the start.
        const Eigen::MatrixXd K = dense_hessian(elastic_only, start, Projection::clamp);
        const Eigen::VectorXd v = v_bar + slope * (y - predictor);
        CHECK(relative_error(gradient_of(E, y), Eigen::VectorXd(beta * K * v)) < 1e-12);
        CHECK(relative_error(dense_hessian(E, y, Projection::none), Eigen::MatrixXd(beta * slope * K)) < 1e-12);
        CHECK(E.value(y) >= 0.0);
    }
    CHECK_THROWS_AS(StiffnessDampingPotential(elastic, -1.0), InputError);
    CHECK_THROWS_AS(StiffnessDampingPotential(nullptr, 1.0), InputError);
}
