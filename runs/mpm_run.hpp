#pragma once
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/runs/scene_runner.hpp"
#include "sinew/solvers/result.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace sinew {

/// One output frame of an MPM run, as result.json's "frames" rows hold it.
struct MpmFrameRow {
    int frame = 0;
    double time = 0.0;        ///< s
    long long steps = 0;      ///< steps taken since t = 0, sub-steps counted
    double kinetic_energy = 0.0;
    double elastic_energy = 0.0;
    double gravity_energy = 0.0;  ///< −Σ_p m_p g·x_p
    double total_energy = 0.0;    ///< kinetic + elastic + gravity
    Eigen::Vector3d linear_momentum = Eigen::Vector3d::Zero();
    double min_J = 1.0;  ///< smallest and largest det F over the particles
    double max_J = 1.0;
    double cfl_time_step = 0.0;  ///< the explicit bound at this state (cfl · dx / max(c + |v|))
    int iterations = 0;          ///< implicit: solver iterations since the previous frame
    double time_s = 0.0;         ///< wall time since the run started
    /// The steps since the previous frame, wall time: explicit steps split into
    /// the transfers (P2G, G2P with advection) and the momentum update (stress
    /// impulses, grid update); an implicit step's whole time is momentum_s.
    double transfer_s = 0.0;
    double momentum_s = 0.0;
    /// Damage (scene part "mpm_damage"), its updates since the previous frame:
    double damage_s = 0.0;                  ///< their wall time
    long long damage_cg_iterations = 0;     ///< implicit damage: iterations of the damage solves
    long long damage_grown = 0;             ///< particle updates that raised d
    long long damage_capped = 0;            ///< particle updates where min(1, ·) acted
    long long damage_decrease_refused = 0;  ///< implicit: particle updates the transfer would have lowered
    /// and the field at the frame:
    double max_damage = 0.0;
    double mean_damage = 0.0;  ///< Σ V⁰ d / Σ V⁰
    /// Inextensibility (scene part "mpm_inextensibility"), its steps since the previous frame:
    double inextensibility_s = 0.0;                ///< wall time of the rows and projections
    long long inextensibility_cg_iterations = 0;   ///< schur-cg: iterations of the Schur solves
    double constraint_violation = 0.0;             ///< the largest ‖B y − rhs‖∞ of a step (1/s)
    /// and the positional constraint at the frame (fiber_drift):
    double fiber_drift_max = 0.0;  ///< max |a₀ᵀ C a₀ − 1| over the inextensible particles
    double fiber_drift_rms = 0.0;
};

struct MpmRunOutcome {
    bool converged = false;  ///< reached the duration, every implicit solve converged
    std::string stopped;     ///< why the run ended early or did not converge ("" when it did)
    std::vector<MpmFrameRow> frames;  ///< frame 0 (t = 0) first
    long long steps = 0;
    Eigen::VectorXd positions;  ///< the particles' x at the end, particle after particle (the run's order)
    /// The run as one result (for --json): status, message, iterations and
    /// time summed over the steps; x is empty.
    Result run;
};

/// What an MPM run checks before it writes anything: explicit steps of the
/// scene's Δt below the CFL bound at t = 0 (unless the scene allows
/// sub-steps); implicit steps with a solver that accepts the grid-velocity
/// NLP of the first step and options it accepts. InputError naming the
/// setting otherwise.
void check_mpm_run(const MpmScene& scene, const SceneRunSettings& settings);

/// Runs the scene's MPM section (docs/mpm.md, "Scenes"): N = ⌈T/Δt⌉ steps of
/// T/N, explicit or implicit (the settings' solver, projected Newton by
/// default), and writes into settings.folder (when not empty):
///   frame_k.vtp   the particles at each of the scene's frames (k = 0 …), unless vtu is "none"
///   result.pvd    the frames with their times
///   result.json   the scene's settings and one row per frame
/// An explicit step above the CFL bound (the particles sped up) is split
/// into sub-steps when the scene allows it, else it ends the run, as does a
/// step whose stress is not finite; an implicit solve that does not converge
/// is taken and counted. The output is written either way. With damage
/// (MpmScene::damage) d advances once before every step, sub-steps
/// included; explicit damage also bounds the step (explicit_damage_time_step:
/// sub-steps when the scene allows them, else refused before the run); a
/// damage solve that does not converge is counted as an implicit solve is.
/// With inextensibility (MpmScene::inextensibility) every step takes its
/// rows (schur-cg: projected, counted as a solve when the CG misses its
/// tolerance; nlp: the implicit solve's constraints), and its drift
/// correction follows each step.
MpmRunOutcome run_mpm(const MpmScene& scene, const SceneRunSettings& settings,
                      const std::function<void(const MpmFrameRow&)>& on_frame = {});

} // namespace sinew
