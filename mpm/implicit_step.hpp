#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/inextensibility/grid_inextensibility.hpp"
#include "sinew/mpm/step_settings.hpp"
#include "sinew/problems/nlp.hpp"

#include <functional>
#include <string>
#include <vector>

namespace sinew {

/// Minimizes `nlp` from v (its starting point on entry), leaving the minimizer
/// in v; returns whether the solve converged. The layer above mpm/ (runs/,
/// tests) supplies it with the strategy of its choice: mpm/ knows no solver.
using GridVelocitySolve = std::function<bool(Nlp& nlp, Eigen::VectorXd& v)>;

/// How an implicit step went.
struct ImplicitStepReport {
    std::string failure;     ///< non-empty when the step could not be posed; nothing moved then
    bool converged = false;  ///< the solve's verdict (the step is taken either way)
    int unknowns = 0;        ///< grid velocity components solved for
    InextensibilityStepReport inextensibility;  ///< the grid inextensibility, when given
};

/// One implicit MLS-MPM step: particles_to_grid, then the grid velocities
/// minimize the incremental potential of GridVelocityNlp (its docs: inertia
/// and gravity through v*, the particles' elastic energy at F_p(v), walls
/// and colliders as each held node's frame), then finish_step (the
/// conditions once more, which changes only a separating node that the
/// solve left approaching; grid_to_particles; advection). Taken whether or
/// not the solve converged (report.converged says which); when ψ is not
/// finite at the starting point nothing moves and `failure` says so.
/// With `inextensibility` (seed 004 §4), its rows at v* either constrain the
/// NLP (InextensibilityMethod::nlp: the solve enforces them, the dependent
/// rows left out by independent_rows) or project the
/// solve's velocities (schur_cg: the seed's Alg. 11 after the step, a
/// first-order split that does not land on the constrained minimizer).
template <int Dim>
ImplicitStepReport implicit_step(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                 const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid,
                                 const GridVelocitySolve& solve,
                                 const GridInextensibility<Dim>* inextensibility = nullptr);

} // namespace sinew
