#pragma once
// The driving force of every particle with its history (seed 004 Alg. 5
// lines 4–11, Alg. 8).
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/damage/damage_grid.hpp"
#include "sinew/mpm/particles.hpp"

#include <string>
#include <vector>

namespace sinew {

/// D̃_p = max(ζ⟨Φ_p − 1⟩, D̃ᴴ_p) into driving[p] for every particle, and the
/// history D̃ᴴ_p ← D̃_p (driving_force, models[material_p], the particle's
/// phase_field). Empty when every particle's undegraded stress is defined;
/// else one line naming the lowest particle whose is not (J ≤ 0 or not
/// finite), and nothing is changed. std::invalid_argument when the
/// particles carry no phase-field points.
template <int Dim>
std::string update_driving_forces(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                  std::vector<double>& driving);

/// The start of every damage update, explicit or implicit: D̃_p
/// (update_driving_forces), then dⁿ to the grid (damage_to_grid). Empty, or
/// update_driving_forces's failure (the grid is then untouched).
template <int Dim>
std::string start_damage_update(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                std::vector<double>& driving, DamageGrid<Dim>& grid);

} // namespace sinew
