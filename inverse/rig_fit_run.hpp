#pragma once
// Fitting a rig to synthesized targets under each strategy: the runs behind
// `sinew bench --suite rig` and its tests.
#include "sinew/inverse/face_rig.hpp"
#include "sinew/inverse/rig_fit_problem.hpp"
#include "sinew/solvers/result.hpp"
#include "sinew/solvers/solver_options.hpp"

#include <map>
#include <string>
#include <vector>

namespace sinew {

/// One way of fitting: a solver on the constrained or the penalty form.
struct RigFitStrategy {
    std::string label;  ///< "ipopt", "kkt-newton", "penalty (seed)", …
    std::string solver;
    OrthogonalityForm form = OrthogonalityForm::constraints;
    SolverOptions options;
};

/// Ipopt's options for the fit with the Gauss-Newton Hessian: that Hessian
/// as if exact (hessian_approximation=exact), the constraints' multipliers
/// started at 0 (constr_mult_init_max=0) and the adaptive barrier update
/// (mu_strategy=adaptive). Ipopt's default least-squares multipliers at the
/// neutral start can make the Lagrangian's Hessian indefinite (they did on
/// the 100k face): the first step then takes the maps far from orthogonal,
/// the warm-started inner solves can follow the tissue into another of its
/// equilibria, and Ipopt converges on that branch, not to θ*. Multipliers
/// from 0 make the first step the Gauss-Newton step; the adaptive barrier
/// needs fewer iterations than the monotone one (docs/benchmarks.md, "Ipopt
/// at its best").
std::map<std::string, std::string> ipopt_gauss_newton_options();

/// The strategies of the rig suite, each with `base`'s tolerance, limits, log
/// and backend options (a strategy's own options take precedence): Ipopt
/// with the Gauss-Newton Hessian (ipopt_gauss_newton_options) and in its
/// limited-memory mode; kkt-newton and relaxed-kkt (κ = 1e8) taking
/// Gauss-Newton steps on the KKT system; augmented-lagrangian;
/// nlopt-slsqp; the seed's penalty form by projected Newton (Gauss-Newton
/// with the activations' bounds); and the rotation-vector form (no
/// constraints) by projected Newton.
std::vector<RigFitStrategy> rig_fit_strategies(const SolverOptions& base);

/// θ* and the landmark targets it gives, with the size of their motion.
struct RigTargets {
    RigParameters truth;
    Eigen::VectorXd exact;    ///< S x̂(θ*)
    Eigen::VectorXd targets;  ///< exact + noise
    double motion_rms = 0.0;  ///< RMS over landmarks of |S x̂(θ*) − S X| (m)
    double noise = 0.0;       ///< standard deviation of the noise per coordinate (m)
};

/// θ*: activations uniform in [0.1, 0.9], the jaw turned by 5–15° about the
/// hinge axis (x through `hinge`, opening the mouth), the cranium turned by
/// 2° about a random axis and moved by 2 mm; targets S x̂(θ*) plus Gaussian
/// noise of standard deviation `noise` (m) per coordinate. Deterministic in
/// `seed`. std::runtime_error when the rig cannot be solved at θ*.
RigTargets synthesize_targets(MuscleRig& rig, const Eigen::Vector3d& hinge, double noise, unsigned seed);

/// What one fit reached.
struct RigFitOutcome {
    std::string strategy;
    Result result;
    double rms = 0.0;              ///< RMS over landmarks of |S x̂(θ) − targets| (m)
    double rms_to_exact = 0.0;     ///< the same against the noise-free targets
    double activation_error = 0.0; ///< max |α − α*|
    double map_error = 0.0;        ///< max |M − M*| over both maps
    double translation_error = 0.0;///< max |t − t*| over both (m)
    double cranium_violation = 0.0;///< ‖M_cᵀM_c − I‖_F
    double jaw_violation = 0.0;
    int equilibrium_solves = 0;
    int factorizations = 0;        ///< sensitivity factorizations
    double equilibrium_seconds = 0.0;
    double sensitivity_seconds = 0.0;
    double seconds = 0.0;
    Eigen::VectorXd landmarks;     ///< S x̂(θ) at the end (3 per landmark); empty where the rig fails there
    /// The branch check: max over nodes of |x̂(θ) − x̂_rest(θ)| (m) at the
    /// fitted θ, x̂ the equilibrium the fit's warm-started inner solves
    /// reached, x̂_rest the one a fresh rig solves from rest. Far from 0 when
    /// the fit followed the tissue into another of its equilibria; infinite
    /// where either solve fails.
    double branch_distance = 0.0;
    /// Where: the node farthest apart (−1 where not checked), and how many
    /// nodes are apart by more than half branch_distance (a few: a local
    /// snap, such as a lip caught at a tooth; many: the tissue as a whole).
    int branch_node = -1;
    int branch_nodes_apart = 0;
    /// With contact: the deepest node in the body (m) and |force| of the body
    /// on the tissue (N) at the fitted θ.
    double max_penetration = 0.0;
    double contact_force = 0.0;
};

/// A fitting case on a generated face: its rig, the inner solves' settings
/// and targets synthesized with seed 1.
struct RigFitCase {
    RigDefinition definition;
    EquilibriumSolveSettings inner;
    RigTargets targets;
};

/// The face of about `tets` tets (generate_face, face_rig; with its skull
/// as a collision body when `skull_contact`), inner solves to 1e-12 of the
/// force scale (at most 100 Newton iterations), targets from
/// synthesize_targets with `noise` (m) and seed 1: the case of `sinew bench
/// --suite rig` and `sinew compare face-rig`. InputError for a size
/// generate_face refuses.
RigFitCase face_fit_case(int tets, double noise, bool skull_contact = false);

/// Fits a fresh rig of `definition` (so every strategy starts alike: from
/// the neutral rig, cold) to `targets` with `strategy`. Where the landmarks
/// do not determine the parameters at the start (rig_identifiability), the
/// result is `failed` at the start, its message naming the undetermined
/// parameters, and nothing is solved.
RigFitOutcome run_rig_fit(const RigDefinition& definition, const EquilibriumSolveSettings& inner,
                          const RigTargets& targets, const RigFitStrategy& strategy, const RigFitSettings& settings);

} // namespace sinew
