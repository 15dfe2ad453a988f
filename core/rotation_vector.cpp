#include "sinew/core/rotation_vector.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace sinew {
namespace {

/// Below this angle a, b and their derivatives come from their Taylor
/// series (truncation below 1e-16 relative), above it from the closed forms,
/// whose cancellation error there is at most ~1e-12 of the terms they scale.
constexpr double kSeriesAngle = 1e-2;

/// The scalar functions of θ in R = I + a[ω]× + b[ω]×² and their
/// derivatives divided by θ: c = a'(θ)/θ, d = b'(θ)/θ, so ∂a/∂ω_k = c ω_k.
struct RodriguesCoefficients {
    double a, b, c, d;
};

RodriguesCoefficients coefficients(double theta)
{
    const double t2 = theta * theta;
    if (theta < kSeriesAngle)
        return {1.0 - t2 / 6.0 + t2 * t2 / 120.0, 0.5 - t2 / 24.0 + t2 * t2 / 720.0,
                -1.0 / 3.0 + t2 / 30.0 - t2 * t2 / 840.0, -1.0 / 12.0 + t2 / 180.0 - t2 * t2 / 6720.0};
    const double s = std::sin(theta), co = std::cos(theta);
    return {s / theta, (1.0 - co) / t2, (theta * co - s) / (t2 * theta), (theta * s - 2.0 * (1.0 - co)) / (t2 * t2)};
}

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d K;
    K << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return K;
}

} // namespace

Eigen::Matrix3d rotation_matrix(const Eigen::Vector3d& omega)
{
    const RodriguesCoefficients k = coefficients(omega.norm());
    const Eigen::Matrix3d W = cross_matrix(omega);
    return Eigen::Matrix3d::Identity() + k.a * W + k.b * W * W;
}

std::array<Eigen::Matrix3d, 3> rotation_matrix_derivatives(const Eigen::Vector3d& omega)
{
    const RodriguesCoefficients k = coefficients(omega.norm());
    const Eigen::Matrix3d W = cross_matrix(omega);
    std::array<Eigen::Matrix3d, 3> dR;
    for (int i = 0; i < 3; ++i) {
        const Eigen::Matrix3d E = cross_matrix(Eigen::Vector3d::Unit(i));
        // ∂R/∂ω_i = a [e_i]× + b([e_i]×[ω]× + [ω]×[e_i]×) + c ω_i [ω]× + d ω_i [ω]×²
        dR[i] = k.a * E + k.b * (E * W + W * E) + omega[i] * (k.c * W + k.d * W * W);
    }
    return dR;
}

Eigen::Vector3d rotation_vector(const Eigen::Matrix3d& R)
{
    const Eigen::AngleAxisd angle_axis(R);
    return angle_axis.angle() * angle_axis.axis();
}

} // namespace sinew
