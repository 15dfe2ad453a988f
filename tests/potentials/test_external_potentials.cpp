#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/gravity_potential.hpp"
#include "sinew/energies/potentials/lumped_mass.hpp"
#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"
#include "sinew/energies/potentials/point_load_potential.hpp"
#include "sinew/energies/potentials/total_potential.hpp"

#include "energies/deformation_regimes.hpp"
#include "potentials/potential_checks.hpp"
#include "potentials/test_meshes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace sinew;
using namespace sinew::test;

TEST_CASE("lumped masses: each element's mass split equally among its nodes", "[potentials][gravity]")
{
    Mesh mesh = box_of_tets(2, 3, 1, 0.5);
    alternate_groups(mesh, "light", "heavy");
    const Eigen::VectorXd m = lumped_masses(mesh, {1000.0, 3000.0});
    // Half the volume at each density.
    const double volume = 2 * 3 * 1 * 0.125;
    CHECK(m.sum() == Approx(0.5 * volume * 1000.0 + 0.5 * volume * 3000.0).epsilon(1e-14));
    CHECK(m.minCoeff() > 0.0);

    const Mesh sheet = sheet_of_triangles(2, 2, 0.5, Eigen::Matrix3d::Identity());
    CHECK(lumped_masses(sheet, {2.0}).sum() == Approx(2.0 * 1.0).epsilon(1e-14));  // kg/m² × 1 m²
}

