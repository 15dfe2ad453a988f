#include "sinew/bodies/analytic_obstacle.hpp"

#include "sinew/core/input_error.hpp"

#include <algorithm>
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

/// The signed distance to the box |x − c| < h (per axis) of `dimension` axes.
class BoxBody final : public CollisionBody {
public:
    BoxBody(const Eigen::Vector3d& center, const Eigen::Vector3d& half, int dimension)
        : center_(center), half_(half), dimension_(dimension)
    {
    }
    std::string name() const override { return "box"; }
    std::string kind() const override { return "box"; }
    int dimension() const override { return dimension_; }
    BodyDistance distance(const Eigen::Vector3d& x) const override
    {
        BodyDistance d;
        Eigen::Vector3d q = Eigen::Vector3d::Constant(-HUGE_VAL), sign = Eigen::Vector3d::Zero(),
                        r = Eigen::Vector3d::Zero();
        for (int a = 0; a < dimension_; ++a) {
            sign[a] = x[a] < center_[a] ? -1.0 : 1.0;
            q[a] = std::abs(x[a] - center_[a]) - half_[a];  // q = |x − c| − h
            r[a] = std::max(q[a], 0.0);
        }
        const double outside = r.norm();
        if (outside > 0.0) {
            d.distance = outside;
            d.gradient = sign.cwiseProduct(r) / outside;
            Eigen::Matrix3d P = Eigen::Matrix3d::Zero();
            for (int a = 0; a < dimension_; ++a)
                P(a, a) = q[a] > 0.0 ? 1.0 : 0.0;
            d.hessian = (P - d.gradient * d.gradient.transpose()) / outside;
            return d;
        }
        int axis = 0;
        for (int a = 1; a < dimension_; ++a)
            if (q[a] > q[axis])
                axis = a;
        d.distance = q[axis];
        d.gradient[axis] = sign[axis];
        return d;
    }

private:
    Eigen::Vector3d center_;
    Eigen::Vector3d half_;
    int dimension_;
};

} // namespace

std::string obstacle_kind(const AnalyticObstacle& obstacle)
{
    return std::holds_alternative<PlaneObstacle>(obstacle) ? "plane"
           : std::holds_alternative<SphereObstacle>(obstacle) ? "sphere"
                                                               : "box";
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
    if (const auto* box = std::get_if<BoxObstacle>(&obstacle)) {
        if (box->lower.size() != dimension || box->upper.size() != dimension)
            throw InputError("box obstacle: corners have " + std::to_string(box->lower.size()) + " and " +
                             std::to_string(box->upper.size()) + " components, expected " + std::to_string(dimension));
        if (!box->lower.allFinite() || !box->upper.allFinite() || !(box->lower.array() < box->upper.array()).all())
            throw InputError("box obstacle: the corners must be finite and upper above lower in every axis");
        return std::make_shared<BoxBody>(embedded(0.5 * (box->lower + box->upper)),
                                         embedded(0.5 * (box->upper - box->lower)), dimension);
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
