#include "sinew/bodies/analytic_obstacle.hpp"

#include "sinew/core/input_error.hpp"

#include <cmath>

namespace sinew {
namespace {

/// The first `dimension` entries of a 3-vector from a 2- or 3-vector.
Eigen::Vector3d embedded(const Eigen::VectorXd& v)
{
    Eigen::Vector3d out = Eigen::Vector3d::Zero();
    out.head(v.size()) = v;
    return out;
}

/// φ(x) = n̂·x − δ with n̂ unit: a plane (a line in 2D).
class PlaneBody final : public CollisionBody {
public:
    PlaneBody(const Eigen::Vector3d& unit_normal, double offset, int dimension)
        : normal_(unit_normal), offset_(offset), dimension_(dimension)
    {
    }
    std::string name() const override { return "plane"; }
    std::string kind() const override { return "plane"; }
    int dimension() const override { return dimension_; }
    BodyDistance distance(const Eigen::Vector3d& x) const override
    {
        BodyDistance d;
        d.distance = normal_.dot(x) - offset_;
        d.gradient = normal_;
        return d;
    }

private:
    Eigen::Vector3d normal_;
    double offset_;
    int dimension_;
};

/// φ(x) = |x − c| − r: a ball (a disc in 2D).
class SphereBody final : public CollisionBody {
public:
    SphereBody(const Eigen::Vector3d& center, double radius, int dimension)
        : center_(center), radius_(radius), dimension_(dimension)
    {
    }
    std::string name() const override { return "sphere"; }
    std::string kind() const override { return "sphere"; }
    int dimension() const override { return dimension_; }
    BodyDistance distance(const Eigen::Vector3d& x) const override
    {
        BodyDistance d;
        const Eigen::Vector3d v = x - center_;
        const double rho = v.norm();  // ρ
        d.distance = rho - radius_;
        if (rho > 0.0) {
            d.gradient = v / rho;  // u
            d.hessian = (Eigen::Matrix3d::Identity() - d.gradient * d.gradient.transpose()) / rho;
        }
        return d;
    }

private:
    Eigen::Vector3d center_;
    double radius_;
    int dimension_;
};

} // namespace

std::string obstacle_kind(const AnalyticObstacle& obstacle)
{
    return std::holds_alternative<PlaneObstacle>(obstacle) ? "plane" : "sphere";
}

std::shared_ptr<const CollisionBody> analytic_body(const AnalyticObstacle& obstacle, int dimension)
{
    if (const auto* plane = std::get_if<PlaneObstacle>(&obstacle)) {
        if (plane->normal.size() != dimension)
            throw InputError("plane obstacle: normal has " + std::to_string(plane->normal.size()) +
                             " components, expected " + std::to_string(dimension));
        const double length = plane->normal.norm();
        if (!std::isfinite(plane->offset) || !std::isfinite(length) || !(length > 0.0))
            throw InputError("plane obstacle: normal must be nonzero and finite, offset finite");
        return std::make_shared<PlaneBody>(embedded(plane->normal / length), plane->offset / length, dimension);
    }
    const auto& sphere = std::get<SphereObstacle>(obstacle);
    if (sphere.center.size() != dimension)
        throw InputError("sphere obstacle: center has " + std::to_string(sphere.center.size()) +
                         " components, expected " + std::to_string(dimension));
    if (!sphere.center.allFinite())
        throw InputError("sphere obstacle: center is not finite");
    if (!(std::isfinite(sphere.radius) && sphere.radius > 0.0))
        throw InputError("sphere obstacle: radius " + std::to_string(sphere.radius) + " must be finite and > 0");
    return std::make_shared<SphereBody>(embedded(sphere.center), sphere.radius, dimension);
}

} // namespace sinew