TEST_CASE("gravity and point loads: E, gradient and zero Hessian", "[potentials][gravity][loads]")
{
    std::mt19937 rng(51);
    const Mesh mesh = box_of_tets(2, 1, 1, 0.5);
    const Eigen::VectorXd masses = lumped_masses(mesh, {1000.0});
    const Eigen::Vector3d g(0.0, -1.0, -9.81);
    auto gravity = std::make_shared<GravityPotential>(3, masses, g);
    Eigen::MatrixXd forces(3, 3);
    forces << 1, 2, -1, 0, 5, 0.5, -3, 1, 2;
    auto loads = std::make_shared<PointLoadPotential>(3, mesh.num_nodes(), std::vector<int>{0, 5, 5}, forces);
    TotalPotential E({gravity, loads});
    REQUIRE(E.hessian_pattern().nonzeros() == 6 * mesh.num_nodes());  // the diagonal blocks alone

    Eigen::VectorXd x = rest_coordinates(mesh) + 0.1 * Eigen::VectorXd::Random(3 * mesh.num_nodes());
    double expected = 0.0;
    for (int i = 0; i < mesh.num_nodes(); ++i)
        expected -= masses[i] * g.dot(x.segment<3>(3 * i));
    expected -= forces.col(0).dot(x.segment<3>(0)) + (forces.col(1) + forces.col(2)).dot(x.segment<3>(15));
    CHECK(E.value(x) == Approx(expected).epsilon(1e-14));

    const Eigen::VectorXd gradient = gradient_of(E, x);
    CHECK(relative_error(gradient, finite_difference_gradient(E, x, 1e-6)) < 1e-8);
    CHECK((gradient.segment<3>(15) + masses[5] * g + forces.col(1) + forces.col(2)).norm() < 1e-12);
    CHECK(dense_hessian(E, x, Projection::none).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("gravity and point loads scaled by a load factor (load steps): E and gradient scale with it",
          "[potentials][gravity][loads]")
{
    std::mt19937 rng(52);
    const Mesh mesh = box_of_tets(2, 1, 1, 0.5);
    const Eigen::VectorXd masses = lumped_masses(mesh, {1000.0});
    const Eigen::Vector3d g(0.3, -1.0, -9.81);
    auto gravity = std::make_shared<GravityPotential>(3, masses, g);
    Eigen::MatrixXd forces(3, 2);
    forces << 1, -2, 0, 5, -3, 1;
    auto loads = std::make_shared<PointLoadPotential>(3, mesh.num_nodes(), std::vector<int>{2, 7}, forces);
    TotalPotential E({gravity, loads});
    const Eigen::VectorXd x = rest_coordinates(mesh) + 0.1 * Eigen::VectorXd::Random(3 * mesh.num_nodes());
    const double full = E.value(x);
    const Eigen::VectorXd full_gradient = gradient_of(E, x);
    for (const double s : {0.0, 0.125, 0.5, 0.75, 1.0, 2.0}) {
        CAPTURE(s);
        gravity->set_scale(s);
        loads->set_scale(s);
        // E_s = −s Σ m_i g·x_i − s Σ f_k·x_(n_k): exactly s times the full load's.
        double expected = 0.0;
        for (int i = 0; i < mesh.num_nodes(); ++i)
            expected -= s * masses[i] * g.dot(x.segment<3>(3 * i));
        expected -= s * (forces.col(0).dot(x.segment<3>(6)) + forces.col(1).dot(x.segment<3>(21)));
        CHECK(E.value(x) == Approx(expected).epsilon(1e-14).margin(1e-14 * std::abs(full)));
        const Eigen::VectorXd gradient = gradient_of(E, x);
        CHECK((gradient - s * full_gradient).cwiseAbs().maxCoeff() <= 1e-14 * full_gradient.cwiseAbs().maxCoeff());
        if (s > 0.0)
            CHECK(relative_error(gradient, finite_difference_gradient(E, x, 1e-6)) < 1e-8);
        CHECK(dense_hessian(E, x, Projection::none).cwiseAbs().maxCoeff() == 0.0);
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(gravity->set_scale(nan), "gravity: scale is not finite");
    CHECK_THROWS_WITH(loads->set_scale(std::numeric_limits<double>::infinity()), "point loads: scale is not finite");
}

namespace {

/// Node positions scattered around the obstacle surface, even ones inside,
/// odd ones outside, each at least 1e-3 away from it (central differences
/// must not straddle the kink of the one-sided quadratic).
template <int Dim>
Eigen::VectorXd around(const AnalyticObstacle& obstacle, int count, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    Eigen::VectorXd x(Dim * count);
    for (int i = 0; i < count; ++i) {
        Eigen::Matrix<double, Dim, 1> p;
        double phi = 0.0;
        do {
            for (int k = 0; k < Dim; ++k)
                p[k] = 1.5 * u11(rng);
            if (const auto* plane = std::get_if<PlaneObstacle>(&obstacle))
                phi = (plane->normal.dot(p) - plane->offset) / plane->normal.norm();
            else
                phi = (p - std::get<SphereObstacle>(obstacle).center).norm() - std::get<SphereObstacle>(obstacle).radius;
        } while (std::abs(phi) < 1e-3 || (phi < 0.0) != (i % 2 == 0));
        x.segment<Dim>(Dim * i) = p;
    }
    return x;
}

template <int Dim>
void check_obstacle(const AnalyticObstacle& obstacle, std::mt19937& rng)
{
    const int count = 12;
    const double stiffness = 2e3;
    auto penalty = std::make_shared<ObstaclePenaltyPotential>(Dim, count, obstacle, stiffness);
    TotalPotential E({penalty});
    for (int sample = 0; sample < 4; ++sample) {
        CAPTURE(obstacle_kind(obstacle), Dim, sample);
        const Eigen::VectorXd x = around<Dim>(obstacle, count, rng);
        // E = Σ ε/2 δ² by the signed distance computed here.
        double expected = 0.0;
        int inside = 0;
        for (int i = 0; i < count; ++i) {
            const Eigen::Matrix<double, Dim, 1> p = x.segment<Dim>(Dim * i);
            const double phi =
                std::holds_alternative<PlaneObstacle>(obstacle)
                    ? (std::get<PlaneObstacle>(obstacle).normal.dot(p) - std::get<PlaneObstacle>(obstacle).offset) /
                          std::get<PlaneObstacle>(obstacle).normal.norm()
                    : (p - std::get<SphereObstacle>(obstacle).center).norm() - std::get<SphereObstacle>(obstacle).radius;
            if (phi < 0) {
                expected += 0.5 * stiffness * phi * phi;
                ++inside;
            }
        }
        REQUIRE(inside > 0);
        REQUIRE(inside < count);
        CHECK(E.value(x) == Approx(expected).epsilon(1e-13));
        const DerivativeErrors errors = derivative_errors(E, x);
        CAPTURE(errors.gradient, errors.hessian);
        CHECK(errors.gradient < 1e-7);
        CHECK(errors.hessian < 1e-7);
        const Eigen::MatrixXd projected = dense_hessian(E, x, Projection::clamp);
        CHECK(smallest_eigenvalue(projected) >= -1e-8 * projected.cwiseAbs().maxCoeff());
        if (std::holds_alternative<SphereObstacle>(obstacle))
            CHECK(smallest_eigenvalue(dense_hessian(E, x, Projection::none)) < 0.0);
    }
}

} // namespace

TEST_CASE("obstacle penalty (seed 000 §5.7): value, gradient, Hessian and projection, planes and spheres in 2D and 3D",
          "[potentials][obstacles]")
{
    std::mt19937 rng(52);
    check_obstacle<3>(PlaneObstacle{Eigen::Vector3d(1.0, 2.0, -0.5), 0.3}, rng);
    check_obstacle<3>(SphereObstacle{Eigen::Vector3d(0.1, -0.2, 0.3), 0.9}, rng);
    check_obstacle<2>(PlaneObstacle{Eigen::Vector2d(-1.0, 3.0), 0.2}, rng);
    check_obstacle<2>(SphereObstacle{Eigen::Vector2d(0.2, 0.1), 0.8}, rng);
}

TEST_CASE("obstacle penalty acts only on the listed nodes, and at a sphere's center the force vanishes",
          "[potentials][obstacles]")
{
    ObstaclePenaltyPotential floor(2, 3, PlaneObstacle{Eigen::Vector2d(0.0, 2.0), 0.0}, 10.0, {1});
    const Eigen::VectorXd x = (Eigen::VectorXd(6) << 0.0, -1.0, 0.0, -0.5, 0.0, -2.0).finished();
    CHECK(floor.value(x) == Approx(0.5 * 10.0 * 0.25));
    Eigen::VectorXd g = Eigen::VectorXd::Zero(6);
    floor.add_gradient(x, g);
    CHECK(g.isApprox((Eigen::VectorXd(6) << 0, 0, 0, -5.0, 0, 0).finished()));

    ObstaclePenaltyPotential ball(3, 1, SphereObstacle{Eigen::Vector3d(1, 1, 1), 0.5}, 10.0);
    const Eigen::VectorXd center = Eigen::Vector3d(1, 1, 1);
    CHECK(ball.value(center) == Approx(0.5 * 10.0 * 0.25));
    Eigen::VectorXd g3 = Eigen::VectorXd::Zero(3);
    ball.add_gradient(center, g3);
    CHECK(g3.norm() == 0.0);
}

TEST_CASE("total potential: +infinity, never NaN, at non-finite positions", "[potentials]")
{
    const Mesh mesh = box_of_tets(1, 1, 1, 1.0);
    auto elastic = std::make_shared<ElasticPotential>(
        mesh, std::vector<ElementModel>{make_element_model(mesh.kind, "stable-neo-hookean", {})});
    auto gravity =
        std::make_shared<GravityPotential>(3, lumped_masses(mesh, {1.0}), Eigen::Vector3d(0.0, 0.0, -9.81));
    auto ball = std::make_shared<ObstaclePenaltyPotential>(3, mesh.num_nodes(),
                                                           SphereObstacle{Eigen::Vector3d::Zero(), 0.1}, 1.0);
    Eigen::VectorXd x = rest_coordinates(mesh);
    x[4] = std::numeric_limits<double>::quiet_NaN();
    for (const std::shared_ptr<Potential>& term : std::vector<std::shared_ptr<Potential>>{elastic, gravity, ball}) {
        CAPTURE(term->name());
        TotalPotential E({term});
        CHECK(E.value(x) == std::numeric_limits<double>::infinity());
        CHECK(term->value(x) == std::numeric_limits<double>::infinity());
    }
}
