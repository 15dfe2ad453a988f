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
    rotation_ = rotation;
    translation_ = translation;
}

BodyDistance PlacedBody::distance(const Eigen::Vector3d& x) const
{
    BodyDistance d = body_->distance(rotation_.transpose() * (x - translation_));  // φ_b(Rᵀ(x − t))
    d.gradient = rotation_ * d.gradient;                                    // R ∇φ_b
    d.hessian = rotation_ * d.hessian * rotation_.transpose();              // R ∇²φ_b Rᵀ
    return d;
}

} // namespace sinew
