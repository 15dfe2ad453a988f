#pragma once
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/runs/scene_runner.hpp"
#include "sinew/solvers/result.hpp"
#include "sinew/time/time_integrator.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace sinew {

/// One time step of a run, as result.json's "steps" rows hold it.
struct TimeStepRow {
    int step = 0;
    double time = 0.0;  ///< tₙ₊₁, s
    Status status = Status::failed;
    int iterations = 0;
    int factorizations = -1;  ///< −1: the solver does not report it
    double kinetic_energy = 0.0;
    double elastic_energy = 0.0;
    /// W = Σ_steps E_ext(xₖ) − E_ext(xₖ₊₁), each step's difference under the
    /// forces of that step: the work of gravity, loads and obstacle
    /// penalties since t = 0 (f·Δx for the linear ones, as loads vary in time).
    double external_work = 0.0;
    double total_energy = 0.0;  ///< kinetic + elastic − W
    Eigen::Vector3d linear_momentum = Eigen::Vector3d::Zero();
    Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();
    double max_constraint_violation = 0.0;
    double time_s = 0.0;  ///< wall time of the step's solve
};

/// What a caller watches and controls during a run (all optional).
struct TimeSteppingObserver {
    /// After each step (and once for t = 0 with step 0), with the state at its end.
    std::function<void(const TimeStepRow&, const TimeState&)> on_step;
    /// Asked after each step: true stops the run there (Ctrl-C), output kept.
    std::function<bool()> stop_requested;
};

struct TimeSteppingOutcome {
    bool converged = false;    ///< every step converged and the run reached its duration
    bool interrupted = false;  ///< stop_requested ended it early
    std::vector<TimeStepRow> steps;  ///< step 0 (t = 0) first
    TimeState state;                 ///< at the last step taken
    Result last;                     ///< the last step's solve
    /// The whole run as one result, for comparisons and benches: the last
    /// step's x, multipliers and status (converged only when the run is),
    /// iterations, evaluations, linear solves, time and statistics summed
    /// over the steps, the largest constraint violation and KKT residual of
    /// any step, and one history row per step (iteration = step, objective =
    /// total energy, the step's violation and KKT residual, the run's time).
    Result run;
    int total_iterations = 0;
    double total_time_s = 0.0;
};

/// Integrates a scene with "dynamics" in time (DESIGN.md "Time: a step is an
/// NLP"): from x₀ (rest, prescribed motions at s(0)) and v₀ (the initial
/// velocity), each step sets the load factor s(t) over the step, the
/// integrator's predictor x̃ and scaling on the scene's inertia and damping
/// terms, starts from the explicit guess x̃ + s·aₙ, solves the scene's NLP
/// with the settings' solver, and advances the integrator. Stops at the
/// first step that does not converge. Writes into settings.folder (when not
/// empty): result.json with one row per step, result.vtu at the end, and
/// with VtuOutput::every_step step_k.vtu every `every` steps of the scene's output
/// (k = 0 included) listed with their times in result.pvd.
///
/// InputError before anything is written for a scene without dynamics,
/// load steps other than 1, or invalid solver settings.
TimeSteppingOutcome run_time_stepping(Scene& scene, const SceneRunSettings& settings,
                                      const TimeSteppingObserver& observer = {});

} // namespace sinew
