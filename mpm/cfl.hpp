#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/particles.hpp"

#include <vector>

namespace sinew {

/// The speed of the fastest elastic wave at F in a material of density ρ
/// (reference configuration): c² = max over directions n of the largest
/// eigenvalue of the acoustic tensor A(n)_ik = Σ_jl ∂P_ij/∂F_kl n_j n_l,
/// divided by ρ. The directions tried are the axes, the face and body
/// diagonals, and the fiber: exact for isotropic models (every n gives
/// the longitudinal speed, √((λ + 2μ)/ρ) at F = I for Lamé models), a lower
/// bound otherwise, their fastest direction not among them.
template <int Dim>
double elastic_wave_speed(const ConstitutiveModel<Dim, Dim>& model, const typename ConstitutiveModel<Dim, Dim>::Deformation& F,
                          const MaterialPoint<Dim>& point, double density);

/// The explicit step's CFL bound, Δt ≤ cfl · dx / max_p (c_p + |v_p|), with
/// c_p the elastic wave speed of particle p at its F and density m_p/V_p⁰.
/// +infinity for no particles.
template <int Dim>
double cfl_time_step(const Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                     double dx, double cfl);

} // namespace sinew
