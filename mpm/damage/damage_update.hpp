#pragma once
// One damage update per MPM step, explicit or implicit (seed 004 Alg. 3 and
// 6, line 3: "just before computeGridVelocity"), and the time step explicit
// damage is stable below.
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/damage/damage_grid.hpp"
#include "sinew/mpm/damage/damage_report.hpp"
#include "sinew/mpm/damage/implicit_damage.hpp"
#include "sinew/mpm/particles.hpp"

#include <vector>

namespace sinew {

/// How d advances: forward Euler on the particles (seed §2.1) or backward
/// Euler on the grid (§2.2).
enum class DamageIntegration { explicit_damage, implicit_damage };

struct DamageSettings {
    DamageIntegration integration = DamageIntegration::implicit_damage;
    ImplicitDamageSettings implicit;  ///< implicit: preconditioner and grid-to-particle transfer
    /// implicit: the damage solve's relative residual and iteration cap, for
    /// the SpdSolve the layer above binds (mpm/ has no solver).
    double cg_tolerance = 1e-8;
    int cg_max_iterations = 1000;
};

/// One damage update of Δt = `dt` (explicit_damage or implicit_damage, by
/// `settings.integration`; `solve` is read by the implicit one only). The
/// step's momentum must read d after it: the run calls it before each step
/// (explicit: before the stress impulses; implicit: before the grid-velocity
/// NLP is posed). Its place relative to the momentum P2G does not matter: it
/// reads x_p, F_p and d_p only, on its own grid.
template <int Dim>
DamageReport update_damage(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                           double dt, const DamageSettings& settings, DamageGrid<Dim>& grid,
                           const SpdSolve& solve);

/// The largest Δt of a stable explicit damage update: min over particles of
/// 2η/(1 + l₀² · 4 Dim/dx²). Explicit damage is forward Euler of
/// ηḋ = (1 − d)D̃ − d + l₀²Δd; its diffusion part is stable while
/// Δt/η (1 + l₀² ρ) ≤ 2, ρ the spectral radius of d ↦ Δ_h d (grid average,
/// then Σ_i d_i ΔN_i(x_p)). ρ ≤ ‖Δ_h‖∞ ≤ max_p Σ_i |ΔN_i(x_p)| ≤ 4 Dim/dx²
/// (the cubic spline's Σ_k |N″| is at most 4, at a node; the average's
/// ∞-norm is 1). The D̃ part needs no bound: it only raises d towards
/// D̃/(1 + D̃), and min(1, ·) caps it. +∞ without particles.
template <int Dim>
double explicit_damage_time_step(const Particles<Dim>& particles, double dx);

} // namespace sinew
