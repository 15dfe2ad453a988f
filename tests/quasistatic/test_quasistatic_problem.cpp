#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/gravity_potential.hpp"
#include "sinew/energies/potentials/lumped_mass.hpp"
#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"
#include "sinew/energies/potentials/point_load_potential.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/solvers/solver.hpp"

#include "potentials/potential_checks.hpp"
#include "potentials/test_meshes.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace sinew;
using namespace sinew::test;
using Catch::Contains;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A bar of 2 × 2 × nz cells of side h along z: nodes of the face z = 0 and
/// of the face z = nz·h.
std::vector<int> face_nodes(int nx, int ny, int k)
{
    std::vector<int> nodes;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            nodes.push_back(grid_node(i, j, k, nx, ny));
    return nodes;
}

/// The rotation by `angle` about the bar's axis (x, y) = (1, 1)·h as an
/// affine map x = M X + t.
std::pair<Eigen::Matrix3d, Eigen::Vector3d> twist(double angle, double h)
{
    const Eigen::Matrix3d M = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d axis(h, h, 0.0);
    return {M, axis - M * axis};
}

/// The bar of the tests: stable Neo-Hookean, gravity, two point loads and a
/// ball pressed into its side.
std::shared_ptr<TotalPotential> bar_potential(const Mesh& mesh)
{
    auto elastic = std::make_shared<ElasticPotential>(
        mesh, std::vector<ElementModel>{make_element_model(mesh.kind, "stable-neo-hookean", {})});
    auto gravity = std::make_shared<GravityPotential>(3, lumped_masses(mesh, {1000.0}), Eigen::Vector3d(0, -9.81, 0));
    Eigen::MatrixXd forces(3, 2);
    forces << 5.0, -2.0, 0.0, 3.0, 1.0, 0.0;
    auto loads = std::make_shared<PointLoadPotential>(3, mesh.num_nodes(), std::vector<int>{4, 13}, forces);
    auto ball = std::make_shared<ObstaclePenaltyPotential>(
        3, mesh.num_nodes(), SphereObstacle{Eigen::Vector3d(1.3, 0.5, 0.75), 0.5}, 1e5);
    return std::make_shared<TotalPotential>(std::vector<std::shared_ptr<Potential>>{elastic, gravity, loads, ball});
}

struct Bar {
    Mesh mesh = box_of_tets(2, 2, 3, 0.5);
    std::shared_ptr<TotalPotential> potential = bar_potential(mesh);
    std::vector<DirichletSet> dirichlet() const
    {
        const auto [M, t] = twist(0.2, 0.5);
        return {fixed_at_rest("bottom", face_nodes(2, 2, 0), 3), DirichletSet{"top", face_nodes(2, 2, 3), M, t}};
    }
};

QuasistaticOptions with_strategy(DirichletStrategy strategy)
{
    QuasistaticOptions options;
    options.dirichlet = strategy;
    return options;
}

} // namespace

TEST_CASE("quasistatic NLP: derivatives pass check_derivatives for both Dirichlet strategies",
          "[quasistatic][derivatives]")
{
    Bar bar;
    std::mt19937 rng(61);
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    for (DirichletStrategy strategy : {DirichletStrategy::eliminate, DirichletStrategy::equality_constraints}) {
        CAPTURE(to_string(strategy));
        QuasistaticProblem nlp(bar.mesh.nodes, bar.potential, bar.dirichlet(), with_strategy(strategy));
        Eigen::VectorXd x = nlp.starting_point();
        for (int i = 0; i < x.size(); ++i)
            x[i] += 0.05 * u11(rng);
        REQUIRE(std::isfinite(nlp.objective(x)));
        const DerivativeCheckReport report = check_derivatives(nlp, x);
        CAPTURE(report.to_text());
        CHECK(report.passed(1e-5));
        CHECK(report.gradient.entries_compared == nlp.num_variables());
        CHECK(report.hessian.entries_compared > 0);
        if (strategy == DirichletStrategy::equality_constraints)
            CHECK(report.jacobian.entries_compared > 0);
    }
}

