#include "sinew/mpm/inextensibility/fiber_drift.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {

template <int Dim>
FiberDrift fiber_drift(const Particles<Dim>& particles, const InextensibilitySettings& settings)
{
    FiberDrift drift;
    double sum_squares = 0.0;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        if (!settings.carries(particles.material[i]))
            continue;
        const double error = (particles.F[i] * particles.point[i].fiber).squaredNorm() - 1.0;  // a₀ᵀ FᵀF a₀ − 1
        drift.max = std::max(drift.max, std::abs(error));
        sum_squares += error * error;
        ++drift.particles;
    }
    if (drift.particles > 0)
        drift.rms = std::sqrt(sum_squares / drift.particles);
    return drift;
}

template <int Dim>
void project_fiber_lengths(Particles<Dim>& particles, const InextensibilitySettings& settings)
{
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        const auto& a0 = particles.point[i].fiber;
        if (!settings.carries(particles.material[i]) || !(a0.squaredNorm() > 0.0))
            continue;
        const Eigen::Matrix<double, Dim, 1> a = particles.F[i] * a0;
        const double length = a.norm();
        if (length > 0.0)
            particles.F[i] += (1.0 / length - 1.0) * a * a0.transpose() / a0.squaredNorm();
    }
}

template FiberDrift fiber_drift<2>(const Particles<2>&, const InextensibilitySettings&);
template FiberDrift fiber_drift<3>(const Particles<3>&, const InextensibilitySettings&);
template void project_fiber_lengths<2>(Particles<2>&, const InextensibilitySettings&);
template void project_fiber_lengths<3>(Particles<3>&, const InextensibilitySettings&);

} // namespace sinew
