#pragma once
#include "sinew/bodies/collision_body.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>

namespace sinew {

struct Mesh;

/// The closest feature of a body's surface to a point.
enum class SurfaceFeature { face, edge, vertex };

/// The signed distance φ to a rigid body's surface at a point, with what its
/// derivatives need (φ > 0 outside, < 0 inside):
///   ∇φ = s u,  u = (x − p)/|x − p|, s = sign φ (the face's outward normal on the surface);
///   ∇²φ = s/ρ · (I − uuᵀ) at a vertex, s/ρ · (I − eeᵀ − uuᵀ) on an edge of
///   direction e, 0 on a face, ρ = |x − p|: the surface seen from x is a
///   sphere, a cylinder or a plane.
struct SurfaceDistance {
    double distance = 0.0;        ///< φ
    Eigen::Vector3d closest;      ///< p, the closest surface point
    Eigen::Vector3d gradient;     ///< ∇φ, a unit vector
    SurfaceFeature feature = SurfaceFeature::face;
    Eigen::Vector3d edge_direction = Eigen::Vector3d::Zero();  ///< e, for an edge
    /// ∇²φ as above (zero on a face and on the surface itself).
    Eigen::Matrix3d hessian() const;
};

/// A rigid collision body bounded by a closed triangle surface (an OBJ),
/// queried through CGAL's AABB tree (closest point) and its
/// Side_of_triangle_mesh (inside or out) — never a hand-written BVH. The
/// surface must be a closed, oriented 2-manifold without self-intersections;
/// triangles may face inward or outward (orientation is fixed on load).
class SurfaceBody final : public CollisionBody {
public:
    /// `surface` a 3D triangle mesh (Mesh of kind triangle_3d). InputError,
    /// one line naming `name` and the defect: fewer than 4 triangles, a
    /// degenerate triangle, a non-manifold edge or vertex, an open boundary
    /// (with the number of border edges), a self-intersection.
    SurfaceBody(const Mesh& surface, const std::string& name);
    ~SurfaceBody() override;
    SurfaceBody(SurfaceBody&&) noexcept;
    SurfaceBody& operator=(SurfaceBody&&) noexcept;

    /// read_obj(path), then as above; errors name the file.
    static SurfaceBody from_obj(const std::string& path);

    std::string name() const override { return name_; }
    std::string kind() const override { return "surface"; }
    int dimension() const override { return 3; }
    /// φ and its derivative data at x (body frame).
    SurfaceDistance query(const Eigen::Vector3d& x) const;
    /// query(x) as φ, ∇φ, ∇²φ.
    BodyDistance distance(const Eigen::Vector3d& x) const override;
    /// The axis-aligned bounds of the surface, min and max corners.
    Eigen::Vector3d lower() const { return lower_; }
    Eigen::Vector3d upper() const { return upper_; }

private:
    struct Geometry;  ///< the CGAL surface, tree and side oracle (kept out of this header)
    std::unique_ptr<Geometry> geometry_;
    std::string name_;
    Eigen::Vector3d lower_, upper_;
};

} // namespace sinew
