#include "sinew/bodies/placed_body.hpp"

#include "sinew/core/input_error.hpp"

#include <Eigen/LU>

#include <cmath>

namespace sinew {

PlacedBody::PlacedBody(std::shared_ptr<const CollisionBody> body, std::string name)
    : body_(std::move(body)), name_(std::move(name))
{
    if (!body_)
        throw InputError("collision body: none given");
    if (name_.empty())
        name_ = body_->name();
}

void PlacedBody::set_placement(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation)
{
    const std::string who = "body '" + name() + "': ";
    if (!rotation.allFinite() || !translation.allFinite())
        throw InputError(who + "the placement is not finite");
    if ((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm() > 1e-9 ||
        !(rotation.determinant() > 0.0))
        throw InputError(who + "the placement's rotation is not a rotation (RᵀR ≠ I or det R ≤ 0)");
    if (dimension() == 2 && (std::abs(rotation(2, 2) - 1.0) > 1e-9 || translation[2] != 0.0))
        throw InputError(who + "a 2D body moves in the plane z = 0 only");
    map_ = rotation;
    inverse_ = rotation.transpose();
    translation_ = translation;
}

void PlacedBody::set_affine_placement(const Eigen::Matrix3d& map, const Eigen::Vector3d& translation)
{
    const std::string who = "body '" + name() + "': ";
    if (!map.allFinite() || !translation.allFinite())
        throw InputError(who + "the placement is not finite");
    if (dimension() != 3)
        throw InputError(who + "an affine placement needs a 3D body");
    const double scale = map.norm();
    if (!(std::abs(map.determinant()) > 1e-12 * scale * scale * scale))
        throw InputError(who + "the placement's map is singular");
    map_ = map;
    inverse_ = map.inverse();
    translation_ = translation;
}

BodyDistance PlacedBody::distance(const Eigen::Vector3d& x) const
{
    BodyDistance d = body_->distance(inverse_ * (x - translation_));  // φ_b(A⁻¹(x − t)), A = R: Rᵀ
    d.gradient = inverse_.transpose() * d.gradient;                   // A⁻ᵀ ∇φ_b
    d.hessian = inverse_.transpose() * d.hessian * inverse_;          // A⁻ᵀ ∇²φ_b A⁻¹
    return d;
}

} // namespace sinew
