// Rigid bodies on MPM's grid (issues 32 and 33): the same bodies the meshes'
// contact terms see hold the nodes inside them to their condition relative
// to their velocity; a block dropped on a ball does not pass into it, and a
// rising floor lifts a block resting in the air.
#include "sinew/bodies/analytic_obstacle.hpp"
#include "sinew/energies/models/model_catalog.hpp"
#include "sinew/mpm/explicit_step.hpp"
#include "sinew/mpm/particle_measures.hpp"
#include "sinew/mpm/particle_sampling.hpp"

#include <catch2/catch.hpp>

using namespace sinew;

namespace {

std::shared_ptr<PlacedBody> ball(const Eigen::Vector3d& center, double radius)
{
    Eigen::VectorXd c = center;
    return std::make_shared<PlacedBody>(analytic_body(SphereObstacle{c, radius}, 3));
}

std::shared_ptr<PlacedBody> floor_plane(double height)
{
    Eigen::VectorXd n = Eigen::Vector3d::UnitZ();
    return std::make_shared<PlacedBody>(analytic_body(PlaneObstacle{n, height}, 3));
}

/// The velocity a node at x with velocity v keeps under one collider.
Eigen::Vector3d after_collider(const GridCollider<3>& collider, const Eigen::Vector3i& node, const Eigen::Vector3d& v)
{
    SparseGrid<3> grid(0.1);
    const auto slot = static_cast<std::size_t>(grid.touch(node));
    grid.mass[slot] = 1.0;
    grid.velocity[slot] = v;
    apply_colliders<3>({collider}, grid);
    return grid.velocity[slot];
}

Particles<3> falling_block(const Eigen::Vector3d& lower, const Eigen::Vector3d& velocity)
{
    LatticeSampling<3> sampling;
    sampling.dx = 0.1;
    sampling.velocity = velocity;
    return sample_box<3>(lower, lower + Eigen::Vector3d(0.4, 0.4, 0.4), sampling);
}

} // namespace

TEST_CASE("grid colliders: nodes inside a moving ball take its condition relative to its velocity")
{
    GridCollider<3> collider;
    collider.body = ball(Eigen::Vector3d::Zero(), 1.0);
    collider.thickness = 0.5;  // z = 1.1 is a cell out: beyond the band
    collider.velocity = Eigen::Vector3d(0.0, 0.0, 2.0);
    const Eigen::Vector3i inside(0, 0, 9);  // z = 0.9: n = e_z
    const Eigen::Vector3i outside(0, 0, 11);
    const Eigen::Vector3d v(1.0, 0.5, -1.0);  // approaching: (v − v_b)·n = −3
    collider.condition = GridCondition::sticky;
    CHECK(after_collider(collider, inside, v) == collider.velocity);
    CHECK(after_collider(collider, outside, v) == v);
    collider.condition = GridCondition::slip;
    CHECK(after_collider(collider, inside, v).isApprox(Eigen::Vector3d(1.0, 0.5, 2.0)));
    collider.condition = GridCondition::separate;
    CHECK(after_collider(collider, inside, v).isApprox(Eigen::Vector3d(1.0, 0.5, 2.0)));
    const Eigen::Vector3d leaving(1.0, 0.5, 3.0);  // (v − v_b)·n = 1 > 0
    CHECK(after_collider(collider, inside, leaving) == leaving);
    // The centre of a ball, where ∇φ vanishes, moves with the ball.
    CHECK(after_collider(collider, Eigen::Vector3i::Zero(), v) == collider.velocity);
}

TEST_CASE("grid colliders: a turning collider holds a node at the velocity of its point there, v + omega x (x - c)")
{
    GridCollider<3> collider;
    collider.body = ball(Eigen::Vector3d(0.5, 0.0, 0.0), 2.0);
    collider.velocity = Eigen::Vector3d(0.1, -0.2, 0.3);
    collider.angular_velocity = Eigen::Vector3d(0.5, -1.0, 2.0);
    collider.center = Eigen::Vector3d(0.2, 0.1, -0.3);
    collider.condition = GridCondition::sticky;
    const Eigen::Vector3i node(3, -4, 7);  // x = (0.3, −0.4, 0.7), inside the ball
    const Eigen::Vector3d x = 0.1 * node.cast<double>();
    const Eigen::Vector3d expected = collider.velocity + collider.angular_velocity.cross(x - collider.center);
    CHECK((after_collider(collider, node, Eigen::Vector3d(5.0, 5.0, 5.0)) - expected).norm() < 1e-15);
    CHECK((collider.velocity_at(collider.center) - collider.velocity).norm() == 0.0);
    GridCollider<2> flat;  // 2D: ω about z
    flat.angular_velocity = Eigen::Vector3d(0.0, 0.0, 3.0);
    flat.center = Eigen::Vector2d(1.0, 1.0);
    CHECK((flat.velocity_at(Eigen::Vector2d(2.0, 1.0)) - Eigen::Vector2d(0.0, 3.0)).norm() < 1e-15);
}

