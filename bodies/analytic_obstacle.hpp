#pragma once
#include "sinew/bodies/collision_body.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <variant>

namespace sinew {

/// A rigid obstacle filling the half-space n·x < d: nodes belong in n·x ≥ d.
/// Signed distance φ(x) = n̂·x − d/|n|.
struct PlaneObstacle {
    Eigen::VectorXd normal;  ///< n, pointing out of the obstacle (any length > 0)
    double offset = 0.0;     ///< d, m (times |n|)
};

/// A rigid solid ball |x − c| < r: nodes belong in |x − c| ≥ r.
/// Signed distance φ(x) = |x − c| − r.
struct SphereObstacle {
    Eigen::VectorXd center;  ///< c, m
    double radius = 0.0;     ///< r > 0, m
};

/// A rigid solid box lower < x < upper (a rectangle in 2D), axis-aligned in
/// the body's frame (a placement turns it): nodes belong outside.
struct BoxObstacle {
    Eigen::VectorXd lower;  ///< m
    Eigen::VectorXd upper;  ///< m, above lower in every axis
};

/// An analytic obstacle in 2D (a line, a disc, a rectangle) or 3D (a plane, a ball, a box).
using AnalyticObstacle = std::variant<PlaneObstacle, SphereObstacle, BoxObstacle>;

/// "plane", "sphere" or "box".
std::string obstacle_kind(const AnalyticObstacle& obstacle);

/// The obstacle as a collision body of `dimension` (2 or 3):
///   plane:  φ = n̂·x − d/|n|, ∇φ = n̂, ∇²φ = 0;
///   sphere: φ = ρ − r, ρ = |x − c|, ∇φ = u = (x − c)/ρ, ∇²φ = (I − uuᵀ)/ρ;
///   box:    with c the centre, h the half extents, q = |x − c| − h (per axis)
///           and r = max(q, 0): outside (some q_a > 0) φ = |r|,
///           ∇φ = sign(x − c) ∘ r/|r|, ∇²φ = (P − ∇φ∇φᵀ)/|r|, P the projection
///           on the axes with q_a > 0 (zero facing one face); inside
///           φ = max_a q_a, ∇φ = sign(x_a − c_a) e_a for its (first) axis a, ∇²φ = 0.
/// InputError for an obstacle of another dimension, a zero or non-finite
/// normal or centre, a non-finite offset, a non-positive radius, a box
/// whose upper corner is not above its lower one in every axis.
std::shared_ptr<const CollisionBody> analytic_body(const AnalyticObstacle& obstacle, int dimension);

} // namespace sinew
