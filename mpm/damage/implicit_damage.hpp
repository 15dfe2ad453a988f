#pragma once
// AnisoMPM's implicit damage update (seed 004 Alg. 6–10, §2.2).
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/damage/damage_grid.hpp"
#include "sinew/mpm/damage/damage_report.hpp"
#include "sinew/mpm/damage/damage_system.hpp"
#include "sinew/mpm/particles.hpp"
#include "sinew/mpm/spd_solve.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace sinew {

/// The Jacobi preconditioner's diagonal: the seed's, A's lumped diagonal
/// alone, or diag(A + B).
enum class DamagePreconditioner { lumped, full_diagonal };

/// Grid to particles (Alg. 10): the seed's d_p ← Σ_i w_ip d_iⁿ⁺¹, or its
/// increment d_p ← d_p + Σ_i w_ip (d_iⁿ⁺¹ − d_iⁿ), which carries only what
/// the step changed (the seed's form also smooths d through the round trip
/// of every step, whatever Δt). Either is then kept in [d_p, 1].
enum class DamageTransfer { increment, seed };

struct ImplicitDamageSettings {
    DamagePreconditioner preconditioner = DamagePreconditioner::lumped;
    DamageTransfer transfer = DamageTransfer::increment;
};

/// dⁿ⁺¹ on the grid: S = A + B of `system` solved on the free slots (some
/// particle weighs them, Σ_p w_ip > 0, and not held), the slots `held`
/// fixed at d = 1 (a crack), the rest 0. `outcome` gets the solve's.
template <int Dim>
Eigen::VectorXd solve_damage_system(const DamageSystem<Dim>& system, const DamageGrid<Dim>& grid,
                                    const std::vector<int>& held, DamagePreconditioner preconditioner,
                                    const SpdSolve& solve, SpdSolveOutcome& outcome);

/// One implicit damage update, before the step's momentum reads d: D̃_p
/// (update_driving_forces), dⁿ to the grid (damage_to_grid), the system and
/// its solve with no slot held, dⁿ⁺¹ back to the particles by
/// `settings.transfer`, clamped to [d_p, 1] (no decrease: irreversibility;
/// the seed's min(1, ·)); the report counts where each bound acted. The
/// grid keeps dⁿ⁺¹ afterwards.
template <int Dim>
DamageReport implicit_damage(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                             double dt, const ImplicitDamageSettings& settings, DamageGrid<Dim>& grid,
                             const SpdSolve& solve);

} // namespace sinew
