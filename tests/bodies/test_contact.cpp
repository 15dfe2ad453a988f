// Contact with rigid bodies (issue 32): the seed's penalty and the exact gap
// constraints pass the shared derivative check near faces, edges and
// vertices of surface bodies, inside and out; a ball pushed into a soft
// block is solved alike by every strategy that takes inequalities, with no
// node inside the body; the candidate set is refreshed between solves.
#include "sinew/bodies/surface_body.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/energies/constraints/body_gaps.hpp"
#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"
#include "sinew/energies/potentials/total_potential.hpp"
#include "sinew/mesh/face_mesh.hpp"
#include "sinew/mesh/icosphere.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/refreshed_solve.hpp"
#include "sinew/solvers/solver.hpp"

#include "bodies/body_surfaces.hpp"
#include "potentials/potential_checks.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <fstream>
#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

/// Points of the body frame in the regimes of a contact node, with the
/// closest feature each one must have: inside near a face, outside a face,
/// an edge and a vertex of the unit cube, and (on the L-shaped prism) inside
/// near its reflex edge, where the closest feature is the edge.
struct RegimePoint {
    Eigen::Vector3d x;
    SurfaceFeature feature;
    bool inside;
};

std::vector<RegimePoint> cube_regimes(std::mt19937& rng)
{
    std::uniform_real_distribution<double> spread(0.2, 0.8), depth(0.01, 0.2);
    std::vector<RegimePoint> points;
    for (int k = 0; k < 4; ++k) {
        points.push_back({{spread(rng), spread(rng), -depth(rng)}, SurfaceFeature::face, false});
        points.push_back({{spread(rng), spread(rng), depth(rng)}, SurfaceFeature::face, true});
        points.push_back({{1.0 + depth(rng), spread(rng), 1.0 + depth(rng)}, SurfaceFeature::edge, false});
        points.push_back({{-depth(rng), -depth(rng), -depth(rng)}, SurfaceFeature::vertex, false});
    }
    return points;
}

std::vector<RegimePoint> l_shape_regimes(std::mt19937& rng)
{
    std::uniform_real_distribution<double> along(0.15, 0.35), off(0.01, 0.06);
    std::vector<RegimePoint> points;
    for (int k = 0; k < 4; ++k)
        points.push_back({{0.5 - off(rng), 0.5 - off(rng), along(rng)}, SurfaceFeature::edge, true});
    return points;
}

/// The points as the nodes of a problem whose objective is the penalty and
/// whose constraints are the gaps (every node a row), body placed by R, t.
void check_contact_derivatives(const std::shared_ptr<const SurfaceBody>& surface,
                               const std::vector<RegimePoint>& regimes, const Eigen::Matrix3d& R,
                               const Eigen::Vector3d& t, ContactCurvature curvature)
{
    const int n = static_cast<int>(regimes.size());
    Eigen::MatrixXd nodes(3, n);
    for (int i = 0; i < n; ++i) {
        const SurfaceDistance d = surface->query(regimes[i].x);
        CAPTURE(i, regimes[i].x.transpose());
        REQUIRE(d.feature == regimes[i].feature);  // the sample is in the regime it stands for
        REQUIRE((d.distance < 0.0) == regimes[i].inside);
        nodes.col(i) = R * regimes[i].x + t;
    }
    auto body = std::make_shared<PlacedBody>(surface);
    body->set_placement(R, t);
    auto penalty = std::make_shared<ObstaclePenaltyPotential>(3, n, body, 3e2, std::vector<int>{}, curvature);
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(nodes.data(), nodes.size());
    QuasistaticOptions options;
    options.constraints = {std::make_shared<BodyGaps>(3, n, body, x, std::vector<int>{}, 2.0, 10.0)};
    QuasistaticProblem problem(nodes, std::make_shared<TotalPotential>(std::vector<std::shared_ptr<Potential>>{penalty}),
                               {}, options);
    REQUIRE(problem.num_constraints() == n);
    const DerivativeCheckReport report = check_derivatives(problem, x);
    CAPTURE(report.to_text());
    CHECK(report.passed(1e-5));
    CHECK(report.hessian.entries_compared > 0);

    TotalPotential E({penalty});
    const Eigen::MatrixXd projected = dense_hessian(E, x, Projection::clamp);
    CHECK(smallest_eigenvalue(projected) >= -1e-10 * projected.cwiseAbs().maxCoeff());
}

