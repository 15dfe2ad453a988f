#include "sinew/mesh/helical_fibers.hpp"

#include "sinew/core/input_error.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace sinew {

Eigen::Vector3d helix_tangent(const HelixField& helix, const Eigen::Vector3d& X, double on_axis)
{
    const Eigen::Vector3d d = X - helix.point;
    const Eigen::Vector3d r = d - d.dot(helix.axis) * helix.axis;
    const double radius = r.norm();
    if (!(radius > on_axis))
        return helix.axis;
    const Eigen::Vector3d around = helix.axis.cross(r / radius);  // â × r̂, the circle's tangent
    return std::cos(helix.angle) * helix.axis + std::sin(helix.angle) * around;
}

Eigen::MatrixXd helical_fibers(const Mesh& mesh, const HelixField& helix)
{
    if (mesh.kind != ElementKind::tetrahedron)
        throw InputError("a helical fiber field needs a tet mesh, not " + to_string(mesh.kind) + " elements");
    const Eigen::Vector3d extent = mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff();
    const double on_axis = 1e-12 * extent.norm();
    Eigen::MatrixXd fibers(3, mesh.num_elements());
    for (int e = 0; e < mesh.num_elements(); ++e) {
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int n = 0; n < 4; ++n)
            centroid += mesh.nodes.col(mesh.elements(n, e)) / 4.0;
        fibers.col(e) = helix_tangent(helix, centroid, on_axis);
    }
    return fibers;
}

} // namespace sinew
