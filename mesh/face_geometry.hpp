#pragma once
// The generated face's shape as functions of (x, y): its outer surface, the
// thickness coordinate, tangents, the face's outline and the mouth
// (mesh/face_mesh.hpp). Shared by the face's tets and its skull.
#include "sinew/mesh/face_mesh.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace sinew {

/// The outer surface as a height field, its slope, and the thickness coordinate w.
struct FaceGeometry {
    FaceShape shape;

    double root(double x, double y) const
    {
        return std::sqrt(std::max(0.0, 1.0 - x * x / (shape.a * shape.a) - y * y / (shape.b * shape.b)));
    }
    /// z of the outer surface over (x, y).
    double outer_z(double x, double y) const { return shape.c * root(x, y); }
    /// The point at (x, y) and thickness fraction w ∈ [0, 1] (0 inner, 1 outer).
    Eigen::Vector3d point(double x, double y, double w) const
    {
        return {x, y, outer_z(x, y) - (1.0 - w) * shape.thickness};
    }
    double thickness_fraction(const Eigen::Vector3d& p) const
    {
        return 1.0 - (outer_z(p.x(), p.y()) - p.z()) / shape.thickness;
    }
    /// A direction (dx, dy) of the plane lifted onto the outer surface's tangent plane, unit.
    Eigen::Vector3d tangent(double x, double y, const Eigen::Vector2d& d) const
    {
        const double s = std::max(root(x, y), 1e-6);
        const double zx = -shape.c * x / (shape.a * shape.a * s), zy = -shape.c * y / (shape.b * shape.b * s);
        return Eigen::Vector3d(d.x(), d.y(), zx * d.x() + zy * d.y()).normalized();
    }
    bool inside_face(double x, double y) const
    {
        return x * x / (shape.a * shape.a) + y * y / (shape.b * shape.b) <= shape.rho * shape.rho;
    }
    /// Half the face's width at height y: the trimmed ellipse's x extent (0 beyond it).
    double half_width(double y) const
    {
        const double r = shape.rho * shape.b;
        return shape.rho * shape.a * std::sqrt(std::max(0.0, 1.0 - y * y / (r * r)));
    }
    /// The bone attachments of the inner surface: above cranium_bottom() to
    /// the cranium; below jaw_top() and within jaw_half_width() of x = 0 to
    /// the mandible; lips and cheeks between them free.
    double cranium_bottom() const { return shape.mouth_y + 0.02; }
    double jaw_top() const { return shape.mouth_y - 0.012; }
    static constexpr double jaw_half_width() { return 0.05; }
    /// The gap between the upper and lower teeth at rest, centred on the
    /// mouth's centre line y = mouth_y (m).
    static constexpr double bite_gap() { return 0.002; }
    bool inside_mouth(double x, double y, double margin = 0.0) const
    {
        const double u = x / (shape.mouth_half_width + margin), v = (y - shape.mouth_y) / (shape.mouth_half_height + margin);
        return u * u + v * v <= 1.0;
    }
};

} // namespace sinew
