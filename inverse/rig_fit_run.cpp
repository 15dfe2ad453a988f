#include "sinew/inverse/rig_fit_run.hpp"

#include "sinew/inverse/rig_identifiability.hpp"
#include "sinew/inverse/rotation_vector_fit_problem.hpp"
#include "sinew/solvers/solver.hpp"

#include <Eigen/Geometry>

#include <chrono>
#include <functional>
#include <limits>
#include <memory>
#include <cmath>
#include <random>
#include <stdexcept>

namespace sinew {

std::map<std::string, std::string> ipopt_gauss_newton_options()
{
    return {{"hessian_approximation", "exact"}, {"constr_mult_init_max", "0"}, {"mu_strategy", "adaptive"}};
}

std::vector<RigFitStrategy> rig_fit_strategies(const SolverOptions& base)
{
    std::vector<RigFitStrategy> strategies;
    const auto add = [&](std::string label, std::string solver, OrthogonalityForm form,
                         std::map<std::string, std::string> backend) {
        RigFitStrategy s{std::move(label), std::move(solver), form, base};
        for (auto& [key, value] : backend)  // the strategy's own options over the caller's
            s.options.backend[key] = std::move(value);
        strategies.push_back(std::move(s));
    };
    add("ipopt (Gauss-Newton)", "ipopt", OrthogonalityForm::constraints, ipopt_gauss_newton_options());
    add("ipopt (limited-memory)", "ipopt", OrthogonalityForm::constraints, {});
    add("kkt-newton", "kkt-newton", OrthogonalityForm::constraints, {});
    add("relaxed-kkt (kappa 1e8)", "relaxed-kkt", OrthogonalityForm::constraints, {{"kappa", "1e8"}});
    add("augmented-lagrangian", "augmented-lagrangian", OrthogonalityForm::constraints, {});
    add("nlopt-slsqp", "nlopt-slsqp", OrthogonalityForm::constraints, {});
    add("penalty (seed)", "projected-newton", OrthogonalityForm::penalty, {});
    add("rotation vectors", "projected-newton", OrthogonalityForm::rotation_vectors, {});
    return strategies;
}

RigTargets synthesize_targets(MuscleRig& rig, const Eigen::Vector3d& hinge, double noise, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::normal_distribution<double> normal;
    RigTargets t;
    t.noise = noise;
    t.truth = RigParameters::neutral(rig.num_muscles());
    for (int m = 0; m < rig.num_muscles(); ++m)
        t.truth.activations[m] = 0.1 + 0.8 * uniform(rng);
    const double jaw_angle = (5.0 + 10.0 * uniform(rng)) * M_PI / 180.0;
    const Eigen::Matrix3d R_j = Eigen::AngleAxisd(jaw_angle, Eigen::Vector3d::UnitX()).toRotationMatrix();
    t.truth.jaw_map = R_j;
    t.truth.jaw_translation = hinge - R_j * hinge;  // x = R_j (X − h) + h
    const Eigen::Vector3d axis = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    t.truth.cranium_map = Eigen::AngleAxisd(2.0 * M_PI / 180.0, axis).toRotationMatrix();
    t.truth.cranium_translation = 0.002 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();

    const RigEvaluation rest = rig.evaluate(RigParameters::neutral(rig.num_muscles()));
    if (!rest.ok)
        throw std::runtime_error("rig targets: " + rest.failure);
    const Eigen::VectorXd at_rest = rig.landmark_positions();
    const RigEvaluation moved = rig.evaluate(t.truth);
    if (!moved.ok)
        throw std::runtime_error("rig targets: " + moved.failure);
    t.exact = rig.landmark_positions();
    t.motion_rms = std::sqrt((t.exact - at_rest).squaredNorm() / rig.num_landmarks());
    t.targets = t.exact;
    for (Eigen::Index i = 0; i < t.targets.size(); ++i)
        t.targets[i] += noise * normal(rng);
    return t;
}

namespace {

/// The fit of `nlp` (on θ, or on rotation vectors φ with θ(φ) from
/// `affine_parameters`) by the strategy's solver, unless the landmarks do
/// not determine the parameters at the start (or the rig cannot be solved
/// there): then a failed result at the start that says why, and no solve.
Result fit(Nlp& nlp, RigFitProblem& affine,
           const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& affine_parameters,
           const RigFitStrategy& strategy)
{
    const Eigen::VectorXd start = nlp.starting_point();
    const Eigen::VectorXd theta = affine_parameters(start);
    std::string refusal;
    if (!std::isfinite(affine.objective(theta))) {
        refusal = "rig fit: the equilibrium solve fails at the starting parameters";
    } else {
        const RigIdentifiability identifiability = rig_identifiability(affine, theta);
        if (!identifiability.determined())
            refusal = "rig fit: " + identifiability.message;
    }
    if (refusal.empty())
        return solve(nlp, strategy.solver, strategy.options);
    Result result;
    result.solver = strategy.solver;
    result.problem = nlp.name();
    result.status = Status::failed;
    result.message = refusal;
    result.x = start;
    result.objective = nlp.objective(start);
    return result;
}

/// The branch check at θ: `rig` solved at θ by the fit's warm starts and a
/// fresh rig of the same definition from rest; max_i |x̂_i − x̂_rest,i|, the
/// node where it is largest and how many nodes are apart by more than half
/// of it. Distance ∞ when either solve fails.
void check_branch(MuscleRig& rig, const RigParameters& theta, RigFitOutcome& outcome)
{
    outcome.branch_distance = std::numeric_limits<double>::infinity();
    const RigEvaluation warm = rig.evaluate(theta);
    MuscleRig fresh(rig.definition(), rig.settings());
    const RigEvaluation cold = fresh.evaluate(theta);
    if (!warm.ok || !cold.ok)
        return;
    const Eigen::VectorXd difference = rig.positions() - fresh.positions();
    const Eigen::VectorXd apart =
        Eigen::Map<const Eigen::Matrix3Xd>(difference.data(), 3, difference.size() / 3).colwise().norm().transpose();
    Eigen::Index node = 0;
    outcome.branch_distance = apart.maxCoeff(&node);
    outcome.branch_node = static_cast<int>(node);
    outcome.branch_nodes_apart = static_cast<int>((apart.array() > 0.5 * outcome.branch_distance).count());
}

} // namespace

RigFitOutcome run_rig_fit(const RigDefinition& definition, const EquilibriumSolveSettings& inner,
                          const RigTargets& targets, const RigFitStrategy& strategy, const RigFitSettings& settings)
{
    MuscleRig rig(definition, inner);
    RigFitSettings fit_settings = settings;
    fit_settings.orthogonality = strategy.form;
    // The rotation-vector form fits φ through a RigFitProblem on θ(φ); the
    // others fit θ directly. Errors and violations are measured on θ.
    std::unique_ptr<RotationVectorFitProblem> rotations;
    std::unique_ptr<RigFitProblem> direct;
    if (strategy.form == OrthogonalityForm::rotation_vectors)
        rotations = std::make_unique<RotationVectorFitProblem>(rig, targets.targets, fit_settings);
    else
        direct = std::make_unique<RigFitProblem>(rig, targets.targets, fit_settings);
    Nlp& nlp = rotations ? static_cast<Nlp&>(*rotations) : *direct;
    RigFitProblem& problem = rotations ? rotations->affine_problem() : *direct;
    const auto affine_parameters = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
        return rotations ? rotations->affine_parameters(x) : x;
    };
    RigFitOutcome outcome;
    outcome.strategy = strategy.label;
    const auto start = std::chrono::steady_clock::now();
    outcome.result = fit(nlp, problem, affine_parameters, strategy);
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    outcome.equilibrium_solves = rig.equilibrium_solves();
    outcome.factorizations = rig.sensitivity_factorizations();
    outcome.equilibrium_seconds = rig.equilibrium_seconds();
    outcome.sensitivity_seconds = rig.sensitivity_seconds();
    const Eigen::VectorXd theta = affine_parameters(outcome.result.x);
    const RigParameters fitted = RigParameters::unpacked(theta, rig.num_muscles());
    const RigParameters& truth = targets.truth;
    outcome.activation_error = (fitted.activations - truth.activations).cwiseAbs().maxCoeff();
    outcome.map_error = std::max((fitted.cranium_map - truth.cranium_map).cwiseAbs().maxCoeff(),
                                 (fitted.jaw_map - truth.jaw_map).cwiseAbs().maxCoeff());
    outcome.translation_error = std::max((fitted.cranium_translation - truth.cranium_translation).cwiseAbs().maxCoeff(),
                                         (fitted.jaw_translation - truth.jaw_translation).cwiseAbs().maxCoeff());
    outcome.cranium_violation = problem.cranium_violation(theta);
    outcome.jaw_violation = problem.jaw_violation(theta);
    const double landmarks = rig.num_landmarks();
    if (std::isfinite(problem.objective(theta))) {
        const Eigen::VectorXd fitted_landmarks = rig.landmark_positions();
        outcome.landmarks = fitted_landmarks;
        outcome.rms = std::sqrt((fitted_landmarks - targets.targets).squaredNorm() / landmarks);
        outcome.rms_to_exact = std::sqrt((fitted_landmarks - targets.exact).squaredNorm() / landmarks);
        outcome.max_penetration = rig.max_penetration();
        outcome.contact_force = rig.contact_force().norm();
        check_branch(rig, fitted, outcome);
    } else {
        outcome.rms = outcome.rms_to_exact = std::numeric_limits<double>::infinity();
        outcome.branch_distance = std::numeric_limits<double>::infinity();
    }
    return outcome;
}

RigFitCase face_fit_case(int tets, double noise, bool skull_contact)
{
    FaceShape shape;
    shape.target_tets = tets;
    const FaceMesh face = generate_face(shape);
    RigFitCase fit_case;
    fit_case.definition = face_rig(face, {}, skull_contact);
    // f = ½‖S x(θ) − x*‖² is known only to |rᵀ S δx| with δx ≈ H⁻¹ r_in
    // (r_in the inner residual): first order in δx wherever the residual r
    // is not zero. The outer line searches measure decreases of f down to
    // ½ gᵀ H_GN⁻¹ g at their KKT tolerance; inner solves to 1e-10 left f
    // noisier than that near a noisy optimum, and every line-search strategy
    // stopped there with line_search_failed. At 1e-12 they converge
    // (docs/inverse.md, "The nested solve").
    fit_case.inner.options.tolerance = 1e-12;
    fit_case.inner.options.kkt_tolerance = 1e-8;
    fit_case.inner.options.max_iterations = 100;
    MuscleRig rig(fit_case.definition, fit_case.inner);
    fit_case.targets = synthesize_targets(rig, face.hinge_point, noise, 1);
    return fit_case;
}

} // namespace sinew
