#include "sinew/bodies/surface_body.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/mesh.hpp"
#include "sinew/mesh/obj_reader.hpp"

#include <Eigen/Geometry>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

namespace sinew {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Surface>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
using Side = CGAL::Side_of_triangle_mesh<Surface, Kernel>;
namespace PMP = CGAL::Polygon_mesh_processing;

Eigen::Vector3d to_eigen(const Point& p) { return {p.x(), p.y(), p.z()}; }

/// The surface as a CGAL mesh; InputError for what a closed 2-manifold cannot have.
Surface build_surface(const Mesh& mesh, const std::string& name)
{
    if (mesh.kind != ElementKind::triangle_3d)
        throw InputError("body '" + name + "': a collision surface is a 3D triangle mesh, not " + to_string(mesh.kind));
    if (mesh.elements.cols() < 4)
        throw InputError("body '" + name + "': " + std::to_string(mesh.elements.cols()) +
                         " triangles cannot close a volume (at least 4)");
    Surface surface;
    std::vector<Surface::Vertex_index> vertices;
    for (Eigen::Index i = 0; i < mesh.nodes.cols(); ++i)
        vertices.push_back(surface.add_vertex(Point(mesh.nodes(0, i), mesh.nodes(1, i), mesh.nodes(2, i))));
    for (Eigen::Index t = 0; t < mesh.elements.cols(); ++t) {
        const auto& e = mesh.elements.col(t);
        const Eigen::Vector3d a = mesh.nodes.col(e[0]), b = mesh.nodes.col(e[1]), c = mesh.nodes.col(e[2]);
        if ((b - a).cross(c - a).norm() <= 1e-14 * std::max(1.0, (b - a).squaredNorm() + (c - a).squaredNorm()))
            throw InputError("body '" + name + "': triangle " + std::to_string(t) + " is degenerate (zero area)");
        if (surface.add_face(vertices[e[0]], vertices[e[1]], vertices[e[2]]) == Surface::null_face())
            throw InputError("body '" + name + "': triangle " + std::to_string(t) +
                             " makes the surface non-manifold or flips the orientation of its neighbours");
    }
    int border_edges = 0;
    for (auto h : surface.halfedges())
        border_edges += surface.is_border(h) ? 1 : 0;
    if (border_edges > 0)
        throw InputError("body '" + name + "': the surface is open (" + std::to_string(border_edges) +
                         " border edges); a collision body must be closed");
    if (PMP::does_self_intersect(surface))
        throw InputError("body '" + name + "': the surface intersects itself");
    if (!PMP::is_outward_oriented(surface))
        PMP::reverse_face_orientations(surface);
    return surface;
}

Eigen::Vector3d face_normal(Surface::Face_index face, const Surface& surface)
{
    const auto n = PMP::compute_face_normal(face, surface);
    return {n.x(), n.y(), n.z()};
}

/// The feature of the surface that holds p, found in `face`: barycentric
/// coordinates at zero (relative 1e-10) mark an edge (one) or a vertex (two),
/// and a crease that is flat (its faces' normals parallel) counts as what it
/// looks like from outside: an edge between coplanar faces is a face, a
/// vertex whose faces have two normals an edge. Sets `edge` for an edge.
SurfaceFeature feature_at(const Eigen::Vector3d& p, Surface::Face_index face, const Surface& surface,
                          Eigen::Vector3d& edge)
{
    std::vector<Surface::Vertex_index> corners;
    for (auto v : CGAL::vertices_around_face(surface.halfedge(face), surface))
        corners.push_back(v);
    const Eigen::Vector3d a = to_eigen(surface.point(corners[0])), b = to_eigen(surface.point(corners[1])),
                          c = to_eigen(surface.point(corners[2]));
    const Eigen::Vector3d v0 = b - a, v1 = c - a, v2 = p - a;
    const double d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1), d20 = v2.dot(v0), d21 = v2.dot(v1);
    const double denominator = d00 * d11 - d01 * d01;
    const double beta = (d11 * d20 - d01 * d21) / denominator, gamma = (d00 * d21 - d01 * d20) / denominator;
    const double weights[3] = {1.0 - beta - gamma, beta, gamma};
    std::vector<Surface::Vertex_index> on;  // the corners with nonzero weight
    for (int k = 0; k < 3; ++k)
        if (weights[k] > 1e-10)
            on.push_back(corners[static_cast<size_t>(k)]);
    // The distinct normals of the faces that meet at the feature.
    std::vector<Eigen::Vector3d> normals;
    auto add_normal = [&](Surface::Face_index f) {
        const Eigen::Vector3d n = face_normal(f, surface);
        for (const Eigen::Vector3d& m : normals)
            if (n.dot(m) > 1.0 - 1e-12)
                return;
        normals.push_back(n);
    };
    if (on.size() == 3)
        return SurfaceFeature::face;
    if (on.size() == 2) {
        const auto h = surface.halfedge(on[0], on[1]);  // on[0] → on[1], in `face` or its neighbour
        add_normal(surface.face(h));
        add_normal(surface.face(surface.opposite(h)));
    } else {
        for (auto f : CGAL::faces_around_target(surface.halfedge(on.empty() ? corners[0] : on[0]), surface))
            add_normal(f);
    }
    if (normals.size() == 1)
        return SurfaceFeature::face;
    if (normals.size() == 2) {
        edge = normals[0].cross(normals[1]).normalized();
        return SurfaceFeature::edge;
    }
    return SurfaceFeature::vertex;
}

} // namespace

