#pragma once
// The grid inextensibility as the MPM steps take it (seed 004 §4).
#include "sinew/mpm/grid_velocity_map.hpp"
#include "sinew/mpm/inextensibility/inextensibility_settings.hpp"
#include "sinew/mpm/inextensibility/schur_projection.hpp"
#include "sinew/mpm/linear_velocity_rows.hpp"
#include "sinew/mpm/particles.hpp"
#include "sinew/mpm/sparse_grid.hpp"
#include "sinew/mpm/spd_solve.hpp"
#include "sinew/mpm/step_settings.hpp"

namespace sinew {

/// The settings and the Schur complement's solve (bound by the layer above).
template <int Dim>
struct GridInextensibility {
    InextensibilitySettings settings;
    SpdSolve solve;
};

/// What the inextensibility did in one step.
struct InextensibilityStepReport {
    int rows = 0;              ///< constrained cells
    int cg_iterations = 0;     ///< schur_cg: the Schur solve's
    bool converged = true;     ///< schur_cg: the Schur solve's verdict
    double violation = 0.0;    ///< ‖B y − rhs‖∞ at the step's grid velocities (1/s)
    double seconds = 0.0;      ///< wall time of the rows and the projection
};

/// Whether any particle carries the constraint.
template <int Dim>
bool any_inextensible(const Particles<Dim>& particles, const InextensibilitySettings& settings);

/// The explicit step's projection, after its grid update (v* in
/// grid.velocity, forces and gravity included) and before its walls and
/// colliders: the map of v* (held nodes in their frames), the rows, the
/// Schur projection, the velocities back into the grid.
template <int Dim>
InextensibilityStepReport project_grid_velocities(const Particles<Dim>& particles, const MpmStepSettings<Dim>& settings,
                                                  const GridInextensibility<Dim>& inextensibility, SparseGrid<Dim>& grid);

} // namespace sinew