/// A soft block whose top is held, pushed up 0.08 m by a ball of radius 0.3
/// (analytic, or an icosphere surface), held off by gap constraints.
std::string ball_scene(const std::string& ball, const std::string& margin)
{
    return R"({"name": "ball-into-block",
      "mesh": {"generator": "box", "lower": [-0.5, -0.5, 0], "upper": [0.5, 0.5, 0.3], "cells": [6, 6, 2]},
      "materials": [{"model": "stable-neo-hookean", "parameters": {"mu": 1e4, "lambda": 4e4}}],
      "boundary": [{"name": "top", "select": {"plane": {"point": [0, 0, 0.3], "normal": [0, 0, 1]}}}],
      "bodies": [{"name": "ball", )" + ball + R"(, "translation": [0, 0, 0.08], "contact": "gaps")" + margin + R"(,
                  "select": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}}}]})";
}

struct ContactSolve {
    Result result;
    double energy = 0.0;
    double penetration = 0.0;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    Eigen::VectorXd positions;
};

ContactSolve solve_ball(const std::string& text, const std::string& solver, const SolverOptions& options = {})
{
    Scene scene = parse_scene(text, "ball-into-block.json");
    scene.apply_load_factor(1.0);
    ContactSolve out;
    out.result = solve_with_refreshed_rows(*scene.problem, solver, options);
    out.positions = scene.problem->full_configuration(out.result.x);
    const auto& gaps = dynamic_cast<const BodyGaps&>(*scene.constraints.at(0));
    out.energy = out.result.objective;
    out.penetration = gaps.max_penetration(out.positions);
    const int offset = scene.problem->constraint_offset(gaps);
    if (out.result.constraint_multipliers.size() > 0)
        out.force = gaps.total_force(out.positions,
                                     out.result.constraint_multipliers.segment(offset, gaps.num_constraints()));
    return out;
}

} // namespace

TEST_CASE("contact penalty and gap constraints pass the shared derivative check near faces, edges and vertices")
{
    std::mt19937 rng(32);
    const Eigen::Matrix3d turned = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const Eigen::Vector3d moved(0.3, -0.2, 0.5);
    const auto cube = std::make_shared<const SurfaceBody>(cube_surface(), "cube");
    const auto l_shape = std::make_shared<const SurfaceBody>(l_shaped_surface(), "L");
    for (const ContactCurvature curvature : {ContactCurvature::gauss_newton, ContactCurvature::projected}) {
        CAPTURE(to_string(curvature));
        check_contact_derivatives(cube, cube_regimes(rng), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(),
                                  curvature);
        check_contact_derivatives(cube, cube_regimes(rng), turned, moved, curvature);
        check_contact_derivatives(l_shape, l_shape_regimes(rng), turned, moved, curvature);
    }
}

