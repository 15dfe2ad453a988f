#include "sinew/mpm/particle_measures.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace sinew {
namespace {

/// a × b as a 3-vector (z only in 2D).
AngularMomentum cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    return {0.0, 0.0, a[0] * b[1] - a[1] * b[0]};
}
AngularMomentum cross(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a.cross(b); }

/// (ε : Mᵀ)_k = Σ_ab ε_kab M_ba: the axial vector of M − Mᵀ.
AngularMomentum axial(const Eigen::Matrix2d& M) { return {0.0, 0.0, M(1, 0) - M(0, 1)}; }
AngularMomentum axial(const Eigen::Matrix3d& M)
{
    return {M(2, 1) - M(1, 2), M(0, 2) - M(2, 0), M(1, 0) - M(0, 1)};
}

} // namespace

template <int Dim>
double total_mass(const Particles<Dim>& particles)
{
    double m = 0.0;
    for (double mp : particles.mass)
        m += mp;
    return m;
}

template <int Dim>
Eigen::Matrix<double, Dim, 1> linear_momentum(const Particles<Dim>& particles)
{
    Eigen::Matrix<double, Dim, 1> p = Eigen::Matrix<double, Dim, 1>::Zero();
    for (int k = 0; k < particles.size(); ++k)
        p += particles.mass[static_cast<std::size_t>(k)] * particles.v[static_cast<std::size_t>(k)];
    return p;
}

template <int Dim>
AngularMomentum angular_momentum(const Particles<Dim>& particles, double inertia_D)
{
    AngularMomentum L = AngularMomentum::Zero();
    for (int k = 0; k < particles.size(); ++k) {
        const auto i = static_cast<std::size_t>(k);
        // m_p (x_p × v_p + ε : (C_p D)ᵀ), D = inertia_D · I
        L += particles.mass[i] * (cross(particles.x[i], particles.v[i]) + inertia_D * axial(particles.C[i]));
    }
    return L;
}

template <int Dim>
double kinetic_energy(const Particles<Dim>& particles)
{
    double e = 0.0;
    for (int k = 0; k < particles.size(); ++k)
        e += 0.5 * particles.mass[static_cast<std::size_t>(k)] * particles.v[static_cast<std::size_t>(k)].squaredNorm();
    return e;
}

template <int Dim>
double elastic_energy(const Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models)
{
    double e = 0.0;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        const double psi = models.at(static_cast<std::size_t>(particles.material[i]))->energy(particles.F[i], particles.point[i]);
        if (!std::isfinite(psi))
            return std::numeric_limits<double>::infinity();
        e += particles.volume[i] * psi;  // V_p⁰ ψ(F_p)
    }
    return e;
}

template <int Dim>
double total_mass(const SparseGrid<Dim>& grid)
{
    double m = 0.0;
    for (double mi : grid.mass)
        m += mi;
    return m;
}

template <int Dim>
Eigen::Matrix<double, Dim, 1> linear_momentum(const SparseGrid<Dim>& grid)
{
    Eigen::Matrix<double, Dim, 1> p = Eigen::Matrix<double, Dim, 1>::Zero();
    for (int slot = 0; slot < grid.slots(); ++slot)
        p += grid.mass[static_cast<std::size_t>(slot)] * grid.velocity[static_cast<std::size_t>(slot)];
    return p;
}

template <int Dim>
AngularMomentum angular_momentum(const SparseGrid<Dim>& grid)
{
    AngularMomentum L = AngularMomentum::Zero();
    for (int slot = 0; slot < grid.slots(); ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        L += grid.mass[s] * cross(grid.position(slot), grid.velocity[s]);
    }
    return L;
}

template double total_mass<2>(const Particles<2>&);
template double total_mass<3>(const Particles<3>&);
template Eigen::Matrix<double, 2, 1> linear_momentum<2>(const Particles<2>&);
template Eigen::Matrix<double, 3, 1> linear_momentum<3>(const Particles<3>&);
template AngularMomentum angular_momentum<2>(const Particles<2>&, double);
template AngularMomentum angular_momentum<3>(const Particles<3>&, double);
template double kinetic_energy<2>(const Particles<2>&);
template double kinetic_energy<3>(const Particles<3>&);
template double elastic_energy<2>(const Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&);
template double elastic_energy<3>(const Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&);
template double total_mass<2>(const SparseGrid<2>&);
template double total_mass<3>(const SparseGrid<3>&);
template Eigen::Matrix<double, 2, 1> linear_momentum<2>(const SparseGrid<2>&);
template Eigen::Matrix<double, 3, 1> linear_momentum<3>(const SparseGrid<3>&);
template AngularMomentum angular_momentum<2>(const SparseGrid<2>&);
template AngularMomentum angular_momentum<3>(const SparseGrid<3>&);

} // namespace sinew
