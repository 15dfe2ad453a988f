// Particle-grid transfers of MPM (issue 33): APIC reproduces affine velocity
// fields exactly, P2G conserves mass and linear momentum, APIC conserves
// angular momentum both ways, PIC/FLIP blends as documented, G2P with the
// advection fused equals the two apart, a reused grid equals a fresh one,
// and a particle outside the grid's domain is an input error; the grid's
// layout finds every stencil node at its slot, and particles sorted by
// block are laid out in their own order.
#include "mpm/particle_clouds.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mpm/active_grid.hpp"
#include "sinew/mpm/particle_measures.hpp"
#include "sinew/mpm/transfers.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
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
    const ParticleBuckets<Dim> layout = particles_to_grid(particles, settings, grid);
    for (int slot = 0; slot < grid.slots(); ++slot)
        if (grid.mass[static_cast<std::size_t>(slot)] > 0.0)
            CHECK((grid.velocity[static_cast<std::size_t>(slot)] - (b + A * grid.position(slot))).norm() < 1e-13);
    const Particles<Dim> before = particles;
    for (int p = 0; p < particles.size(); ++p)
        particles.C[static_cast<std::size_t>(p)].setZero();
    grid_to_particles(grid, layout, settings, particles);
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
    const ParticleBuckets<Dim> layout = particles_to_grid(particles, settings, grid);
    const double scale = mass * 10.0;  // Σ m |v| is of this order
    CHECK(total_mass(grid) == Approx(mass).epsilon(1e-14));
    CHECK((linear_momentum(grid) - momentum).norm() < 1e-13 * scale);
    CHECK((angular_momentum(grid) - L).norm() < 1e-13 * scale);
    grid_to_particles(grid, layout, settings, particles);
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
    const ParticleBuckets<2> layout = particles_to_grid(particles, settings, grid);
    const Eigen::Vector2d kick(0.25, -0.5);  // every node's velocity changes by the same amount
    for (auto& v : grid.velocity)
        v += kick;
    settings.flip_ratio = 1.0;
    Particles<2> flip = particles;
    grid_to_particles(grid, layout, settings, flip);
    settings.flip_ratio = 0.0;
    Particles<2> pic = particles;
    grid_to_particles(grid, layout, settings, pic);
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

namespace {

template <int Dim>
void check_fused_advection(TransferScheme scheme)
{
    using Matrix = Eigen::Matrix<double, Dim, Dim>;
    Particles<Dim> particles = random_particles<Dim>(200, -0.2, 0.4, 1.5, 2.0, 21);
    for (int p = 0; p < particles.size(); ++p)
        particles.F[static_cast<std::size_t>(p)] = Matrix::Identity() + 0.1 * Matrix::Random();
    TransferSettings settings;
    settings.scheme = scheme;
    SparseGrid<Dim> grid(0.05);
    const ParticleBuckets<Dim> layout = particles_to_grid(particles, settings, grid);
    for (int slot = 0; slot < grid.slots(); ++slot)  // a grid velocity unlike the particles'
        grid.velocity[static_cast<std::size_t>(slot)] += 0.3 * grid.position(slot).reverse();
    const double h = 0.01;
    Particles<Dim> separate = particles, fused = particles;
    grid_to_particles(grid, layout, settings, separate);
    for (int p = 0; p < separate.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        separate.x[i] += h * separate.v[i];
        separate.F[i] = (Matrix::Identity() + h * separate.C[i]) * separate.F[i];
    }
    grid_to_particles_advected(grid, layout, settings, h, fused);
    double worst = 0.0;
    for (int p = 0; p < fused.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        worst = std::max({worst, (fused.v[i] - separate.v[i]).norm(), (fused.C[i] - separate.C[i]).norm(),
                          (fused.x[i] - separate.x[i]).norm(), (fused.F[i] - separate.F[i]).norm()});
        CHECK((fused.x[i] - particles.x[i]).norm() > 0.0);  // the particles moved
    }
    CAPTURE(Dim, worst);
    CHECK(worst < 1e-14);
}

} // namespace

TEST_CASE("transfers: G2P with advection in the same pass equals G2P, then x += h v and F = (I + h C) F")
{
    check_fused_advection<2>(TransferScheme::apic);
    check_fused_advection<3>(TransferScheme::apic);
    check_fused_advection<3>(TransferScheme::pic_flip);
}