TEST_CASE("the penalty's gradient derivatives in an affine placement match central differences of the gradient")
{
    // ∂(∇E)/∂(A, t) (the rig's lower teeth carried by the jaw map, which is a
    // rotation only at a solution): a ball and the L-shaped prism under a
    // map that is not a rotation, nodes inside near a face and a reflex edge
    // and outside (no term).
    const Eigen::Matrix3d A = (Eigen::Matrix3d() << 1.05, 0.08, -0.03, -0.06, 0.97, 0.04, 0.02, -0.05, 1.02).finished();
    const Eigen::Vector3d t(0.03, -0.02, 0.01);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> along(0.15, 0.35), off(0.01, 0.06);
    const std::vector<std::pair<std::shared_ptr<const CollisionBody>, std::vector<Eigen::Vector3d>>> cases{
        {analytic_body(SphereObstacle{Eigen::Vector3d(0.1, 0.2, 0.3), 0.5}, 3),
         {{0.3, 0.2, 0.5}, {0.1, -0.15, 0.35}, {0.1, 0.2, 0.9}}},
        {std::make_shared<const SurfaceBody>(l_shaped_surface(), "L"),
         {{0.5 - off(rng), 0.5 - off(rng), along(rng)}, {0.2, 0.2, 0.02}, {1.2, 0.3, 0.3}}}};
    for (const auto& [body, points] : cases) {
        CAPTURE(body->name());
        const int n = static_cast<int>(points.size());
        auto placed = std::make_shared<PlacedBody>(body);
        Eigen::VectorXd x(3 * n);
        for (int i = 0; i < n; ++i)
            x.segment<3>(3 * i) = A * points[static_cast<std::size_t>(i)] + t;
        auto gradient_at = [&](const Eigen::Matrix3d& map, const Eigen::Vector3d& shift) {
            placed->set_affine_placement(map, shift);
            ObstaclePenaltyPotential penalty(3, n, placed, 4e2);
            Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
            penalty.add_gradient(x, g);
            return g;
        };
        placed->set_affine_placement(A, t);
        const Eigen::MatrixXd analytic = ObstaclePenaltyPotential(3, n, placed, 4e2).placement_gradient_derivatives(x);
        REQUIRE(analytic.cwiseAbs().maxCoeff() > 0.0);
        const double h = 1e-6;
        for (int column = 0; column < 12; ++column) {
            CAPTURE(column);
            Eigen::Matrix3d dA = Eigen::Matrix3d::Zero();
            Eigen::Vector3d dt = Eigen::Vector3d::Zero();
            if (column < 9)
                dA(column / 3, column % 3) = h;
            else
                dt[column - 9] = h;
            const Eigen::VectorXd differenced = (gradient_at(A + dA, t + dt) - gradient_at(A - dA, t - dt)) / (2 * h);
            CHECK((analytic.col(column) - differenced).cwiseAbs().maxCoeff() <=
                  1e-6 * std::max(1.0, analytic.cwiseAbs().maxCoeff()));
        }
        CHECK(analytic.middleRows(3 * (n - 1), 3).isZero());  // the node outside adds nothing
    }
}

