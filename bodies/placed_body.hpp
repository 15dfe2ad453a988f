#pragma once
#include "sinew/bodies/collision_body.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>

namespace sinew {

/// A collision body placed in the scene by a rigid motion y ↦ x = R y + t (y
/// in the body's frame), which a load factor or time may change between
/// solves (prescribed motion). In the scene's frame
///     φ(x) = φ_b(Rᵀ(x − t)),  ∇φ = R ∇φ_b,  ∇²φ = R ∇²φ_b Rᵀ.
/// One placement is shared by every contact term on the body, so that
/// moving it moves them all.
class PlacedBody {
public:
    /// `name` for messages ("" keeps the body's own). InputError for a null body.
    explicit PlacedBody(std::shared_ptr<const CollisionBody> body, std::string name = "");

    const CollisionBody& body() const { return *body_; }
    const std::string& name() const { return name_; }
    int dimension() const { return body_->dimension(); }

    /// R (a rotation: RᵀR = I, det R = 1) and t. InputError otherwise, or for
    /// a non-finite entry; a 2D body turns about z only.
    void set_placement(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation);
    /// An affine placement y ↦ x = A y + t of a 3D body, A invertible: a body
    /// carried by a map that is a rotation only at a solution (the rig's jaw
    /// map between fit iterates, inverse/muscle_rig.hpp). Then
    ///     φ(x) = φ_b(A⁻¹(x − t)),  ∇φ = A⁻ᵀ∇φ_b,  ∇²φ = A⁻ᵀ∇²φ_b A⁻¹,
    /// a signed distance when A is a rotation. InputError for a non-finite
    /// entry, a 2D body, or |det A| ≤ 1e-12 ‖A‖³.
    void set_affine_placement(const Eigen::Matrix3d& map, const Eigen::Vector3d& translation);
    /// The placement's linear part: R, or A of an affine placement.
    const Eigen::Matrix3d& rotation() const { return map_; }
    /// Its inverse: Rᵀ, or A⁻¹.
    const Eigen::Matrix3d& inverse_map() const { return inverse_; }
    const Eigen::Vector3d& translation() const { return translation_; }

    /// φ and its derivatives at x, scene frame (x of a 2D scene as (x, y, 0)).
    BodyDistance distance(const Eigen::Vector3d& x) const;

private:
    std::shared_ptr<const CollisionBody> body_;
    std::string name_;
    Eigen::Matrix3d map_ = Eigen::Matrix3d::Identity();
    Eigen::Matrix3d inverse_ = Eigen::Matrix3d::Identity();
    Eigen::Vector3d translation_ = Eigen::Vector3d::Zero();
};

} // namespace sinew
