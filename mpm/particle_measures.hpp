#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/particles.hpp"
#include "sinew/mpm/sparse_grid.hpp"

#include <vector>

namespace sinew {

/// Angular momentum as a 3-vector (its z component in 2D).
using AngularMomentum = Eigen::Vector3d;

template <int Dim>
double total_mass(const Particles<Dim>& particles);
template <int Dim>
Eigen::Matrix<double, Dim, 1> linear_momentum(const Particles<Dim>& particles);
/// Σ_p m_p (x_p × v_p + ε : (C_p D_p)ᵀ), D_p = σ dx² I: APIC's angular
/// momentum, which its transfers conserve (Jiang et al. 2015, §5.3); the
/// affine part is zero for C_p = 0.
template <int Dim>
AngularMomentum angular_momentum(const Particles<Dim>& particles, double inertia_D);
/// Σ_p ½ m_p |v_p|²
template <int Dim>
double kinetic_energy(const Particles<Dim>& particles);
/// Σ_p V_p⁰ ψ_p(F_p), ψ_p the model of the particle's material
/// (+infinity where a ψ is not finite).
template <int Dim>
double elastic_energy(const Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models);

template <int Dim>
double total_mass(const SparseGrid<Dim>& grid);
/// Σ_i m_i v_i over the nodes' `velocity`.
template <int Dim>
Eigen::Matrix<double, Dim, 1> linear_momentum(const SparseGrid<Dim>& grid);
/// Σ_i x_i × m_i v_i
template <int Dim>
AngularMomentum angular_momentum(const SparseGrid<Dim>& grid);

} // namespace sinew