TEST_CASE("an affine placement is refused when singular, not finite or of a 2D body")
{
    PlacedBody ball(analytic_body(SphereObstacle{Eigen::Vector3d::Zero(), 1.0}, 3));
    Eigen::Matrix3d singular = Eigen::Matrix3d::Identity();
    singular(2, 2) = 0.0;
    CHECK_THROWS_AS(ball.set_affine_placement(singular, Eigen::Vector3d::Zero()), InputError);
    Eigen::Matrix3d not_finite = Eigen::Matrix3d::Identity();
    not_finite(0, 1) = std::nan("");
    CHECK_THROWS_AS(ball.set_affine_placement(not_finite, Eigen::Vector3d::Zero()), InputError);
    PlacedBody disk(analytic_body(SphereObstacle{Eigen::Vector2d::Zero(), 1.0}, 2));
    CHECK_THROWS_AS(disk.set_affine_placement(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()), InputError);
    // A stretch is accepted: φ is then the ball's distance in the body's frame.
    ball.set_affine_placement(2.0 * Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    CHECK(ball.distance(Eigen::Vector3d(4.0, 0.0, 0.0)).distance == Approx(1.0));
}

TEST_CASE("a node inside a reflex edge is pushed out through the edge")
{
    // At x = (½ − a, ½ − a, z) inside the L-shaped prism the closest point is
    // on the reflex edge x = y = ½: ρ = a√2, δ = ρ, ∇φ = (1, 1, 0)/√2, so
    // E = ε/2 · 2a² and the force ε δ ∇φ = ε a (1, 1, 0).
    auto body = std::make_shared<PlacedBody>(std::make_shared<const SurfaceBody>(l_shaped_surface(), "L"));
    ObstaclePenaltyPotential penalty(3, 1, body, 10.0);
    const double a = 0.03;
    const Eigen::VectorXd x = Eigen::Vector3d(0.5 - a, 0.5 - a, 0.25);
    CHECK(penalty.value(x) == Approx(0.5 * 10.0 * 2.0 * a * a));
    CHECK(penalty.max_penetration(x) == Approx(a * std::sqrt(2.0)));
    const Eigen::Vector3d f = penalty.total_force(x);
    CHECK(f.x() == Approx(10.0 * a).epsilon(1e-12));
    CHECK(f.y() == Approx(10.0 * a).epsilon(1e-12));
    CHECK(std::abs(f.z()) < 1e-12);
}

TEST_CASE("a ball pushed into a soft block: every strategy that takes inequalities agrees with Ipopt and no node enters the ball")
{
    const std::string scene = ball_scene(R"("sphere": {"center": [0, 0, -0.3], "radius": 0.3})", "");
    // Tolerances tight enough that "converged" pins the energy to 1e-8, and
    // bounds kept exact: at their default Ipopt and interior-point relax each
    // bound by 1e-8 (bound_relax_factor), which lets the active nodes sit
    // 1e-8·L inside and moves the energy by Σ|λ_i|·1e-8 ≈ 5e-7 relative here.
    SolverOptions tight;
    tight.tolerance = 1e-10;
    tight.kkt_tolerance = 1e-9;
    SolverOptions exact = tight;
    exact.backend["bound_relax_factor"] = "0";
    const ContactSolve ipopt = solve_ball(scene, "ipopt", exact);
    REQUIRE(ipopt.result.status == Status::converged);
    const double size = std::sqrt(1.0 + 1.0 + 0.09);
    CHECK(ipopt.penetration <= 1e-12 * size);
    CHECK(ipopt.force.z() > 0.0);
    for (const std::string solver : {"interior-point", "augmented-lagrangian", "penalty"}) {
        CAPTURE(solver);
        // A penalty meets an energy gap κ/2‖c − P(c)‖² ≤ 1e-9·|f| only past κ = 1e13.
        SolverOptions options = solver == "interior-point" ? exact : tight;
        if (solver == "penalty")
            options.backend["max_kappa"] = "1e16";
        const ContactSolve s = solve_ball(scene, solver, options);
        REQUIRE(s.result.status == Status::converged);
        CHECK(s.penetration <= 1e-6 * size);  // the default constraint tolerance on rows φ/L
        const double gap = std::abs(s.energy - ipopt.energy) / std::abs(ipopt.energy);
        CAPTURE(s.energy, ipopt.energy, gap);
        CHECK(gap <= 1e-8);
        CHECK((s.positions - ipopt.positions).cwiseAbs().maxCoeff() <= 1e-5 * size);
    }
}

TEST_CASE("a surface body gives the answer of the analytic ball it approximates, to its faceting")
{
    SolverOptions tight;
    tight.tolerance = 1e-10;
    tight.kkt_tolerance = 1e-9;
    const ContactSolve analytic = solve_ball(ball_scene(R"("sphere": {"center": [0, 0, -0.3], "radius": 0.3})", ""),
                                             "interior-point", tight);
    const ContactSolve faceted = solve_ball(
        ball_scene(R"("surface": {"generator": "icosphere", "center": [0, 0, -0.3], "radius": 0.3, "subdivisions": 5})",
                   ""),
        "interior-point", tight);
    REQUIRE(analytic.result.status == Status::converged);
    REQUIRE(faceted.result.status == Status::converged);
    // The icosphere's faces lie within r(1 − cos θ) ≈ 2e-4 m of the sphere (edge angle θ ≈ 0.037 at 5 subdivisions).
    CHECK((faceted.positions - analytic.positions).cwiseAbs().maxCoeff() < 1e-3);
    CHECK(faceted.force.z() == Approx(analytic.force.z()).epsilon(0.02));
    const ContactSolve ipopt = solve_ball(
        ball_scene(R"("surface": {"generator": "icosphere", "center": [0, 0, -0.3], "radius": 0.3, "subdivisions": 5})",
                   ""),
        "ipopt", tight);
    REQUIRE(ipopt.result.status == Status::converged);
    CHECK(std::abs(faceted.energy - ipopt.energy) <= 1e-8 * std::abs(ipopt.energy));
}

TEST_CASE("augmented-lagrangian on a faceted ball ends in a few hundred iterations at the answer of Ipopt")
{
    // A node the multiplier method leaves a hair inside a faceted body sits
    // where φ is not smooth (the distance inside a polyhedron has a ridge at
    // every convex edge); its subproblems used to take Newton steps there
    // until the iteration limit (3000 on block-on-sphere). Projected
    // Newton's stagnation watch ends such a subproblem and the outer loop
    // keeps the point when it is feasible, its multipliers settled and its
    // KKT residual within tolerance.
    const std::string scene = ball_scene(
        R"("surface": {"generator": "icosphere", "center": [0, 0, -0.3], "radius": 0.3, "subdivisions": 4})", "");
    SolverOptions tight;
    tight.tolerance = 1e-10;
    tight.kkt_tolerance = 1e-9;
    const ContactSolve ipopt = solve_ball(scene, "ipopt", tight);
    REQUIRE(ipopt.result.status == Status::converged);
    const ContactSolve al = solve_ball(scene, "augmented-lagrangian");
    CAPTURE(al.result.message, al.result.iterations);
    CHECK(al.result.status == Status::converged);
    CHECK(al.result.iterations < 500);
    const double size = std::sqrt(1.0 + 1.0 + 0.09);
    CHECK(al.penetration <= 1e-6 * size);
    // Feasible to 1e-6 of the size with the contact force Σ|λ| ≈ 10² N: the
    // energies agree to what that penetration moves them by.
    CHECK(std::abs(al.energy - ipopt.energy) <= 1e-6 * std::abs(ipopt.energy));
}

TEST_CASE("the contact candidate set is refreshed between solves: margin 0 gives the answer of a wide margin")
{
    const std::string ball = R"("sphere": {"center": [0, 0, -0.3], "radius": 0.3})";
    const ContactSolve wide = solve_ball(ball_scene(ball, R"(, "margin": 1)"), "interior-point");
    const ContactSolve tight = solve_ball(ball_scene(ball, R"(, "margin": 0)"), "interior-point");
    REQUIRE(wide.result.status == Status::converged);
    REQUIRE(tight.result.status == Status::converged);
    CHECK(tight.result.statistics.at("constraint_rounds") >= 1);
    CHECK((tight.positions - wide.positions).cwiseAbs().maxCoeff() < 1e-7);
}

TEST_CASE("the face pressed against its skull: its lips enter the bone without the skull and stay out with it")
{
    // Scene face-on-skull, solved as it is and without its "bodies": the
    // contracting muscles press the lips and cheeks into the maxilla and
    // upper teeth 0.5 mm below them, which the seed's penalty holds them off.
    std::ifstream file(std::string(SINEW_SOURCE_DIR) + "/scenes/face-on-skull.json");
    const nlohmann::json scene_json = nlohmann::json::parse(file);
    FaceShape shape;
    shape.target_tets = scene_json["mesh"]["target_tets"].get<int>();
    const SurfaceBody skull(generate_face_skull(shape), "skull");
    double depth_with = 0.0, depth_without = 0.0;
    for (const bool with_skull : {false, true}) {
        CAPTURE(with_skull);
        nlohmann::json text = scene_json;
        if (!with_skull)
            text.erase("bodies");
        Scene scene = parse_scene(text.dump(), "face-on-skull.json");
        scene.apply_load_factor(1.0);
        const Result result = solve(*scene.problem, "projected-newton", SolverOptions{});
        REQUIRE(result.status == Status::converged);
        const Eigen::VectorXd x = scene.problem->full_configuration(result.x);
        const auto& sets = scene.mesh.node_sets;
        const auto contact = std::find_if(sets.begin(), sets.end(), [](const auto& s) { return s.first == "skull_contact"; });
        REQUIRE(contact != sets.end());
        double deepest = 0.0;
        for (const int node : contact->second)
            deepest = std::max(deepest, -skull.query(x.segment<3>(3 * node)).distance);
        (with_skull ? depth_with : depth_without) = deepest;
    }
    CAPTURE(depth_with, depth_without);
    CHECK(depth_without > 1e-4);           // more than 0.1 mm into the bone
    CHECK(depth_with < 0.05 * depth_without);  // held off, to the penalty's depth
}
