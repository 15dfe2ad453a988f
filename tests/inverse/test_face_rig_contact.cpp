#include "sinew/bodies/surface_body.hpp"
#include "sinew/inverse/face_rig.hpp"
#include "sinew/inverse/muscle_rig.hpp"
#include "sinew/mesh/face_mesh.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace sinew;

namespace {

/// The lowest signed distance of the contact nodes of `x` (all coordinates,
/// node-major) to `bone` after mapping each into the bone's frame by
/// y = M⁻¹(x − t); also counts the nodes within `near` of it.
double lowest_distance(const FaceMesh& face, const Eigen::VectorXd& x, const SurfaceBody& bone,
                       const Eigen::Matrix3d& M, const Eigen::Vector3d& t, double near, int& near_count)
{
    double lowest = std::numeric_limits<double>::infinity();
    near_count = 0;
    for (const int n : face.skull_contact_nodes) {
        const Eigen::Vector3d y = M.inverse() * (x.segment<3>(3 * n) - t);
        const double d = bone.query(y).distance;
        lowest = std::min(lowest, d);
        near_count += d < near ? 1 : 0;
    }
    return lowest;
}

} // namespace

TEST_CASE("face rig with contact: the cranium holds the maxilla and the jaw carries the mandible as it opens",
          "[inverse][rig][face][contact]")
{
    FaceShape shape;
    shape.target_tets = 3000;
    const FaceMesh face = generate_face(shape);
    const RigDefinition definition = face_rig(face, {}, true);
    REQUIRE(definition.contact);
    REQUIRE(definition.jaw_contact);
    EquilibriumSolveSettings settings;
    settings.options.tolerance = 1e-10;
    settings.options.max_iterations = 200;
    MuscleRig rig(definition, settings);

    // The lips tightened (every muscle at 0.5) with the jaw rotated open by
    // 8° about its hinge axis (along x): x = R(X − p) + p.
    RigParameters theta = RigParameters::neutral(rig.num_muscles());
    theta.activations.setConstant(0.5);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(8.0 * M_PI / 180.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
    theta.jaw_map = R;
    theta.jaw_translation = face.hinge_point - R * face.hinge_point;
    const RigEvaluation evaluation = rig.evaluate(theta);
    REQUIRE(evaluation.ok);
    const Eigen::VectorXd x = rig.positions();

    // The penalty keeps every node within a small depth of both bones, the
    // mandible where the jaw map put it; and the jaw's attachment moved with
    // the jaw.
    const double depth = 1e-4;
    CHECK(rig.max_penetration() > 0.0);
    CHECK(rig.max_penetration() < depth);
    for (const int n : face.jaw_nodes)
        CHECK((x.segment<3>(3 * n) - (R * face.mesh.nodes.col(n) + theta.jaw_translation)).norm() < 1e-12);
    const SurfaceBody maxilla(face.maxilla, "maxilla"), mandible(face.mandible, "mandible");
    int on_maxilla = 0, on_mandible = 0, on_resting_mandible = 0;
    const double near = 2.0 * shape.skull_gap;
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    CHECK(lowest_distance(face, x, maxilla, I, zero, near, on_maxilla) > -depth);
    CHECK(lowest_distance(face, x, mandible, R, theta.jaw_translation, near, on_mandible) > -depth);
    // The lips rest on both: the upper on the maxilla, the lower on the
    // mandible in its moved place, which is millimetres from where it rested
    // (a mandible left at rest would have the lower lip in it, or far off).
    CHECK(on_maxilla > 10);
    CHECK(on_mandible > 10);
    const double resting = lowest_distance(face, x, mandible, I, zero, near, on_resting_mandible);
    CAPTURE(resting, on_mandible, on_resting_mandible);
    CHECK((resting < -10.0 * depth || on_resting_mandible < on_mandible / 2));
}
