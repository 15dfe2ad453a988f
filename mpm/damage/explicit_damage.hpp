#pragma once
// AnisoMPM's explicit damage update (seed 004 Alg. 3–5, §2.1).
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/damage/damage_grid.hpp"
#include "sinew/mpm/damage/damage_report.hpp"
#include "sinew/mpm/particles.hpp"

#include <vector>

namespace sinew {

/// One explicit damage update, before the step's momentum reads d:
/// D̃_p (update_driving_forces), d to the grid and Δd_p back (damage_to_grid,
/// damage_laplacians), then per particle, seed §2.1,
///   D_c = d − l₀²Δd,   d ← min(1, d + Δt/η ⟨(1 − d)D̃ − D_c⟩),
/// which never lowers d (the Macaulay bracket). The seed's Alg. 5 line 3
/// writes D_c = d l₀²Δd; §2.1's derivation (and the continuous law
/// ηḋ = ⟨(1 − d)D̃ − (d − l₀²Δd)⟩) gives the difference, which is used.
template <int Dim>
DamageReport explicit_damage(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                             double dt, DamageGrid<Dim>& grid);

} // namespace sinew
