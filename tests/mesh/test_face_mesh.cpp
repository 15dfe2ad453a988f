#include "sinew/bodies/surface_body.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/mesh/element_geometry.hpp"
#include "sinew/mesh/face_geometry.hpp"
#include "sinew/mesh/face_mesh.hpp"
#include "sinew/mesh/mesh_validation.hpp"

#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <set>

using namespace sinew;

TEST_CASE("face generator: a valid shell of about the asked size with muscles, attachments and landmarks",
          "[mesh][face]")
{
    FaceShape shape;
    shape.target_tets = 8000;
    const FaceMesh face = generate_face(shape);
    const Mesh& mesh = face.mesh;
    CHECK_NOTHROW(validate_mesh(mesh, "face"));
    CAPTURE(mesh.num_elements(), mesh.num_nodes());
    CHECK(mesh.num_elements() >= 0.75 * shape.target_tets);
    CHECK(mesh.num_elements() <= 1.25 * shape.target_tets);
    // Size of a face: about 13 cm wide, 19 cm tall, the tissue 1.5 cm thick.
    const Eigen::Vector3d extent = mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff();
    CHECK(extent.x() == Approx(2 * shape.rho * shape.a).epsilon(0.05));
    CHECK(extent.y() == Approx(2 * shape.rho * shape.b).epsilon(0.05));
    double volume = 0.0;
    for (int e = 0; e < mesh.num_elements(); ++e)
        volume += element_measure(mesh, e);
    const double expected = shape.thickness * M_PI *
                            (shape.a * shape.b * shape.rho * shape.rho - shape.mouth_half_width * shape.mouth_half_height);
    CHECK(volume == Approx(expected).epsilon(0.15));  // the cell staircase trims the rim
    // The mouth is an opening: no tet holds a point of its axis, at any depth.
    int mouth_points = 0;
    for (double x = -0.5 * shape.mouth_half_width; x <= 0.5 * shape.mouth_half_width; x += 0.002)
        for (double z = -0.02; z <= shape.c; z += 0.002) {
            const Eigen::Vector3d p(x, shape.mouth_y, z);
            ++mouth_points;
            for (int e = 0; e < mesh.num_elements(); ++e) {
                Eigen::Matrix3d D;
                for (int k = 0; k < 3; ++k)
                    D.col(k) = mesh.nodes.col(mesh.elements(k + 1, e)) - mesh.nodes.col(mesh.elements(0, e));
                const Eigen::Vector3d b = D.inverse() * (p - mesh.nodes.col(mesh.elements(0, e)));
                const bool inside = b.minCoeff() >= 0.0 && b.sum() <= 1.0;
                if (inside)
                    FAIL_CHECK("tet " << e << " holds the mouth point " << p.transpose());
            }
        }
    CHECK(mouth_points > 100);
    REQUIRE(face.muscle_names.size() >= 8);
    REQUIRE(mesh.group_names.size() == face.muscle_names.size() + 1);
    for (std::size_t m = 0; m < face.muscle_names.size(); ++m) {
        CAPTURE(face.muscle_names[m]);
        CHECK(face.muscle_elements[m].size() >= 20);
        for (const int e : face.muscle_elements[m])
            CHECK(mesh.element_groups[e] == static_cast<int>(m) + 1);
    }
    for (int e = 0; e < mesh.num_elements(); ++e)
        CHECK(mesh.element_fibers.col(e).norm() == Approx(1.0));
    CHECK(face.landmarks.size() >= 40);
    CHECK(std::set<int>(face.landmarks.begin(), face.landmarks.end()).size() == face.landmarks.size());
    CHECK(face.cranium_nodes.size() > 20);
    CHECK(face.jaw_nodes.size() > 20);
    std::set<int> cranium(face.cranium_nodes.begin(), face.cranium_nodes.end());
    for (const int n : face.jaw_nodes) {
        CHECK(cranium.count(n) == 0);
        CHECK(mesh.nodes(1, n) < shape.mouth_y);
    }
}

