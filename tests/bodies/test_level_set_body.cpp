// Collision bodies given as OpenVDB level sets (issue 32, contact): the
// narrow band of an icosphere against the sphere's exact signed distance,
// the clamped field beyond the band, the B-spline φ's derivatives through
// the shared check, a round trip through a .vdb file, and one-line errors.
#include "sinew/bodies/level_set_body.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/core/threads.hpp"
#include "sinew/mesh/icosphere.hpp"
#include "sinew/problems/derivative_check.hpp"

#include "bodies/body_surfaces.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

using namespace sinew;
using sinew::test::DistanceProblem;

namespace {

const Eigen::Vector3d kCentre(0.1, -0.2, 0.3);
constexpr double kRadius = 0.5;
constexpr double kVoxel = 0.02;

/// The ball |x − c| < 0.5 as an icosphere of 20,480 triangles (its facets
/// lie within r(1 − cos 1.1°) ≈ 1e-4 of the sphere), in a level set of
/// 0.02 voxels with a band of 3 voxels each side.
const LevelSetBody& ball()
{
    static const LevelSetBody body = LevelSetBody::from_surface(icosphere(kCentre, kRadius, 5), "ball", kVoxel, 3.0);
    return body;
}

/// A point at signed distance d from the sphere, in a random direction.
Eigen::Vector3d at_distance(double d, std::mt19937& rng)
{
    std::normal_distribution<double> normal;
    const Eigen::Vector3d u = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    return kCentre + (kRadius + d) * u;
}

std::string scratch(const std::string& file)
{
    const auto folder = std::filesystem::temp_directory_path() / "sinew_level_set_tests";
    std::filesystem::create_directories(folder);
    return (folder / file).string();
}

} // namespace

TEST_CASE("a level set made from an icosphere gives the sphere's signed distance in its band")
{
    const LevelSetBody& body = ball();
    CHECK(body.kind() == "level-set");
    CHECK(body.voxel_size() == Approx(kVoxel));
    CHECK(body.band_width() == Approx(3.0 * kVoxel));
    std::mt19937 rng(3);
    SECTION("near the surface: φ within a fiftieth of a voxel, a unit radial gradient")
    {
        // OpenVDB's meshToLevelSet stores exact distances to the triangles
        // next to the surface. The quadratic B-spline smooths a field curved
        // as 1/r by about h²/8·Δφ = h²/(4r) = 2e-4 and the facets add 1e-4
        // (measured at voxel centres: |φ − d| ≤ 0.017 h): 0.02 h = 4e-4.
        std::uniform_real_distribution<double> depth(-kVoxel, kVoxel);
        for (int trial = 0; trial < 200; ++trial) {
            const double d = depth(rng);
            const Eigen::Vector3d x = at_distance(d, rng);
            const BodyDistance phi = body.distance(x);
            const Eigen::Vector3d radial = (x - kCentre).normalized();
            CAPTURE(x.transpose(), d, phi.distance, phi.gradient.transpose());
            CHECK(std::abs(phi.distance - d) < 0.02 * kVoxel);
            if (std::abs(d) > 0.5 * kVoxel)
                continue;  // ∇φ also needs the cell's far corners, up to 1.5 h out
            CHECK(phi.gradient.norm() == Approx(1.0).margin(0.02));
            CHECK(phi.gradient.normalized().dot(radial) > std::cos(2.0 * M_PI / 180.0));
        }
    }
    SECTION("across the band: the right side of the surface, within a third of a voxel")
    {
        // Farther out meshToLevelSet propagates distances approximately
        // (measured up to 0.1 h off between 1.5 and 2 voxels): φ keeps its
        // sign and stays within h/3 of the distance, which is what pushing a
        // node out needs (docs/contact.md).
        std::uniform_real_distribution<double> depth(-1.9 * kVoxel, 1.9 * kVoxel);
        for (int trial = 0; trial < 400; ++trial) {
            const double d = depth(rng);
            const Eigen::Vector3d x = at_distance(d, rng);
            const double phi = body.distance(x).distance;
            CAPTURE(x.transpose(), d, phi);
            CHECK(std::abs(phi - d) < kVoxel / 3.0);
            if (std::abs(d) > 0.05 * kVoxel)
                CHECK(phi * d > 0.0);
        }
    }
}

TEST_CASE("beyond its band a level set holds plus or minus the band width with no gradient")
{
    const LevelSetBody& body = ball();
    std::mt19937 rng(5);
    for (const double d : {5.0 * kVoxel, 0.3, -5.0 * kVoxel, -0.45}) {
        const BodyDistance phi = body.distance(at_distance(d, rng));
        CAPTURE(d);
        CHECK(phi.distance == Approx(std::copysign(body.band_width(), d)));
        CHECK(phi.gradient.norm() < 1e-12);  // the corners' equal values cancel but for round-off
    }
    const BodyDistance far = body.distance(Eigen::Vector3d(1e12, 0, 0));  // beyond the grid's index range
    CHECK(far.distance == Approx(body.band_width()));
}

