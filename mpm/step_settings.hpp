#pragma once
#include "sinew/mpm/grid_colliders.hpp"
#include "sinew/mpm/grid_walls.hpp"
#include "sinew/mpm/particles.hpp"
#include "sinew/mpm/sparse_grid.hpp"
#include "sinew/mpm/transfers.hpp"

#include <optional>
#include <vector>

namespace sinew {

/// What an MPM step, explicit or implicit, needs beyond particles and models.
template <int Dim>
struct MpmStepSettings {
    double time_step = 1e-4;  ///< Δt, s
    TransferSettings transfer;
    Eigen::Matrix<double, Dim, 1> gravity = Eigen::Matrix<double, Dim, 1>::Zero();
    /// Walls around the domain, applied to the grid velocity (none by default).
    std::optional<GridWalls<Dim>> walls;
    /// Rigid bodies acting on the grid after the walls (none by default).
    std::vector<GridCollider<Dim>> colliders;
};

/// The walls' then the colliders' contacts holding the node at x.
template <int Dim>
std::vector<NodeContact<Dim>> node_contacts(const MpmStepSettings<Dim>& settings, const Eigen::Matrix<double, Dim, 1>& x,
                                            double dx);

/// The walls' and the colliders' conditions on the velocity of every node with mass.
template <int Dim>
void apply_grid_conditions(const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid);

/// grid_to_particles (v_p, C_p) on the step's layout, then advection
/// x_p ← x_p + Δt v_p and F_p ← (I + Δt C_p) F_p.
template <int Dim>
void advect_particles(const MpmStepSettings<Dim>& settings, const SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout,
                      Particles<Dim>& particles);

/// The end of every step once the grid velocity is known: apply_grid_conditions, then advect_particles.
template <int Dim>
void finish_step(const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout,
                 Particles<Dim>& particles);

} // namespace sinew
