// Collision bodies bounded by closed triangle surfaces (issue 32, contact):
// the signed distance, its gradient and Hessian against the closed forms on
// a cube (face, edge and vertex regions, inside and out) and through the
// shared derivative check, and one-line errors for surfaces that cannot
// bound a volume.
#include "sinew/bodies/analytic_obstacle.hpp"
#include "sinew/bodies/surface_body.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/mesh/mesh.hpp"
#include "sinew/problems/derivative_check.hpp"

#include "bodies/body_surfaces.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

using namespace sinew;
using sinew::test::cube_surface;
using sinew::test::DistanceProblem;

TEST_CASE("a cube body gives the signed distance, closest point and feature of faces, edges and vertices")
{
    const SurfaceBody body(cube_surface(), "cube");
    SECTION("inside, nearest a face")
    {
        const SurfaceDistance d = body.query(Eigen::Vector3d(0.5, 0.5, 0.3));
        CHECK(d.distance == Approx(-0.3));
        CHECK(d.feature == SurfaceFeature::face);
        CHECK((d.gradient - Eigen::Vector3d(0, 0, -1)).norm() < 1e-12);  // φ grows towards the face z = 0
        CHECK(d.hessian().norm() == 0.0);
    }
    SECTION("outside a face, an edge and a vertex")
    {
        const SurfaceDistance face = body.query(Eigen::Vector3d(2.0, 0.5, 0.5));
        CHECK(face.distance == Approx(1.0));
        CHECK(face.feature == SurfaceFeature::face);
        const SurfaceDistance edge = body.query(Eigen::Vector3d(1.5, 1.5, 0.5));
        CHECK(edge.distance == Approx(std::sqrt(0.5)));
        CHECK(edge.feature == SurfaceFeature::edge);
        CHECK(std::abs(edge.edge_direction.z()) == Approx(1.0));
        const SurfaceDistance vertex = body.query(Eigen::Vector3d(2.0, 2.0, 2.0));
        CHECK(vertex.distance == Approx(std::sqrt(3.0)));
        CHECK(vertex.feature == SurfaceFeature::vertex);
        CHECK((vertex.closest - Eigen::Vector3d(1, 1, 1)).norm() < 1e-12);
        CHECK((vertex.gradient - Eigen::Vector3d::Constant(1.0 / std::sqrt(3.0))).norm() < 1e-12);
    }
    SECTION("an inward-facing surface is turned outward on load")
    {
        const SurfaceBody inward(cube_surface(false), "inward cube");
        CHECK(inward.query(Eigen::Vector3d(0.5, 0.5, 0.5)).distance == Approx(-0.5));
        CHECK(inward.query(Eigen::Vector3d(0.5, 0.5, 1.5)).distance == Approx(0.5));
    }
}

TEST_CASE("the signed distance to a body passes the shared derivative check near faces, edges and vertices")
{
    const SurfaceBody body(cube_surface(), "cube");
    std::mt19937 rng(61);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    // Centres of the regimes: inside near a face, outside a face, an edge and a
    // vertex, deep inside, and just outside a face (1e-3 away).
    const Eigen::Vector3d centres[] = {{0.5, 0.5, 0.2}, {0.5, 0.5, 1.4}, {1.3, 0.5, 1.3}, {1.4, -0.3, 1.2},
                                       {0.45, 0.5, 0.55}, {0.5, 0.4, 1.001}};
    for (const Eigen::Vector3d& centre : centres)
        for (int trial = 0; trial < 3; ++trial) {
            Eigen::Vector3d x = centre;
            for (int k = 0; k < 3; ++k)
                x[k] += (centre == centres[5] ? 0.01 : 1.0) * jitter(rng);
            DistanceProblem problem(body, x);
            const DerivativeCheckReport report = check_derivatives(problem, x);
            CAPTURE(x.transpose(), report.to_text());
            CHECK(report.passed(1e-5));
        }
}

TEST_CASE("a surface that cannot bound a volume is refused with one line naming the body and the defect")
{
    using Catch::Matchers::Contains;
    SECTION("open: one triangle missing")
    {
        Mesh open = cube_surface();
        open.elements.conservativeResize(3, 11);
        CHECK_THROWS_WITH(SurfaceBody(open, "lid-less"), Contains("lid-less") && Contains("open"));
    }
    SECTION("self-intersecting: two overlapping cubes in one surface")
    {
        Mesh two = cube_surface();
        Mesh shifted = cube_surface();
        shifted.nodes.array() += 0.5;
        Mesh joined;
        joined.kind = ElementKind::triangle_3d;
        joined.nodes.resize(3, 16);
        joined.nodes << two.nodes, shifted.nodes;
        joined.elements.resize(3, 24);
        joined.elements << two.elements, (shifted.elements.array() + 8).matrix();
        CHECK_THROWS_WITH(SurfaceBody(joined, "overlap"), Contains("overlap") && Contains("intersects itself"));
    }
    SECTION("too few triangles, a degenerate triangle, a tet mesh")
    {
        Mesh few = cube_surface();
        few.elements.conservativeResize(3, 3);
        CHECK_THROWS_AS(SurfaceBody(few, "few"), InputError);
        Mesh flat = cube_surface();
        flat.elements.col(0) << 0, 1, 1;
        CHECK_THROWS_AS(SurfaceBody(flat, "flat"), InputError);
        Mesh tets = cube_surface();
        tets.kind = ElementKind::tetrahedron;
        CHECK_THROWS_WITH(SurfaceBody(tets, "tets"), Contains("triangle"));
    }
}

TEST_CASE("an analytic box gives the signed distance of the cube surface, and passes the shared derivative check")
{
    // The unit cube as an analytic box and as a closed triangle surface: the same φ and ∇φ everywhere.
    const auto box = analytic_body(BoxObstacle{Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()}, 3);
    const SurfaceBody surface(cube_surface(), "cube");
    std::mt19937 rng(67);
    std::uniform_real_distribution<double> position(-1.0, 2.0);
    for (int sample = 0; sample < 1000; ++sample) {
        const Eigen::Vector3d x(position(rng), position(rng), position(rng));
        const BodyDistance analytic = box->distance(x);
        const SurfaceDistance faceted = surface.query(x);
        CAPTURE(x.transpose());
        CHECK(analytic.distance == Approx(faceted.distance).margin(1e-12));
        CHECK((analytic.gradient - faceted.gradient).norm() < 1e-9);
    }
    // The derivative check outside a face, an edge and a vertex, and inside.
    const Eigen::Vector3d points[] = {{0.5, 0.5, 1.4}, {1.3, 0.4, 1.3}, {1.4, -0.3, 1.2}, {0.45, 0.6, 0.8}};
    for (const Eigen::Vector3d& x : points) {
        DistanceProblem problem(*box, x);
        const DerivativeCheckReport report = check_derivatives(problem, x);
        CAPTURE(x.transpose(), report.to_text());
        CHECK(report.passed(1e-5));
    }
    // 2D: a rectangle.
    const auto rectangle = analytic_body(BoxObstacle{Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 1)}, 2);
    CHECK(rectangle->distance(Eigen::Vector3d(3, 2, 0)).distance == Approx(std::sqrt(2.0)));
    CHECK(rectangle->distance(Eigen::Vector3d(1, 0.25, 0)).distance == Approx(-0.25));
    CHECK(rectangle->distance(Eigen::Vector3d(1, 0.25, 0)).gradient.isApprox(Eigen::Vector3d(0, -1, 0)));
    CHECK_THROWS_AS(analytic_body(BoxObstacle{Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 0)}, 2), InputError);
}
