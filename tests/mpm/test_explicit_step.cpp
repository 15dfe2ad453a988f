// Explicit MLS-MPM steps (issue 33): free fall against its closed form, and
// linear and APIC angular momentum conserved by a deformed elastic block
// with no gravity and no boundaries; a non-finite stress names its particle.
#include "mpm/particle_clouds.hpp"

#include "sinew/core/threads.hpp"
#include "sinew/energies/models/model_catalog.hpp"
#include "sinew/mpm/explicit_step.hpp"
#include "sinew/mpm/particle_measures.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

std::unique_ptr<Model3d> fixed_corotated() { return make_model<3, 3>("fixed-corotated", ParameterValues{{"mu", 1e4}, {"lambda", 2e4}}); }

/// A block of 4 × 4 × 4 cells of dx, two particles a cell along each axis, at rest.
Particles<3> block(double dx)
{
    Particles<3> particles;
    const double spacing = 0.5 * dx, volume = spacing * spacing * spacing;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
            for (int k = 0; k < 8; ++k)
                particles.add(Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5) * spacing + Eigen::Vector3d::Constant(1.0),
                              Eigen::Vector3d::Zero(), 1000.0 * volume, volume);
    return particles;
}

} // namespace

TEST_CASE("explicit MPM step: an unstressed block falls as symplectic Euler says, v = n dt g")
{
    const auto model = fixed_corotated();
    const std::vector<const Model3d*> models{model.get()};
    Particles<3> particles = block(0.1);
    const Particles<3> start = particles;
    MpmStepSettings<3> settings;
    settings.time_step = 1e-3;
    settings.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
    SparseGrid<3> grid(0.1);
    const int steps = 50;
    for (int n = 0; n < steps; ++n)
        REQUIRE(explicit_step(particles, models, settings, grid).failure.empty());
    // vₙ = n Δt g, xₙ = x₀ + Δt Σ_{k=1..n} v_k = x₀ + Δt² g n(n+1)/2
    const Eigen::Vector3d v = steps * settings.time_step * settings.gravity;
    const Eigen::Vector3d drop = settings.time_step * settings.time_step * settings.gravity * steps * (steps + 1) / 2.0;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        CHECK((particles.v[i] - v).norm() < 1e-12);
        CHECK((particles.x[i] - (start.x[i] + drop)).norm() < 1e-12);
        CHECK((particles.F[i] - Eigen::Matrix3d::Identity()).norm() < 1e-12);
    }
}

TEST_CASE("explicit MPM step: a deformed spinning block conserves linear and APIC angular momentum")
{
    const auto model = fixed_corotated();
    const std::vector<const Model3d*> models{model.get()};
    const double dx = 0.1;
    Particles<3> particles = block(dx);
    const Eigen::Vector3d center(1.2, 1.2, 1.2), omega(0.3, -0.2, 0.5), drift(0.1, 0.0, -0.05);
    Eigen::Matrix3d stretch;
    stretch << 1.1, 0.05, 0.0, -0.02, 0.95, 0.03, 0.0, 0.04, 1.02;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        particles.x[i] = center + stretch * (particles.x[i] - center);
        particles.F[i] = stretch;  // released from a uniform stretch and shear
        particles.v[i] = drift + omega.cross(particles.x[i] - center);
    }
    MpmStepSettings<3> settings;
    settings.time_step = 1e-4;
    SparseGrid<3> grid(dx);
    const double D = apic_inertia_factor(settings.transfer.order) * dx * dx;
    const Eigen::Vector3d momentum = linear_momentum(particles);
    const AngularMomentum L = angular_momentum(particles, D);
    const double mass = total_mass(particles);
    for (int n = 0; n < 40; ++n)
        REQUIRE(explicit_step(particles, models, settings, grid).failure.empty());
    // It moved: the stress did work, so the velocities are no longer rigid.
    double deformation_rate = 0.0;
    for (const auto& C : particles.C)
        deformation_rate = std::max(deformation_rate, (C + C.transpose()).norm());
    CHECK(deformation_rate > 1e-2);
    const double scale = mass * (drift.norm() + omega.norm());
    CHECK((linear_momentum(particles) - momentum).norm() < 1e-12 * scale);
    CHECK((angular_momentum(particles, D) - L).norm() < 1e-12 * scale);
}

TEST_CASE("explicit MPM step: a stress that is not finite ends the step and names the particle")
{
    const auto model = make_model<3, 3>("stable-neo-hookean", ParameterValues{{"mu", 1e4}, {"lambda", 2e4}});
    const std::vector<const Model3d*> models{model.get()};
    Particles<3> particles = block(0.1);
    particles.F[5](0, 0) = std::numeric_limits<double>::quiet_NaN();
    const Particles<3> before = particles;
    SparseGrid<3> grid(0.1);
    const ExplicitStepReport report = explicit_step(particles, models, MpmStepSettings<3>{}, grid);
    CHECK_THAT(report.failure, Catch::Contains("particle 5"));
    CHECK(particles.x == before.x);
}

TEST_CASE("explicit MPM step: the same particles bit for bit on one thread and on two")
{
    const auto model = fixed_corotated();
    const std::vector<const Model3d*> models{model.get()};
    MpmStepSettings<3> settings;
    settings.time_step = 1e-4;
    settings.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
    std::vector<Particles<3>> results;
    for (const int count : {1, std::min(2, available_cores())}) {
        set_threads(count);
        Particles<3> particles = random_particles<3>(3000, 0.3, 0.7, 0.5, 2.0, 17);
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> u11(-1.0, 1.0);
        for (auto& F : particles.F)
            F = Eigen::Matrix3d::Identity() + 0.05 * Eigen::Matrix3d::NullaryExpr([&] { return u11(rng); });
        SparseGrid<3> grid(0.05);
        for (int n = 0; n < 10; ++n)
            REQUIRE(explicit_step(particles, models, settings, grid).failure.empty());
        results.push_back(particles);
    }
    set_threads(available_cores());
    if (available_cores() < 2)
        WARN("one core: both runs were on one thread");
    for (int p = 0; p < results[0].size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        CHECK(results[0].x[i] == results[1].x[i]);
        CHECK(results[0].v[i] == results[1].v[i]);
        CHECK(results[0].C[i] == results[1].C[i]);
        CHECK(results[0].F[i] == results[1].F[i]);
    }
}
