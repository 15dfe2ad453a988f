#pragma once
#include <Eigen/Core>

#include <string>
#include <variant>

namespace sinew {

/// A rigid obstacle filling the half-space n·x < d: nodes belong in n·x ≥ d.
/// Signed distance φ(x) = n̂·x − d/|n| (n normalized by the potential).
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

/// An analytic obstacle in 2D (a line, a disc) or 3D (a plane, a ball).
using AnalyticObstacle = std::variant<PlaneObstacle, SphereObstacle>;

/// "plane" or "sphere".
std::string obstacle_kind(const AnalyticObstacle& obstacle);

} // namespace sinew