TEST_CASE("quasistatic NLP: elimination and equality constraints give the same objective, gradient and Hessian "
          "at the same full configuration",
          "[quasistatic][strategies]")
{
    Bar bar;
    QuasistaticProblem eliminated(bar.mesh.nodes, bar.potential, bar.dirichlet(),
                                  with_strategy(DirichletStrategy::eliminate));
    QuasistaticProblem constrained(bar.mesh.nodes, bar.potential, bar.dirichlet(),
                                   with_strategy(DirichletStrategy::equality_constraints));
    const int n_full = 3 * bar.mesh.num_nodes();
    const int n_prescribed = 3 * 2 * 9;
    REQUIRE(eliminated.num_variables() == n_full - n_prescribed);
    REQUIRE(eliminated.num_constraints() == 0);
    REQUIRE(constrained.num_variables() == n_full);
    REQUIRE(constrained.num_constraints() == n_prescribed);
    CHECK(capabilities_of(eliminated).unconstrained());
    CHECK(capabilities_of(constrained).num_equalities == n_prescribed);

    std::mt19937 rng(62);
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    Eigen::VectorXd full = eliminated.prescribed_configuration();
    for (int i = 0; i < full.size(); ++i)
        full[i] += 0.05 * u11(rng);
    // The same full configuration: the prescribed coordinates at their values.
    const Eigen::VectorXd x_free = eliminated.variables_of(full);
    const Eigen::VectorXd x_all = eliminated.full_configuration(x_free);
    CHECK(constrained.variables_of(x_all) == x_all);

    CHECK(eliminated.objective(x_free) == constrained.objective(x_all));
    Eigen::VectorXd g_free(eliminated.num_variables()), g_all(constrained.num_variables());
    eliminated.gradient(x_free, g_free);
    constrained.gradient(x_all, g_all);
    CHECK(eliminated.variables_of(g_all) == g_free);

    Eigen::VectorXd c(constrained.num_constraints());
    constrained.constraints(x_all, c);
    CHECK(c.cwiseAbs().maxCoeff() == 0.0);
    Eigen::VectorXd jacobian(constrained.jacobian_pattern().nonzeros());
    constrained.jacobian_values(x_all, jacobian);
    CHECK(jacobian.size() == n_prescribed);
    CHECK((jacobian.array() == 1.0).all());

    // The eliminated Hessian is the constrained one restricted to the free
    // coordinates, entry for entry; σ scales it.
    const Eigen::VectorXd no_lambda = Eigen::VectorXd::Zero(constrained.num_constraints());
    Eigen::VectorXd h_free(eliminated.hessian_pattern().nonzeros()), h_all(constrained.hessian_pattern().nonzeros());
    eliminated.hessian(x_free, 2.0, Eigen::VectorXd(), Projection::none, h_free);
    constrained.hessian(x_all, 2.0, no_lambda, Projection::none, h_all);
    // Free coordinate of each NLP variable: variables_of picks them from a
    // vector of coordinate indices.
    const Eigen::VectorXd free_ids = eliminated.variables_of(Eigen::VectorXd::LinSpaced(n_full, 0, n_full - 1));
    std::vector<int> free_index(n_full, -1);
    for (int k = 0; k < free_ids.size(); ++k)
        free_index[static_cast<int>(free_ids[k])] = k;
    Eigen::MatrixXd dense_free = Eigen::MatrixXd::Zero(eliminated.num_variables(), eliminated.num_variables());
    for (int k = 0; k < h_free.size(); ++k)
        dense_free(eliminated.hessian_pattern().rows[k], eliminated.hessian_pattern().cols[k]) = h_free[k];
    int matched = 0;
    for (int k = 0; k < h_all.size(); ++k) {
        const int r = free_index[constrained.hessian_pattern().rows[k]];
        const int col = free_index[constrained.hessian_pattern().cols[k]];
        if (r >= 0 && col >= 0) {
            CHECK(dense_free(r, col) == h_all[k]);
            ++matched;
        }
    }
    CHECK(matched == eliminated.hessian_pattern().nonzeros());
}