TEST_CASE("grid colliders: a block dropped on a ball does not pass into it")
{
    const auto model = make_model<3, 3>("fixed-corotated", ParameterValues{{"mu", 1e4}, {"lambda", 2e4}});
    const std::vector<const Model3d*> models{model.get()};
    const Eigen::Vector3d center(1.2, 1.2, 0.5);
    const double radius = 0.3;
    Particles<3> particles = falling_block(Eigen::Vector3d(1.0, 1.0, 1.0), Eigen::Vector3d(0.0, 0.0, -1.0));
    MpmStepSettings<3> settings;
    settings.time_step = 1e-3;
    settings.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
    settings.colliders.push_back({ball(center, radius), GridCondition::separate, Eigen::Vector3d::Zero(), 1.0});
    SparseGrid<3> grid(0.1);
    const double mass = total_mass(particles);
    double deepest = -1e300, fastest_up = 0.0;  // deepest: max over particles and steps of r − |x − c|
    for (int n = 0; n < 500; ++n) {
        REQUIRE(explicit_step(particles, models, settings, grid).failure.empty());
        for (const auto& x : particles.x)
            deepest = std::max(deepest, radius - (x - center).norm());
        fastest_up = std::max(fastest_up, linear_momentum(particles).z() / mass);
    }
    CAPTURE(deepest, fastest_up);
    CHECK(deepest < 0.0);      // no particle entered the ball
    CHECK(fastest_up > 0.5);  // the ball turned the block back up
}

TEST_CASE("grid colliders: a rising floor lifts a block and carries it at its own speed")
{
    const auto model = make_model<3, 3>("fixed-corotated", ParameterValues{{"mu", 1e4}, {"lambda", 2e4}});
    const std::vector<const Model3d*> models{model.get()};
    Particles<3> particles = falling_block(Eigen::Vector3d(1.0, 1.0, 1.0), Eigen::Vector3d::Zero());
    const auto floor = floor_plane(0.6);
    const double rise = 0.5;  // m/s
    MpmStepSettings<3> settings;
    settings.time_step = 1e-3;
    settings.colliders.push_back({floor, GridCondition::sticky, Eigen::Vector3d(0.0, 0.0, rise), 1.0});
    SparseGrid<3> grid(0.1);
    const double mass = total_mass(particles);
    for (int n = 1; n <= 1600; ++n) {
        REQUIRE(explicit_step(particles, models, settings, grid).failure.empty());
        floor->set_placement(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, rise * n * settings.time_step));
    }
    // By 1.6 s the floor (from 0.6 to 1.4) has reached the block at 1.0 and pushed it for 1.2 s.
    const double v_z = linear_momentum(particles).z() / mass;
    double lowest = 1e300;
    for (const auto& x : particles.x)
        lowest = std::min(lowest, x.z());
    CAPTURE(v_z, lowest);
    CHECK(v_z > 0.5 * rise);
    CHECK(lowest > 0.6 + rise * 1.6 - 0.1);  // above the floor but for a cell
}

TEST_CASE("grid colliders: a block dropped on a box bounces off its top face, not into it")
{
    const auto model = make_model<3, 3>("fixed-corotated", ParameterValues{{"mu", 1e4}, {"lambda", 2e4}});
    const std::vector<const Model3d*> models{model.get()};
    Particles<3> particles = falling_block(Eigen::Vector3d(1.0, 1.0, 1.0), Eigen::Vector3d::Zero());
    // A table 0.5 m high under the block, wider than it.
    Eigen::VectorXd lower = Eigen::Vector3d(0.8, 0.8, 0.0), upper = Eigen::Vector3d(1.6, 1.6, 0.5);
    const auto table = std::make_shared<PlacedBody>(analytic_body(BoxObstacle{lower, upper}, 3));
    MpmStepSettings<3> settings;
    settings.time_step = 1e-3;
    settings.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
    settings.colliders.push_back({table, GridCondition::separate, Eigen::Vector3d::Zero(), 1.0});
    SparseGrid<3> grid(0.1);
    const double mass = total_mass(particles);
    double lowest = 1e300, fastest_up = 0.0;
    for (int n = 0; n < 1000; ++n) {
        REQUIRE(explicit_step(particles, models, settings, grid).failure.empty());
        for (const auto& x : particles.x)
            lowest = std::min(lowest, x.z());
        fastest_up = std::max(fastest_up, linear_momentum(particles).z() / mass);
    }
    CAPTURE(lowest, fastest_up);
    CHECK(lowest > 0.5);        // never below the table's top
    CHECK(lowest < 0.75);       // it fell 0.25 m onto it
    CHECK(fastest_up > 0.5);    // and the top face turned it back up (it arrived at 2.2 m/s)
}
