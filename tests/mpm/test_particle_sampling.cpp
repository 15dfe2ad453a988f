// Sampling particles (issue 33): a box filled exactly, a ball and a disk to
// within the lattice's resolution, a tet mesh element by element, and the
// input errors of each.
#include "sinew/core/input_error.hpp"
#include "sinew/mesh/box_tets.hpp"
#include "sinew/mesh/element_geometry.hpp"
#include "sinew/mpm/particle_measures.hpp"
#include "sinew/mpm/particle_sampling.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numeric>

using namespace sinew;

namespace {

template <int Dim>
double total_volume(const Particles<Dim>& particles)
{
    return std::accumulate(particles.volume.begin(), particles.volume.end(), 0.0);
}

} // namespace

TEST_CASE("particle sampling: a box is filled exactly, its volume and mass summed by the particles")
{
    LatticeSampling<3> sampling;
    sampling.dx = 0.1;
    sampling.per_cell = 2;
    sampling.density = 800.0;
    sampling.velocity = Eigen::Vector3d(1.0, 0.0, -2.0);
    const Eigen::Vector3d lower(-0.2, 0.0, 1.0), upper(0.33, 0.2, 1.07);  // not a multiple of the spacing
    const Particles<3> particles = sample_box<3>(lower, upper, sampling);
    const double volume = (upper - lower).prod();
    CHECK(particles.size() == 11 * 4 * 1);  // round(0.53/0.05), round(0.2/0.05), max(1, round(0.07/0.05))
    CHECK(total_volume(particles) == Approx(volume).epsilon(1e-12));
    CHECK(total_mass(particles) == Approx(800.0 * volume).epsilon(1e-12));
    for (int p = 0; p < particles.size(); ++p) {
        const auto& x = particles.x[static_cast<std::size_t>(p)];
        CHECK(((x - lower).minCoeff() > 0.0 && (upper - x).minCoeff() > 0.0));
        CHECK(particles.v[static_cast<std::size_t>(p)] == sampling.velocity);
    }
    LatticeSampling<2> flat;
    flat.per_cell = 3;
    const Particles<2> square = sample_box<2>(Eigen::Vector2d::Zero(), Eigen::Vector2d::Ones(), flat);
    CHECK(square.size() == 30 * 30);
    CHECK(total_volume(square) == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("particle sampling: a ball and a disk approach their volume as the lattice refines")
{
    LatticeSampling<3> sampling;
    sampling.dx = 0.02;
    const Eigen::Vector3d center(0.3, -0.1, 0.2);
    const double radius = 0.2;  // 20 lattice spacings
    const Particles<3> ball = sample_ball<3>(center, radius, sampling);
    for (const auto& x : ball.x)
        CHECK((x - center).norm() < radius);
    CHECK(total_volume(ball) == Approx(4.0 / 3.0 * M_PI * radius * radius * radius).epsilon(0.02));
    LatticeSampling<2> flat;
    flat.dx = 0.01;
    const Particles<2> disk = sample_ball<2>(Eigen::Vector2d(0.2, 0.2), 0.2, flat);
    CHECK(total_volume(disk) == Approx(M_PI * 0.04).epsilon(0.01));
    // A ball smaller than the spacing still holds its centre.
    CHECK(sample_ball<3>(center, 1e-6, sampling).size() == 1);
}

TEST_CASE("particle sampling: a tet mesh gives a particle per element with its volume and fiber")
{
    Mesh mesh = box_tets(Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 0.5, 0.25), 4, 2, 1);
    mesh.element_fibers = Eigen::MatrixXd::Zero(3, mesh.num_elements());
    mesh.element_fibers.row(1).setOnes();
    const Particles<3> particles = sample_mesh_elements<3>(mesh, 1100.0);
    REQUIRE(particles.size() == mesh.num_elements());
    CHECK(total_volume(particles) == Approx(total_measure(mesh)).epsilon(1e-12));
    CHECK(total_mass(particles) == Approx(1100.0 * 0.125).epsilon(1e-12));
    for (int e = 0; e < mesh.num_elements(); ++e) {
        const auto i = static_cast<std::size_t>(e);
        CHECK(particles.volume[i] == Approx(element_measure(mesh, e)));
        CHECK(particles.point[i].fiber == Eigen::Vector3d::UnitY());
    }
    CHECK_THROWS_WITH(sample_mesh_elements<2>(mesh, 1000.0), Catch::Contains("triangle"));
    CHECK_THROWS_WITH(sample_mesh_elements<3>(mesh, 0.0), Catch::Contains("density"));
}

TEST_CASE("particle sampling: invalid sizes, densities and counts are input errors")
{
    const Eigen::Vector3d lower = Eigen::Vector3d::Zero(), upper = Eigen::Vector3d::Ones();
    auto box_with = [&](auto change) {
        LatticeSampling<3> s;
        change(s);
        return [=] { sample_box<3>(lower, upper, s); };
    };
    CHECK_THROWS_WITH(box_with([](LatticeSampling<3>& s) { s.dx = 0.0; })(), Catch::Contains("dx"));
    CHECK_THROWS_WITH(box_with([](LatticeSampling<3>& s) { s.dx = -1.0; })(), Catch::Contains("dx"));
    CHECK_THROWS_WITH(box_with([](LatticeSampling<3>& s) { s.per_cell = 0; })(), Catch::Contains("particles_per_cell"));
    CHECK_THROWS_WITH(box_with([](LatticeSampling<3>& s) { s.density = std::numeric_limits<double>::quiet_NaN(); })(),
                      Catch::Contains("density"));
    CHECK_THROWS_WITH(box_with([](LatticeSampling<3>& s) { s.dx = 1e-4; })(), Catch::Contains("1e8 particles"));
    CHECK_THROWS_AS(sample_box<3>(upper, lower, LatticeSampling<3>{}), InputError);
    CHECK_THROWS_AS(sample_ball<3>(lower, 0.0, LatticeSampling<3>{}), InputError);
    CHECK_THROWS_AS(sample_ball<3>(lower, std::numeric_limits<double>::infinity(), LatticeSampling<3>{}), InputError);
}