TEST_CASE("quasistatic NLP: projected Hessian offered and PSD, exact Hessian indefinite under the ball",
          "[quasistatic][projection]")
{
    Bar bar;
    QuasistaticProblem nlp(bar.mesh.nodes, bar.potential, bar.dirichlet());
    REQUIRE(nlp.supports(Projection::clamp));
    std::mt19937 rng(63);
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    Eigen::VectorXd x = nlp.starting_point();
    for (int i = 0; i < x.size(); ++i)
        x[i] += 0.1 * u11(rng);
    const int n = nlp.num_variables();
    auto dense = [&](const Eigen::VectorXd& values) {
        Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
        for (int k = 0; k < values.size(); ++k) {
            H(nlp.hessian_pattern().rows[k], nlp.hessian_pattern().cols[k]) += values[k];
            if (nlp.hessian_pattern().rows[k] != nlp.hessian_pattern().cols[k])
                H(nlp.hessian_pattern().cols[k], nlp.hessian_pattern().rows[k]) += values[k];
        }
        return H;
    };
    Eigen::VectorXd values(nlp.hessian_pattern().nonzeros());
    nlp.hessian(x, 1.0, Eigen::VectorXd(), Projection::clamp, values);
    const Eigen::MatrixXd projected = dense(values);
    CHECK(smallest_eigenvalue(projected) >= -1e-8 * projected.cwiseAbs().maxCoeff());
    nlp.hessian(x, 1.0, Eigen::VectorXd(), Projection::none, values);
    const Eigen::MatrixXd exact = dense(values);
    CHECK(smallest_eigenvalue(exact) < 0.0);
}

TEST_CASE("quasistatic NLP: a face turned by 90° starts from the rest state of the free nodes, and steps of 30° solve",
          "[quasistatic][start]")
{
    const int nz = 3;
    const double h = 0.5;
    const Mesh mesh = box_of_tets(2, 2, nz, h);
    auto potential = std::make_shared<TotalPotential>(std::vector<std::shared_ptr<Potential>>{
        std::make_shared<ElasticPotential>(
            mesh, std::vector<ElementModel>{make_element_model(mesh.kind, "stable-neo-hookean", {})})});
    const auto [M90, t90] = twist(0.5 * kPi, h);
    const std::vector<int> top = face_nodes(2, 2, nz);
    QuasistaticProblem nlp(mesh.nodes, potential,
                           {fixed_at_rest("bottom", face_nodes(2, 2, 0), 3), DirichletSet{"top", top, M90, t90}});

    const Eigen::VectorXd start = nlp.full_configuration(nlp.starting_point());
    const Eigen::VectorXd rest = rest_coordinates(mesh);
    std::vector<bool> on_top(mesh.num_nodes(), false);
    for (int node : top)
        on_top[node] = true;
    for (int node = 0; node < mesh.num_nodes(); ++node) {
        const Eigen::Vector3d expected =
            on_top[node] ? Eigen::Vector3d(M90 * mesh.nodes.col(node) + t90) : Eigen::Vector3d(mesh.nodes.col(node));
        CHECK((start.segment<3>(3 * node) - expected).norm() < 1e-15);
    }
    CHECK(std::isfinite(nlp.objective(nlp.starting_point())));

    // The same motion in steps of 30°, each solve starting from the last.
    SolverOptions options;
    options.tolerance = 1e-9;
    for (int step = 1; step <= 3; ++step) {
        CAPTURE(step);
        const auto [M, t] = twist(step * kPi / 6.0, h);
        nlp.set_affine_map(1, M, t);
        const Result result = solve(nlp, "ipopt", options);
        REQUIRE(result.status == Status::converged);
        nlp.set_starting_configuration(nlp.full_configuration(result.x));
    }
    // The top face is where the map puts it, and the free nodes followed the twist.
    const Eigen::VectorXd final_state = nlp.full_configuration(nlp.starting_point());
    for (int node : top)
        CHECK((final_state.segment<3>(3 * node) - start.segment<3>(3 * node)).norm() < 1e-12);
    double largest_free_motion = 0.0;
    for (int node = 0; node < mesh.num_nodes(); ++node)
        if (!on_top[node])
            largest_free_motion = std::max(largest_free_motion, (final_state - rest).segment<3>(3 * node).norm());
    CHECK(largest_free_motion > 0.1 * h);
}

