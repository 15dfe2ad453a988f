#pragma once
// A small rig for the inverse tests: a tissue slab of tets whose bottom face is
// attached half to the cranium, half (and a strip of one side) to the jaw, with two muscles of
// different fiber directions, and landmarks on the top face.
#include "sinew/bodies/analytic_obstacle.hpp"
#include "sinew/energies/potentials/element_model.hpp"
#include "sinew/inverse/rig_fit_run.hpp"
#include "sinew/inverse/muscle_rig.hpp"
#include "sinew/mesh/box_tets.hpp"
#include "sinew/problems/nlp.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <cmath>

namespace sinew::test {

inline RigDefinition slab_rig(int nx = 4, int ny = 3, int nz = 2)
{
    const Eigen::Vector3d lower(0.0, 0.0, 0.0), upper(0.04, 0.03, 0.015);
    RigDefinition rig;
    rig.mesh = box_tets(lower, upper, nx, ny, nz);
    Mesh& mesh = rig.mesh;
    mesh.group_names = {"tissue", "muscles"};
    mesh.element_fibers.resize(3, mesh.num_elements());
    rig.muscle_names = {"diagonal", "transverse"};
    rig.muscle_elements.resize(2);
    for (int e = 0; e < mesh.num_elements(); ++e) {
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int a = 0; a < 4; ++a)
            centroid += 0.25 * mesh.nodes.col(mesh.elements(a, e));
        const bool upper_half = centroid.z() > 0.5 * upper.z();
        const bool front = centroid.y() < 0.5 * upper.y();
        mesh.element_groups[e] = upper_half ? 1 : 0;
        mesh.element_fibers.col(e) = front ? Eigen::Vector3d(1.0, 1.0, 0.0).normalized() : Eigen::Vector3d(1.0, 0.0, 0.2).normalized();
        if (upper_half)
            rig.muscle_elements[front ? 0 : 1].push_back(e);
    }
    const ParameterValues tissue{{"A", 1000.0}, {"B", 500.0}, {"K", 1e5}, {"sigma_max", 0.0}};
    const ParameterValues muscle{{"A", 1000.0}, {"B", 500.0}, {"K", 1e5}, {"sigma_max", 2000.0}};
    rig.group_models = {make_element_model(ElementKind::tetrahedron, "mooney-rivlin-muscle", tissue),
                        make_element_model(ElementKind::tetrahedron, "mooney-rivlin-muscle", muscle)};
    for (int i = 0; i < mesh.num_nodes(); ++i) {
        const Eigen::Vector3d X = mesh.nodes.col(i);
        // The jaw holds a corner of two faces, so that its nodes span 3D and
        // every entry of M_j moves them.
        if (X.z() == lower.z())
            (X.x() < 0.5 * upper.x() ? rig.cranium_nodes : rig.jaw_nodes).push_back(i);
        else if (X.x() == upper.x() && X.z() < 0.6 * upper.z())
            rig.jaw_nodes.push_back(i);
        else if (X.z() == upper.z())
            rig.landmarks.push_back(i);
    }
    return rig;
}

/// Tight inner solves, so that differences of re-solves resolve 1e-6 of ∂x/∂θ.
inline EquilibriumSolveSettings tight_settings()
{
    EquilibriumSolveSettings settings;
    settings.options.tolerance = 1e-11;
    settings.options.kkt_tolerance = 1e-10;
    settings.options.max_iterations = 200;
    return settings;
}

/// The slab pressed by a rigid ball fixed in the cranium frame, 1 mm into its
/// top face at rest (seed 000 §5.7's penalty on the top nodes, ε = 10³ μ h,
/// μ = 2(A + B) = 3000 Pa, h = 1 cm).
inline RigDefinition slab_rig_pressed_by_ball()
{
    RigDefinition definition = slab_rig();
    const double radius = 0.02, top = 0.015;
    const AnalyticObstacle ball = SphereObstacle{Eigen::Vector3d(0.02, 0.015, top + radius - 0.001), radius};
    std::vector<int> top_nodes;
    for (int n = 0; n < definition.mesh.num_nodes(); ++n)
        if (definition.mesh.nodes(2, n) == top)
            top_nodes.push_back(n);
    definition.contact = RigContact{analytic_body(ball, 3), 1e3 * 3000.0 * 0.01, top_nodes};
    return definition;
}

/// The slab pressed by a rigid ball the jaw carries (placed by the jaw map,
/// as the lower teeth are), 3 mm into its top face at rest: the jaw's turn
/// in moved_parameters(8) lifts it about 2 mm.
inline RigDefinition slab_rig_pressed_by_ball_on_jaw()
{
    RigDefinition definition = slab_rig_pressed_by_ball();
    const double radius = 0.02, top = 0.015;
    const AnalyticObstacle ball = SphereObstacle{Eigen::Vector3d(0.02, 0.015, top + radius - 0.003), radius};
    definition.jaw_contact = RigContact{analytic_body(ball, 3), definition.contact->stiffness, definition.contact->nodes};
    definition.contact.reset();
    return definition;
}

/// A rig state away from rest: activations inside (0, 1), the jaw turned by
/// `jaw_degrees` about the x axis through the bottom face's front edge and
/// moved, the cranium slightly turned and moved.
inline RigParameters moved_parameters(double jaw_degrees)
{
    RigParameters theta = RigParameters::neutral(2);
    theta.activations << 0.35, 0.6;
    const double angle = jaw_degrees * M_PI / 180.0;
    theta.jaw_map = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()).toRotationMatrix();
    theta.jaw_translation = Eigen::Vector3d(0.001, -0.0005, 0.0008);
    theta.cranium_map = Eigen::AngleAxisd(0.05, Eigen::Vector3d(0.3, 1.0, 0.2).normalized()).toRotationMatrix();
    theta.cranium_translation = Eigen::Vector3d(0.002, 0.001, -0.003);
    return theta;
}

/// Targets of the rig at θ* (no noise), for run_rig_fit.
inline RigTargets targets_at(const RigDefinition& definition, const RigParameters& truth)
{
    MuscleRig rig(definition, tight_settings());
    REQUIRE(rig.evaluate(truth).ok);
    RigTargets targets;
    targets.truth = truth;
    targets.exact = targets.targets = rig.landmark_positions();
    targets.motion_rms = 1.0;
    return targets;
}

/// Central differences of a fit's objective, step h in every variable: each
/// side a full re-solve of the rig (the reference for adjoint gradients).
inline Eigen::VectorXd objective_differences(Nlp& nlp, const Eigen::VectorXd& x, double h = 1e-6)
{
    Eigen::VectorXd differences(x.size());
    for (Eigen::Index k = 0; k < x.size(); ++k) {
        Eigen::VectorXd plus = x, minus = x;
        plus[k] += h;
        minus[k] -= h;
        differences[k] = (nlp.objective(plus) - nlp.objective(minus)) / (2 * h);
    }
    return differences;
}

} // namespace sinew::test
