#pragma once
// The grid of AnisoMPM's damage (seed 004 Alg. 4 lines 1–4, Alg. 7, 10): the
// particles' damage carried to nodes by cubic B-spline weights (the seed
// needs N″, so cubic), the Laplacian of that field at the particles, and the
// way back.
#include "sinew/mpm/particles.hpp"
#include "sinew/mpm/sparse_grid.hpp"

#include <vector>

namespace sinew {

/// The nodes the particles' cubic stencils reach (their slots, as the
/// momentum grid's) and the damage field on them. Separate from the
/// momentum grid, whose spline may be quadratic.
template <int Dim>
struct DamageGrid {
    explicit DamageGrid(double dx) : nodes(dx) {}

    SparseGrid<Dim> nodes;
    std::vector<double> weight;  ///< Σ_p w_ip by slot
    std::vector<double> damage;  ///< d_i by slot, 0 where no particle weighs
};

/// Clears `grid`, creates the nodes every particle's cubic stencil reaches
/// and sets d_i = Σ_p w_ip d_p / Σ_p w_ip (Alg. 4 line 4). Particles in
/// index order, one thread: one input, one field. InputError naming the
/// first particle the grid cannot hold.
template <int Dim>
void damage_to_grid(const Particles<Dim>& particles, DamageGrid<Dim>& grid);

/// Δd_p = Σ_i d_i ΔN_i(x_p), ΔN_i = Σ_a N″_a Π_{b≠a} N_b (Alg. 4 lines 5–8),
/// on the field damage_to_grid left.
template <int Dim>
std::vector<double> damage_laplacians(const Particles<Dim>& particles, const DamageGrid<Dim>& grid);

/// Calls f(slot, w_ip, ∇w_ip) for every node of particle p's cubic stencil
/// (nodes damage_to_grid created).
template <int Dim, typename Function>
void for_each_damage_node(const Particles<Dim>& particles, const DamageGrid<Dim>& grid, int p, Function&& f);

} // namespace sinew

#include "sinew/mpm/damage/damage_grid_impl.hpp"
