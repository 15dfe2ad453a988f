#pragma once
#include "sinew/mpm/bspline_stencil.hpp"
#include "sinew/mpm/particle_buckets.hpp"
#include "sinew/mpm/particles.hpp"
#include "sinew/mpm/sparse_grid.hpp"

#include <vector>

namespace sinew {

/// How velocities go between particles and grid.
enum class TransferScheme {
    apic,     ///< affine particle-in-cell (Jiang et al. 2015): C_p carried by the particles
    pic_flip  ///< PIC blended with FLIP's increment, no affine part
};

struct TransferSettings {
    SplineOrder order = SplineOrder::quadratic;
    TransferScheme scheme = TransferScheme::apic;
    /// PIC/FLIP only: the share α of FLIP, 0 (PIC) to 1 (FLIP).
    double flip_ratio = 0.95;
};

/// The particle-to-grid transfer: lays the grid out for the particles
/// (lay_out_grid) and scatters
///   m_i = Σ_p w_ip m_p,  (m v)_i = Σ_p w_ip (m_p v_p + (m_p C_p + S_p)(x_i − x_p))
/// (C_p = 0 for PIC/FLIP), with S_p the particles' impulses when given (the
/// explicit step's stress, −Δt V_p⁰ D_p⁻¹ P Fᵀ: MLS-MPM's one scatter) and 0
/// otherwise; then v_i = (m v)_i / m_i where m_i > 0. PIC/FLIP also writes
/// velocity_transferred, v_i without the impulses (FLIP's increment reads
/// it). Returns the step's layout, for grid_to_particles. Throws InputError
/// naming the first particle whose stencil leaves the grid's indices.
template <int Dim>
ParticleBuckets<Dim> particles_to_grid(const Particles<Dim>& particles, const TransferSettings& settings,
                                       SparseGrid<Dim>& grid,
                                       const std::vector<typename Particles<Dim>::Matrix>* impulses = nullptr);

/// The grid-to-particle transfer of the grid's velocity, on the layout
/// particles_to_grid returned for these particles:
///   v_p = Σ_i w_ip v_i  (APIC and PIC; PIC/FLIP blends in α times
///   FLIP's v_p + Σ_i w_ip (v_i − v_i transferred)),
///   C_p = Σ_i w_ip v_i (x_i − x_p)ᵀ D_p⁻¹,  D_p = σ dx² I (apic_inertia_factor),
/// the MLS velocity gradient, exact for affine grid velocities.
template <int Dim>
void grid_to_particles(const SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout, const TransferSettings& settings,
                       Particles<Dim>& particles);

/// grid_to_particles and, in the same pass over the particles, their
/// advection over a step of h: x_p ← x_p + h v_p and F_p ← (I + h C_p) F_p
/// (Fⁿ⁺¹ = (I + Δt ∇v) Fⁿ, ∇v_p = C_p).
template <int Dim>
void grid_to_particles_advected(const SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout,
                                const TransferSettings& settings, double time_step, Particles<Dim>& particles);

/// Whether the grid can hold the stencil of a particle at x: every
/// coordinate finite and within 2²⁰ − 4 cells of dx of the origin.
template <int Dim>
bool in_grid(const Eigen::Matrix<double, Dim, 1>& x, double dx);

/// InputError naming particle p and its position when the grid cannot hold
/// its stencil (not in_grid).
template <int Dim>
void check_in_grid(const Particles<Dim>& particles, int p, double dx);

/// The stencil of particle p, after check_in_grid.
template <int Dim>
BSplineStencil<Dim> checked_stencil(const Particles<Dim>& particles, int p, double dx, SplineOrder order);

} // namespace sinew