struct SurfaceBody::Geometry {
    Surface surface;
    Tree tree;
    std::unique_ptr<Side> side;

    explicit Geometry(Surface s) : surface(std::move(s)), tree(faces(surface).first, faces(surface).second, surface)
    {
        tree.accelerate_distance_queries();
        side = std::make_unique<Side>(surface);
    }
};

SurfaceBody::SurfaceBody(const Mesh& surface, const std::string& name)
    : geometry_(std::make_unique<Geometry>(build_surface(surface, name))), name_(name),
      lower_(surface.nodes.rowwise().minCoeff()), upper_(surface.nodes.rowwise().maxCoeff())
{
}

SurfaceBody::~SurfaceBody() = default;
SurfaceBody::SurfaceBody(SurfaceBody&&) noexcept = default;
SurfaceBody& SurfaceBody::operator=(SurfaceBody&&) noexcept = default;

SurfaceBody SurfaceBody::from_obj(const std::string& path) { return SurfaceBody(read_obj(path), path); }

SurfaceDistance SurfaceBody::query(const Eigen::Vector3d& x) const
{
    const Point q(x[0], x[1], x[2]);
    const auto [closest, face] = geometry_->tree.closest_point_and_primitive(q);
    SurfaceDistance d;
    d.closest = to_eigen(closest);
    const Surface& s = geometry_->surface;
    d.feature = feature_at(d.closest, face, s, d.edge_direction);
    const double rho = (x - d.closest).norm();
    const CGAL::Bounded_side side = (*geometry_->side)(q);
    const double sign = side == CGAL::ON_BOUNDED_SIDE ? -1.0 : side == CGAL::ON_UNBOUNDED_SIDE ? 1.0 : 0.0;
    d.distance = sign * rho;  // φ = s ρ
    if (rho > 0.0 && sign != 0.0)
        d.gradient = sign * (x - d.closest) / rho;  // ∇φ = s u
    else
        d.gradient = face_normal(face, s);  // on the surface: the outward normal
    return d;
}

BodyDistance SurfaceBody::distance(const Eigen::Vector3d& x) const
{
    const SurfaceDistance d = query(x);
    BodyDistance out;
    out.distance = d.distance;
    out.gradient = d.gradient;
    out.hessian = d.hessian();
    return out;
}

Eigen::Matrix3d SurfaceDistance::hessian() const
{
    const double rho = std::abs(distance);
    if (feature == SurfaceFeature::face || rho == 0.0)
        return Eigen::Matrix3d::Zero();
    const double sign = distance > 0.0 ? 1.0 : -1.0;
    const Eigen::Vector3d u = sign * gradient;  // (x − p)/ρ
    Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - u * u.transpose();
    if (feature == SurfaceFeature::edge)
        projector -= edge_direction * edge_direction.transpose();
    return sign / rho * projector;  // ∇²φ = s/ρ (I − uuᵀ [− eeᵀ])
}

} // namespace sinew