TEST_CASE("the B-spline level set passes the shared derivative check inside and outside the surface")
{
    const LevelSetBody& body = ball();
    std::mt19937 rng(11);
    // Regimes: on the surface, just inside and outside, and at the band's edges.
    for (const double d : {0.0, -0.3 * kVoxel, 0.3 * kVoxel, -2.5 * kVoxel, 2.5 * kVoxel})
        for (int trial = 0; trial < 4; ++trial) {
            const Eigen::Vector3d x = at_distance(d, rng);
            DistanceProblem problem(body, x);
            const DerivativeCheckReport report = check_derivatives(problem, x);
            CAPTURE(d, x.transpose(), report.to_text());
            CHECK(report.passed(1e-5));
        }
}

TEST_CASE("a level set made on one thread and on every core is the same field bit for bit")
{
    const Mesh surface = icosphere(kCentre, kRadius, 4);
    const int before = threads();
    set_threads(1);
    const LevelSetBody one = LevelSetBody::from_surface(surface, "one", kVoxel, 3.0);
    set_threads(available_cores());
    const LevelSetBody all = LevelSetBody::from_surface(surface, "all", kVoxel, 3.0);
    set_threads(before);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> depth(-3.0 * kVoxel, 3.0 * kVoxel);
    for (int trial = 0; trial < 500; ++trial) {
        const Eigen::Vector3d x = at_distance(depth(rng), rng);
        CHECK(one.distance(x).distance == all.distance(x).distance);
    }
}

TEST_CASE("a level set written to a vdb file reads back the same field")
{
    const std::string path = scratch("ball.vdb");
    ball().write_vdb(path);
    const LevelSetBody read = LevelSetBody::from_vdb(path);
    CHECK(read.name() == path);
    CHECK(read.band_width() == ball().band_width());
    std::mt19937 rng(13);
    for (int trial = 0; trial < 20; ++trial) {
        const Eigen::Vector3d x = at_distance(0.05 * (trial - 10) * kVoxel, rng);
        CHECK(read.distance(x).distance == ball().distance(x).distance);
        CHECK(read.distance(x).gradient == ball().distance(x).gradient);
    }
    CHECK(LevelSetBody::from_vdb(path, "ball").band_width() == ball().band_width());
    CHECK_THROWS_WITH(LevelSetBody::from_vdb(path, "skull"), Catch::Matchers::Contains("no float level set grid named 'skull'"));
}

TEST_CASE("a level set that cannot serve as a body is refused with one line naming it")
{
    using Catch::Matchers::Contains;
    SECTION("a file that is not VDB, and one that is missing")
    {
        const std::string text = scratch("not.vdb");
        std::ofstream(text) << "not a vdb file\n";
        CHECK_THROWS_WITH(LevelSetBody::from_vdb(text), Contains(text) && Contains("cannot read it as a VDB file"));
        CHECK_THROWS_WITH(LevelSetBody::from_vdb(scratch("missing.vdb")), Contains("missing.vdb"));
    }
    SECTION("a VDB file whose only grid is a fog volume")
    {
        // tests/data/fog_volume.vdb: one FloatGrid 'density' of class fog volume, one active voxel.
        const std::string fog = std::string(SINEW_SOURCE_DIR) + "/tests/data/fog_volume.vdb";
        CHECK_THROWS_WITH(LevelSetBody::from_vdb(fog),
                          Contains("no float level set grid") && Contains("'density' (float, fog volume)"));
    }
    SECTION("an open surface, a voxel too small for the surface, a band of no voxels")
    {
        Mesh open = icosphere(kCentre, kRadius, 1);
        open.elements.conservativeResize(3, open.elements.cols() - 1);
        CHECK_THROWS_WITH(LevelSetBody::from_surface(open, "lid-less", kVoxel, 3.0), Contains("lid-less") && Contains("open"));
        const Mesh sphere = icosphere(kCentre, kRadius, 1);
        CHECK_THROWS_WITH(LevelSetBody::from_surface(sphere, "fine", 1e-5, 3.0), Contains("fine") && Contains("at most 2000"));
        CHECK_THROWS_WITH(LevelSetBody::from_surface(sphere, "thin", kVoxel, 0.0), Contains("half_width"));
        CHECK_THROWS_AS(LevelSetBody::from_surface(sphere, "nan", std::nan(""), 3.0), InputError);
    }
}
