#pragma once
// The grid inextensibility's constraint rows (seed 004 §4, Alg. 11).
#include "sinew/mpm/grid_velocity_map.hpp"
#include "sinew/mpm/inextensibility/inextensibility_settings.hpp"
#include "sinew/mpm/linear_velocity_rows.hpp"
#include "sinew/mpm/particles.hpp"

namespace sinew {

/// One row per grid cell c that an inextensible particle's Γ reaches
/// (cell_basis.hpp), in the unknowns y of `map`:
///
///     (1/W_c) Σ_p V_p⁰ Γ_c(x_p) aᵀ (∇v)_p a = 0,   W_c = Σ_p V_p⁰ Γ_c(x_p),
///
/// a = F_pⁿ a₀ the current fibre (unnormalized, so that aᵀ(∇v)a = ½ d|F a₀|²/dt)
/// and (∇v)_p = Σ_i v_i q_ipᵀ the velocity gradient F follows (the MLS q_ip
/// of the map: the seed writes ∇N_i, which F does not follow under MLS).
/// Since q_ip·a = b_ip·a₀, the row's entries are
///     B_(c,i) = (1/W_c) Σ_p V_p⁰ Γ_c(x_p) (b_ip·a₀) aᵀ,
/// seed 004's B_(c,iα) = Σ_p V_p Γ_c a_α (a·∇N_i) up to the row's scale W_c
/// (which makes each row a mean fibre strain rate, 1/s) and the gradient.
/// A node's velocity v_i = offset_i + basis_i y_i: the rows act on y through
/// basis_i and move offset_i to the right-hand side (held nodes keep v_b).
/// Cells are numbered in the order the particles first reach them; a row
/// with no free unknown (every node held) is left out.
template <int Dim>
LinearVelocityRows inextensibility_rows(const Particles<Dim>& particles, const GridVelocityMap<Dim>& map, double dx,
                                        const InextensibilitySettings& settings);

} // namespace sinew
