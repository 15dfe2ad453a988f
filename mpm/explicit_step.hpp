#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/inextensibility/grid_inextensibility.hpp"
#include "sinew/mpm/step_settings.hpp"

#include <string>
#include <vector>

namespace sinew {

/// How a step went: empty `failure` when every particle's stress was
/// finite; and the wall time of its phases (s), for the benchmark.
struct ExplicitStepReport {
    std::string failure;
    double stress_s = 0.0;        ///< P of every particle and its stress impulse
    double to_grid_s = 0.0;       ///< particles_to_grid: the grid's layout and one scatter of mass, momentum and impulses
    double grid_update_s = 0.0;   ///< v_i from momentum and gravity, walls and colliders
    double to_particles_s = 0.0;  ///< grid_to_particles and advection
    InextensibilityStepReport inextensibility;  ///< the grid inextensibility's projection (its own time)
};

/// One explicit (symplectic Euler) MLS-MPM step (Hu et al. 2018, "A moving
/// least squares material point method", §4):
///   the MLS stress divergence f_i = −Σ_p V_p⁰ P(F_p) F_pᵀ D_p⁻¹ (x_i − x_p) w_ip,
///   scattered with the momentum in one particles_to_grid: m_i and
///   (m v)_i + Δt f_i;
///   grid update v_i ← ((m v)_i + Δt f_i)/m_i + Δt g on nodes with mass,
///   with `inextensibility`, the grid velocities projected onto its rows
///   (project_grid_velocities: seed 004 Alg. 11);
///   then finish_step: the walls' and the colliders' conditions,
///   grid_to_particles (v_p, C_p) and advection of x_p and F_p.
/// P comes from models[material_p] at the particle's material point. A
/// particle whose ψ or P is not finite (an inverted F for a model undefined
/// there) leaves the particles as they were and names itself in `failure`.
template <int Dim>
ExplicitStepReport explicit_step(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                 const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid,
                                 const GridInextensibility<Dim>* inextensibility = nullptr);

} // namespace sinew
