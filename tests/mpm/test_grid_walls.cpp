// Walls on MPM's grid (issue 33): each condition on a node by a wall, and a
// block dropped with a sideways velocity onto a separating floor: the floor
// turns it back without letting it through, and it keeps its sideways
// momentum.
#include "mpm/particle_clouds.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/model_catalog.hpp"
#include "sinew/mpm/explicit_step.hpp"
#include "sinew/mpm/particle_measures.hpp"

#include <catch2/catch.hpp>

using namespace sinew;

namespace {

/// The velocity a node by the floor z = 0 keeps under `condition`.
Eigen::Vector3d after_floor(GridCondition condition, const Eigen::Vector3d& v)
{
    SparseGrid<3> grid(0.1);
    const int slot = grid.touch(Eigen::Vector3i(5, 5, 1));  // 0.1 above the floor, within the band
    grid.mass[static_cast<std::size_t>(slot)] = 1.0;
    grid.velocity[static_cast<std::size_t>(slot)] = v;
    GridWalls<3> walls = GridWalls<3>::box(Eigen::Vector3d::Constant(-10.0), Eigen::Vector3d::Constant(10.0),
                                           GridCondition::sticky);
    walls.lower.z() = 0.0;
    walls.condition[2][0] = condition;
    apply_walls(walls, grid);
    return grid.velocity[static_cast<std::size_t>(slot)];
}

} // namespace

TEST_CASE("grid walls: sticky stops, slip drops the normal part, separate drops it only towards the wall")
{
    const Eigen::Vector3d towards(0.3, -0.2, -1.0), away(0.3, -0.2, 1.0);
    CHECK(after_floor(GridCondition::sticky, towards).isZero());
    CHECK(after_floor(GridCondition::sticky, away).isZero());
    CHECK(after_floor(GridCondition::slip, towards) == Eigen::Vector3d(0.3, -0.2, 0.0));
    CHECK(after_floor(GridCondition::slip, away) == Eigen::Vector3d(0.3, -0.2, 0.0));
    CHECK(after_floor(GridCondition::separate, towards) == Eigen::Vector3d(0.3, -0.2, 0.0));
    CHECK(after_floor(GridCondition::separate, away) == away);
    CHECK(grid_condition("slip") == GridCondition::slip);
    CHECK_THROWS_WITH(grid_condition("glue"), Catch::Contains("sticky, slip, separate"));
}

TEST_CASE("grid walls: a block dropped on a separating floor bounces off it and keeps its sideways momentum")
{
    const auto model = make_model<3, 3>("fixed-corotated", ParameterValues{{"mu", 1e4}, {"lambda", 2e4}});
    const std::vector<const Model3d*> models{model.get()};
    const double dx = 0.1, spacing = 0.5 * dx, volume = spacing * spacing * spacing;
    Particles<3> particles;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
            for (int k = 0; k < 8; ++k)
                particles.add(Eigen::Vector3d(1.0 + (i + 0.5) * spacing, 1.0 + (j + 0.5) * spacing, 0.6 + (k + 0.5) * spacing),
                              Eigen::Vector3d(0.5, 0.0, -1.0), 1000.0 * volume, volume);
    MpmStepSettings<3> settings;
    settings.time_step = 1e-3;
    settings.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
    settings.walls = GridWalls<3>::box(Eigen::Vector3d(-5.0, -5.0, 0.0), Eigen::Vector3d(5.0, 5.0, 5.0),
                                       GridCondition::separate);
    SparseGrid<3> grid(dx);
    const double mass = total_mass(particles);
    double lowest = 1e300, fastest_down = 0.0, fastest_up = 0.0;
    for (int n = 0; n < 800; ++n) {
        REQUIRE(explicit_step(particles, models, settings, grid).failure.empty());
        for (const auto& x : particles.x)
            lowest = std::min(lowest, x.z());
        const double v_z = linear_momentum(particles).z() / mass;  // the centre of mass's
        fastest_down = std::min(fastest_down, v_z);
        fastest_up = std::max(fastest_up, v_z);
    }
    const Eigen::Vector3d momentum = linear_momentum(particles);
    CAPTURE(lowest, fastest_down, fastest_up, momentum.transpose());
    // Falling from 0.6 m at 1 m/s, the block meets the floor's band (2 cells,
    // 0.2 m) at about 3 m/s; the elastic block, undamped, bounces back up.
    CHECK(fastest_down < -2.5);
    CHECK(fastest_up > 1.0);
    CHECK(lowest > 0.0);  // nothing went through the floor
    CHECK(momentum.x() == Approx(0.5 * mass).epsilon(1e-10));  // the floor does not touch the sideways motion
    CHECK(std::abs(momentum.y()) < 1e-10 * mass);
}