namespace {

/// Checks that the nodes that can touch `bone` lie outside it, and that
/// those of the inner surface over its top see it shape.skull_gap below
/// along z; returns how many did.
int check_tissue_over_bone(const FaceMesh& face, const FaceShape& shape, const SurfaceBody& bone)
{
    int over_the_bone = 0;
    for (const int n : face.skull_contact_nodes) {
        CAPTURE(n);
        const Eigen::Vector3d X = face.mesh.nodes.col(n);
        const SurfaceDistance d = bone.query(X);
        CHECK(d.distance > 0.0);
        // A node of the inner surface over the bone's top sees it the gap
        // below along z: at the distance gap·n_z along the top's normal n,
        // plus the facets' sag (cells of half the tets' spacing; the top is a
        // dome, its chords lie below it, so the sag only widens the gap).
        const double inner_z =
            shape.c * std::sqrt(1.0 - std::pow(X.x() / shape.a, 2) - std::pow(X.y() / shape.b, 2)) - shape.thickness;
        const bool inner = std::abs(X.z() - inner_z) < 1e-9;
        if (inner && d.feature == SurfaceFeature::face && d.gradient.z() > 0.5 && X.y() > bone.lower().y() &&
            X.y() < bone.upper().y()) {
            ++over_the_bone;
            CHECK(d.distance >= 0.95 * shape.skull_gap * d.gradient.z());
            CHECK(d.distance <= shape.skull_gap * d.gradient.z() + 0.15 * shape.skull_gap);
        }
    }
    return over_the_bone;
}

} // namespace

TEST_CASE("face generator: the skull, maxilla and mandible lie the gap below the free tissue, which touches them "
          "nowhere at rest",
          "[mesh][face][contact]")
{
    FaceShape shape;
    shape.target_tets = 4000;
    shape.skull_gap = 0.001;
    const FaceMesh face = generate_face(shape);
    // Closed, oriented, self-intersection-free surfaces: SurfaceBody refuses anything else.
    const SurfaceBody skull(face.skull, "skull"), maxilla(face.maxilla, "maxilla"), mandible(face.mandible, "mandible");
    std::set<int> attached(face.cranium_nodes.begin(), face.cranium_nodes.end());
    attached.insert(face.jaw_nodes.begin(), face.jaw_nodes.end());
    REQUIRE(face.skull_contact_nodes.size() > 50);
    for (const int n : face.skull_contact_nodes)
        CHECK(attached.count(n) == 0);
    CHECK(check_tissue_over_bone(face, shape, skull) > 20);
    CHECK(check_tissue_over_bone(face, shape, maxilla) > 10);
    CHECK(check_tissue_over_bone(face, shape, mandible) > 10);
    // The jaws split the skull's band at the mouth, the bite gap apart.
    CHECK(maxilla.upper().y() == Approx(skull.upper().y()));
    CHECK(mandible.lower().y() == Approx(skull.lower().y()));
    CHECK(maxilla.lower().y() - mandible.upper().y() == Approx(FaceGeometry::bite_gap()));
    CHECK(0.5 * (maxilla.lower().y() + mandible.upper().y()) == Approx(shape.mouth_y));
    // Each attachment is above its bone's top too: bone under tissue, not in it.
    for (const int n : face.cranium_nodes) {
        CHECK(skull.query(face.mesh.nodes.col(n)).distance > 0.0);
        CHECK(maxilla.query(face.mesh.nodes.col(n)).distance > 0.0);
    }
    for (const int n : face.jaw_nodes)
        CHECK(mandible.query(face.mesh.nodes.col(n)).distance > 0.0);
}

TEST_CASE("face generator: shapes out of range are refused", "[mesh][face][errors]")
{
    FaceShape shape;
    shape.target_tets = 10;
    CHECK_THROWS_AS(generate_face(shape), InputError);
    shape = FaceShape{};
    shape.rho = 1.0;
    CHECK_THROWS_AS(generate_face(shape), InputError);
    shape = FaceShape{};
    shape.mouth_y = -0.2;
    CHECK_THROWS_AS(generate_face(shape), InputError);
    shape = FaceShape{};
    shape.thickness = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(generate_face(shape), InputError);
    for (const double gap : {-1e-3, 0.02, std::numeric_limits<double>::infinity()}) {
        CAPTURE(gap);
        shape = FaceShape{};
        shape.skull_gap = gap;
        CHECK_THROWS_AS(generate_face(shape), InputError);
    }
}