TEST_CASE("transfers: a grid reused from a larger step gives the grid of a fresh one, bit for bit")
{
    const Particles<3> large = random_particles<3>(600, -0.5, 0.9, 1.0, 1.0, 7);
    const Particles<3> small = random_particles<3>(80, 0.1, 0.3, 1.0, 1.0, 8);
    SparseGrid<3> reused(0.05), fresh(0.05);
    particles_to_grid(large, TransferSettings{}, reused);
    particles_to_grid(small, TransferSettings{}, reused);
    particles_to_grid(small, TransferSettings{}, fresh);
    REQUIRE(reused.slots() == fresh.slots());
    int differing = 0;
    for (std::size_t s = 0; s < static_cast<std::size_t>(fresh.slots()); ++s)
        differing += reused.mass[s] != fresh.mass[s] || reused.momentum[s] != fresh.momentum[s] ||
                             reused.velocity[s] != fresh.velocity[s]
                         ? 1
                         : 0;
    CHECK(differing == 0);
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

namespace {

template <int Dim>
void check_layout(SplineOrder order)
{
    using Index = typename SparseGrid<Dim>::Index;
    const Particles<Dim> particles = random_particles<Dim>(500, -0.33, 0.71, 0.0, 0.0, 9);
    SparseGrid<Dim> grid(0.05);
    const ParticleBuckets<Dim> layout = lay_out_grid(particles, order, grid);
    std::vector<int> seen(static_cast<std::size_t>(particles.size()), 0);
    int mismatches = 0;
    for (const auto& bucket : layout.buckets) {
        REQUIRE(bucket.first < bucket.last);
        for (int j = bucket.first; j < bucket.last; ++j) {
            const int p = layout.order[static_cast<std::size_t>(j)];
            if (j > bucket.first)
                CHECK(layout.order[static_cast<std::size_t>(j) - 1] < p);  // increasing within a bucket
            ++seen[static_cast<std::size_t>(p)];
            const auto& x = particles.x[static_cast<std::size_t>(p)];
            const BSplineStencil<Dim> stencil = bspline_stencil<Dim>(x, grid.dx(), order);
            CHECK(SparseGrid<Dim>::block_of(stencil.base) == bucket.block);
            const StencilTables<Dim> tables(bucket, x, grid.dx(), order);
            stencil.for_each_offset([&](const Index& offset) {
                const int slot = Dim == 2 ? tables.slot(bucket, offset[0], offset[1])
                                          : tables.slot(bucket, offset[0], offset[1], offset[Dim - 1]);
                if (slot != grid.find(stencil.base + offset))
                    ++mismatches;
            });
        }
    }
    CHECK(mismatches == 0);
    CHECK(std::count(seen.begin(), seen.end(), 1) == particles.size());  // every particle in one bucket
    std::size_t coloured = 0;
    for (int colour = 0; colour < ParticleBuckets<Dim>::kCorners; ++colour)
        for (const int b : layout.colours[static_cast<std::size_t>(colour)]) {
            ++coloured;
            for (int a = 0; a < Dim; ++a)
                CHECK(((layout.buckets[static_cast<std::size_t>(b)].block[a] & 1) << a) == (colour & (1 << a)));
        }
    CHECK(coloured == layout.buckets.size());
}

} // namespace

TEST_CASE("transfers: the grid's layout finds every stencil node of every particle at its slot")
{
    check_layout<2>(SplineOrder::quadratic);
    check_layout<2>(SplineOrder::cubic);
    check_layout<3>(SplineOrder::quadratic);
    check_layout<3>(SplineOrder::cubic);
}

TEST_CASE("transfers: particles sorted by block are laid out in their own order and keep every field")
{
    Particles<3> particles = random_particles<3>(400, -0.3, 0.7, 1.0, 1.0, 12);
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        particles.material[i] = p % 3;
        particles.volume[i] = 1.0 + p;
        particles.F[i] = (1.0 + 0.001 * p) * Eigen::Matrix3d::Identity();
        particles.point[i].activation = 0.001 * p;
    }
    const Particles<3> before = particles;
    sort_particles_by_block(particles, 0.05, SplineOrder::quadratic);
    REQUIRE(particles.size() == before.size());
    SparseGrid<3> grid(0.05);
    const ParticleBuckets<3> layout = lay_out_grid(particles, SplineOrder::quadratic, grid);
    std::vector<int> identity(static_cast<std::size_t>(particles.size()));
    std::iota(identity.begin(), identity.end(), 0);
    CHECK(layout.order == identity);  // bucket after bucket already
    CHECK(layout.order != lay_out_grid(before, SplineOrder::quadratic, grid).order);  // the random cloud was not
    std::vector<int> found(static_cast<std::size_t>(before.size()), 0);
    int mismatched = 0;
    for (int k = 0; k < particles.size(); ++k) {
        const auto i = static_cast<std::size_t>(k);
        const auto was = static_cast<std::size_t>(std::lround(particles.volume[i] - 1.0));  // volume 1 + original index
        REQUIRE(was < found.size());
        ++found[was];
        mismatched += particles.x[i] != before.x[was] || particles.v[i] != before.v[was] ||
                              particles.mass[i] != before.mass[was] || particles.F[i] != before.F[was] ||
                              particles.C[i] != before.C[was] || particles.material[i] != before.material[was] ||
                              particles.point[i].activation != before.point[was].activation
                          ? 1
                          : 0;
    }
    CHECK(mismatched == 0);
    CHECK(std::count(found.begin(), found.end(), 1) == before.size());  // a permutation
}

TEST_CASE("active grid: every node with mass, and the cells with mass at every corner, in VTK's corner order")
{
    const Particles<3> particles = random_particles<3>(300, 0.1, 0.6, 0.0, 0.0, 4);
    SparseGrid<3> grid(0.05);
    particles_to_grid(particles, TransferSettings{}, grid);
    const ActiveGrid<3> active = active_grid(grid);
    double mass = 0.0;
    int with_mass = 0;
    for (int slot = 0; slot < grid.slots(); ++slot)
        with_mass += grid.mass[static_cast<std::size_t>(slot)] > 0.0 ? 1 : 0;
    for (const int slot : active.slots)
        mass += grid.mass[static_cast<std::size_t>(slot)];
    CHECK(static_cast<int>(active.slots.size()) == with_mass);
    CHECK(mass == Approx(total_mass(particles)).epsilon(1e-14));
    REQUIRE(!active.cells.empty());
    int misplaced = 0;
    for (const auto& cell : active.cells)
        for (int corner = 0; corner < 8; ++corner) {
            const Eigen::Vector3d offset(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
            const Eigen::Vector3d step = active.positions.col(cell[static_cast<std::size_t>(corner)]) -
                                         active.positions.col(cell[0]);
            misplaced += (step - grid.dx() * offset).norm() < 1e-12 ? 0 : 1;
        }
    CHECK(misplaced == 0);
}
