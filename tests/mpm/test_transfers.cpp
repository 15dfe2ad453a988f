// Particle-grid transfers of MPM (issue 33): APIC reproduces affine velocity
// fields exactly, P2G conserves mass and linear momentum, APIC conserves
// angular momentum both ways, PIC/FLIP blends as documented, and a particle
// outside the grid's domain is an input error.
#include "mpm/particle_clouds.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mpm/particle_measures.hpp"
#include "sinew/mpm/transfers.hpp"

#include <catch2/catch.hpp>

#include <limits>

using namespace sinew;
using namespace sinew::test;

namespace {

template <int Dim>
void check_affine_reproduction(SplineOrder order)
{
    using Matrix = Eigen::Matrix<double, Dim, Dim>;
    using Vector = Eigen::Matrix<double, Dim, 1>;
    Particles<Dim> particles = random_particles<Dim>(400, -0.3, 0.7, 0.0, 0.0, 3);
    const Vector b = Vector::LinSpaced(0.5, -0.25);
    Matrix A;
    for (int a = 0; a < Dim; ++a)
        for (int c = 0; c < Dim; ++c)
            A(a, c) = 0.3 * (a + 1) - 0.7 * c + 0.1 * a * c;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        particles.v[i] = b + A * particles.x[i];  // v(x) = b + A x
        particles.C[i] = A;
    }
    TransferSettings settings;
    settings.order = order;
    SparseGrid<Dim> grid(0.05);
    particles_to_grid(particles, settings, grid);
    for (int slot = 0; slot < grid.slots(); ++slot)
        if (grid.mass[static_cast<std::size_t>(slot)] > 0.0)
            CHECK((grid.velocity[static_cast<std::size_t>(slot)] - (b + A * grid.position(slot))).norm() < 1e-13);
    const Particles<Dim> before = particles;
    for (int p = 0; p < particles.size(); ++p)
        particles.C[static_cast<std::size_t>(p)].setZero();
    grid_to_particles(grid, settings, particles);
    double worst_v = 0.0, worst_C = 0.0;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        worst_v = std::max(worst_v, (particles.v[i] - before.v[i]).norm());
        worst_C = std::max(worst_C, (particles.C[i] - A).norm());
    }
    CAPTURE(Dim, worst_v, worst_C);
    CHECK(worst_v < 1e-13);
    CHECK(worst_C < 1e-11);
}

template <int Dim>
void check_conservation(SplineOrder order)
{
    Particles<Dim> particles = random_particles<Dim>(300, -1.0, 1.0, 2.0, 5.0, 17);
    TransferSettings settings;
    settings.order = order;
    SparseGrid<Dim> grid(0.1);
    const double D = apic_inertia_factor(order) * grid.dx() * grid.dx();
    const double mass = total_mass(particles);
    const auto momentum = linear_momentum(particles);
    const AngularMomentum L = angular_momentum(particles, D);
    particles_to_grid(particles, settings, grid);
    const double scale = mass * 10.0;  // Σ m |v| is of this order
    CHECK(total_mass(grid) == Approx(mass).epsilon(1e-14));
    CHECK((linear_momentum(grid) - momentum).norm() < 1e-13 * scale);
    CHECK((angular_momentum(grid) - L).norm() < 1e-13 * scale);
    grid_to_particles(grid, settings, particles);
    CHECK((linear_momentum(particles) - momentum).norm() < 1e-13 * scale);
    CHECK((angular_momentum(particles, D) - L).norm() < 1e-13 * scale);
}

} // namespace

TEST_CASE("transfers: APIC P2G then G2P reproduces an affine velocity field and its gradient to round-off")
{
    check_affine_reproduction<2>(SplineOrder::quadratic);
    check_affine_reproduction<3>(SplineOrder::quadratic);
    check_affine_reproduction<2>(SplineOrder::cubic);
    check_affine_reproduction<3>(SplineOrder::cubic);
}

TEST_CASE("transfers: mass, linear momentum and APIC's angular momentum are conserved both ways")
{
    check_conservation<2>(SplineOrder::quadratic);
    check_conservation<3>(SplineOrder::quadratic);
    check_conservation<3>(SplineOrder::cubic);
}

TEST_CASE("transfers: PIC/FLIP takes the grid's velocity (PIC) or adds its increment (FLIP)")
{
    Particles<2> particles = random_particles<2>(50, 0.0, 1.0, 1.0, 0.0, 5);
    const Particles<2> before = particles;
    TransferSettings settings;
    settings.scheme = TransferScheme::pic_flip;
    SparseGrid<2> grid(0.1);
    particles_to_grid(particles, settings, grid);
    const Eigen::Vector2d kick(0.25, -0.5);  // every node's velocity changes by the same amount
    for (auto& v : grid.velocity)
        v += kick;
    settings.flip_ratio = 1.0;
    Particles<2> flip = particles;
    grid_to_particles(grid, settings, flip);
    settings.flip_ratio = 0.0;
    Particles<2> pic = particles;
    grid_to_particles(grid, settings, pic);
    double pic_moved = 0.0;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        CHECK((flip.v[i] - (before.v[i] + kick)).norm() < 1e-14);  // FLIP: v_p + Σ w Δv_i
        pic_moved = std::max(pic_moved, (pic.v[i] - kick - before.v[i]).norm());
    }
    // PIC replaces v_p by the grid's average: it smooths the random velocities.
    CHECK(pic_moved > 0.1);
    CHECK(kinetic_energy(pic) < kinetic_energy(flip));
}

TEST_CASE("transfers: a particle outside the grid's domain is an input error naming it")
{
    Particles<3> particles = random_particles<3>(3, 0.0, 1.0, 0.0, 0.0, 1);
    particles.x[1] = Eigen::Vector3d(0.5, 1e9, 0.5);
    SparseGrid<3> grid(0.01);
    CHECK_THROWS_WITH(particles_to_grid(particles, TransferSettings{}, grid),
                      Catch::Contains("particle 1") && Catch::Contains("outside the grid's domain"));
    particles.x[1] = Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
    CHECK_THROWS_AS(particles_to_grid(particles, TransferSettings{}, grid), InputError);
}