TEST_CASE("quasistatic NLP: set_affine_map moves the prescribed values, keeps the patterns", "[quasistatic]")
{
    Bar bar;
    QuasistaticProblem nlp(bar.mesh.nodes, bar.potential, bar.dirichlet());
    const int nonzeros = nlp.hessian_pattern().nonzeros();
    const Eigen::Vector3d shift(0.0, 0.0, 0.3);
    nlp.set_affine_map(0, Eigen::Matrix3d::Identity(), shift);
    const Eigen::VectorXd full = nlp.full_configuration(nlp.starting_point());
    for (int node : face_nodes(2, 2, 0))
        CHECK((full.segment<3>(3 * node) - (bar.mesh.nodes.col(node) + shift)).norm() < 1e-15);
    CHECK(nlp.hessian_pattern().nonzeros() == nonzeros);
    // A rejected map changes nothing.
    Eigen::Matrix3d bad = Eigen::Matrix3d::Identity();
    bad(1, 2) = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(nlp.set_affine_map(0, bad, shift), Contains("'bottom'") && Contains("M(1,2)"));
    CHECK(nlp.full_configuration(nlp.starting_point()) == full);
    CHECK_THROWS_WITH(nlp.set_affine_map(2, bad, shift), Contains("Dirichlet set 2 does not exist"));
}

TEST_CASE("quasistatic NLP: bad Dirichlet data is refused, naming it", "[quasistatic][input]")
{
    Bar bar;
    const auto make = [&](std::vector<DirichletSet> sets) { QuasistaticProblem(bar.mesh.nodes, bar.potential, sets); };
    const double nan = std::numeric_limits<double>::quiet_NaN();

    CHECK_THROWS_WITH(make({fixed_at_rest("pins", {0, 1, 36}, 3)}),
                      Contains("Dirichlet set 0 ('pins')") && Contains("node 36 is outside [0, 36)"));
    CHECK_THROWS_WITH(make({fixed_at_rest("pins", {-1}, 3)}), Contains("node -1"));
    CHECK_THROWS_WITH(make({fixed_at_rest("pins", {3, 3}, 3)}), Contains("node 3 is listed twice"));
    CHECK_THROWS_WITH(make({fixed_at_rest("a", {1, 2}, 3), fixed_at_rest("b", {2, 5}, 3)}),
                      Contains("node 2 is in both Dirichlet set 0 ('a') and Dirichlet set 1 ('b')"));
    Eigen::Matrix3d M = Eigen::Matrix3d::Identity();
    M(2, 0) = nan;
    CHECK_THROWS_WITH(make({DirichletSet{"jaw", {1}, M, Eigen::Vector3d::Zero()}}),
                      Contains("'jaw'") && Contains("M(2,0) is not finite"));
    CHECK_THROWS_WITH(make({DirichletSet{"jaw", {1}, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, nan, 0)}}),
                      Contains("t(1) is not finite"));
    CHECK_THROWS_WITH(make({DirichletSet{"jaw", {1}, Eigen::Matrix2d::Identity(), Eigen::Vector3d::Zero()}}),
                      Contains("map M is 2x2, expected 3x3"));
    std::vector<int> all(bar.mesh.num_nodes());
    for (int i = 0; i < bar.mesh.num_nodes(); ++i)
        all[i] = i;
    CHECK_THROWS_WITH(make({fixed_at_rest("everything", all, 3)}), Contains("nothing to solve"));
    CHECK_THROWS_WITH(QuasistaticProblem(Eigen::MatrixXd::Zero(3, 5), bar.potential, {}),
                      Contains("rest positions are 3x5"));
    CHECK_THROWS_WITH(QuasistaticProblem(bar.mesh.nodes, nullptr, {}), Contains("no potential"));
    QuasistaticProblem nlp(bar.mesh.nodes, bar.potential, {});
    CHECK_THROWS_WITH(nlp.set_starting_configuration(Eigen::VectorXd::Constant(108, nan)), Contains("not finite"));
}
