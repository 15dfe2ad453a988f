#pragma once
#include <Eigen/Core>

#include <string>

namespace sinew {

/// The signed distance φ to a rigid body at a point and its derivatives
/// (φ > 0 outside, < 0 inside, ∇φ a unit vector).
struct BodyDistance {
    double distance = 0.0;                                ///< φ, m
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();   ///< ∇φ
    Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();    ///< ∇²φ, 1/m
};

/// A rigid collision body in its own frame, known through its signed
/// distance: an analytic plane or ball (2D or 3D), a closed triangle surface
/// (SurfaceBody), a level set. Contact potentials and gap constraints see
/// bodies only through this interface (docs/contact.md). A 2D body answers
/// for points (x, y, 0) and its ∇φ and ∇²φ live in the top-left 2 × 2 block.
class CollisionBody {
public:
    virtual ~CollisionBody() = default;
    /// The body's name in messages ("plane", "sphere", the file's name).
    virtual std::string name() const = 0;
    /// "plane", "sphere", "surface", "level-set".
    virtual std::string kind() const = 0;
    /// 2 or 3: the scenes the body can collide with.
    virtual int dimension() const = 0;
    /// φ, ∇φ and ∇²φ at x (body frame). Where ∇φ is undefined (the centre
    /// of a ball) the gradient and Hessian are zero.
    virtual BodyDistance distance(const Eigen::Vector3d& x) const = 0;
};

} // namespace sinew
