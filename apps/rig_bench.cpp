#include "rig_bench.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/inverse/rig_fit_run.hpp"
#include "sinew/runs/result_json.hpp"
#include "sinew/solvers/solver.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

namespace sinew::cli {
namespace {

constexpr double kNoise = 1e-3;  // m

std::string cell(const char* pattern, double value)
{
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

void print_fit_header(int tets, int nodes, int parameters, const RigTargets& targets, bool skull_contact)
{
    std::cout << "\n### Face of " << tets << " tets, " << nodes << " nodes, " << parameters << " parameters, "
              << (targets.noise > 0.0 ? "1 mm noise" : "exact targets")
              << (skull_contact ? ", pressed against its skull" : "") << " (landmark motion RMS "
              << cell("%.2f", 1e3 * targets.motion_rms) << " mm)\n\n"
              << "| strategy | status | RMS (mm) | RMS / motion | RMS to exact (mm) | max dα | max dM | max dt (mm) "
                 "| ‖McᵀMc−I‖ | ‖MjᵀMj−I‖ | outer it | eq. solves | fact. | equilibrium s | sensitivities s | total s "
                 "| branch (mm) |"
              << (skull_contact ? " max depth (µm) | skull force (N) |" : "") << "\n"
              << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
              << (skull_contact ? "---|---|" : "") << "\n";
}

void print_fit_row(const RigFitOutcome& o, const RigTargets& targets, bool skull_contact)
{
    std::cout << "| " << o.strategy << " | " << to_string(o.result.status) << " | " << cell("%.3g", 1e3 * o.rms)
              << " | " << cell("%.2g", o.rms / targets.motion_rms) << " | " << cell("%.3g", 1e3 * o.rms_to_exact)
              << " | " << cell("%.2g", o.activation_error) << " | " << cell("%.2g", o.map_error) << " | "
              << cell("%.2g", 1e3 * o.translation_error) << " | " << cell("%.1e", o.cranium_violation) << " | "
              << cell("%.1e", o.jaw_violation) << " | " << o.result.iterations << " | " << o.equilibrium_solves
              << " | " << o.factorizations << " | " << cell("%.2f", o.equilibrium_seconds) << " | "
              << cell("%.2f", o.sensitivity_seconds) << " | " << cell("%.2f", o.seconds) << " | "
              << cell("%.2g", 1e3 * o.branch_distance) << " |";
    if (skull_contact)
        std::cout << " " << cell("%.3g", 1e6 * o.max_penetration) << " | " << cell("%.3g", o.contact_force) << " |";
    std::cout << "\n" << std::flush;
}

nlohmann::json outcome_json(const RigFitOutcome& o, const RigDefinition& definition, const RigTargets& targets,
                            bool skull_contact)
{
    nlohmann::json run = {{"suite", "rig"},
            {"tets", definition.mesh.num_elements()},
            {"skull_contact", skull_contact},
            {"noise_m", targets.noise},
            {"strategy", o.strategy},
            {"status", to_string(o.result.status)},
            {"rms_m", number(o.rms)},
            {"rms_relative", number(o.rms / targets.motion_rms)},
            {"rms_to_exact_m", number(o.rms_to_exact)},
            {"activation_error", number(o.activation_error)},
            {"map_error", number(o.map_error)},
            {"translation_error_m", number(o.translation_error)},
            {"cranium_violation", number(o.cranium_violation)},
            {"jaw_violation", number(o.jaw_violation)},
            {"outer_iterations", o.result.iterations},
            {"equilibrium_solves", o.equilibrium_solves},
            {"factorizations", o.factorizations},
            {"equilibrium_s", number(o.equilibrium_seconds)},
            {"sensitivities_s", number(o.sensitivity_seconds)},
            {"time_s", number(o.seconds)},
            {"branch_distance_m", number(o.branch_distance)},
            {"branch_node", o.branch_node},
            {"branch_node_rest_m", o.branch_node < 0 ? nlohmann::json(nullptr)
                                                     : nlohmann::json(std::vector<double>{
                                                           definition.mesh.nodes(0, o.branch_node),
                                                           definition.mesh.nodes(1, o.branch_node),
                                                           definition.mesh.nodes(2, o.branch_node)})},
            {"branch_nodes_apart", o.branch_nodes_apart},
            {"result", to_json(o.result)}};
    if (skull_contact)
        run["contact"] = {{"max_penetration_m", number(o.max_penetration)}, {"force_n", number(o.contact_force)}};
    return run;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// One outer iteration's pieces at θ*, on a fresh rig: the equilibrium solve
/// from rest and again warm from a nearby θ, the factorization, the forward
/// Jacobian (a solve per parameter that moves the equilibrium) and the
/// adjoint gradient (one solve).
nlohmann::json iteration_cost(const RigFitCase& fit_case, int tets)
{
    const RigTargets& targets = fit_case.targets;
    MuscleRig rig(fit_case.definition, fit_case.inner);
    RigParameters near = targets.truth;
    near.activations = (near.activations.array() + 0.01).min(1.0);
    auto start = std::chrono::steady_clock::now();
    rig.evaluate(near);
    const double cold = seconds_since(start);
    start = std::chrono::steady_clock::now();
    const RigEvaluation warm = rig.evaluate(targets.truth);
    const double warm_s = seconds_since(start);
    if (!warm.ok)
        throw std::runtime_error(warm.failure);
    start = std::chrono::steady_clock::now();
    const Eigen::VectorXd w = rig.landmark_positions() - targets.targets;
    const Eigen::VectorXd gradient = rig.landmark_gradient(w);  // factorization + 1 solve
    const double adjoint_with_factorization = seconds_since(start);
    start = std::chrono::steady_clock::now();
    const Eigen::MatrixXd J = rig.landmark_jacobian();  // the kept factors, a solve per parameter
    const double forward = seconds_since(start);
    const int solves = rig.num_muscles() + RigParameters::kAffineParameters;
    std::cout << "| " << tets << " | " << cell("%.2f", cold) << " | " << cell("%.2f", warm_s) << " ("
              << warm.inner.iterations << " it) | " << cell("%.2f", adjoint_with_factorization) << " | "
              << cell("%.3f", forward) << " (" << solves << " solves, " << cell("%.4f", forward / solves)
              << " s each) | " << J.cols() << " |\n"
              << std::flush;
    return {{"suite", "rig-iteration"}, {"tets", tets}, {"cold_solve_s", number(cold)}, {"warm_solve_s", number(warm_s)},
            {"warm_iterations", warm.inner.iterations}, {"factorization_and_adjoint_s", number(adjoint_with_factorization)},
            {"adjoint_gradient_norm", number(gradient.norm())},
            {"forward_s", number(forward)}, {"forward_solves", solves}, {"parameters", J.cols()}};
}

/// Whether `strategy` is one of those `names` choose (all when there are none).
bool chosen(const RigFitStrategy& strategy, const std::vector<std::string>& names)
{
    return names.empty() || std::find(names.begin(), names.end(), strategy.solver) != names.end() ||
           std::find(names.begin(), names.end(), strategy.label) != names.end();
}

} // namespace

void check_rig_strategies(const std::vector<std::string>& names, const SolverOptions& options)
{
    const std::vector<RigFitStrategy> strategies = rig_fit_strategies(options);
    for (const std::string& name : names) {
        if (std::any_of(strategies.begin(), strategies.end(),
                        [&](const RigFitStrategy& s) { return s.solver == name || s.label == name; }))
            continue;
        std::string valid;
        for (const RigFitStrategy& s : strategies)
            valid += (valid.empty() ? "" : ", ") + ("'" + s.label + "'");
        throw InputError("--solver: '" + name + "' is neither a solver nor a strategy of suite rig (strategies: " +
                         valid + ")");
    }
    for (const RigFitStrategy& strategy : strategies)
        if (chosen(strategy, names))
            find_solver(strategy.solver).check_options(strategy.options);
}

bool run_rig_bench(const std::vector<int>& sizes, const std::vector<std::string>& solvers,
                   const SolverOptions& options, bool skull_contact, nlohmann::json& runs)
{
    bool all_converged = true;
    std::vector<RigFitCase> exact_cases;
    for (const int tets : sizes) {
        for (const double noise : {0.0, kNoise}) {
            RigFitCase fit_case = face_fit_case(tets, noise, skull_contact);
            const RigDefinition& definition = fit_case.definition;
            const RigTargets& targets = fit_case.targets;
            print_fit_header(definition.mesh.num_elements(), definition.mesh.num_nodes(),
                             static_cast<int>(definition.muscle_elements.size()) + 2 * RigParameters::kAffineParameters,
                             targets, skull_contact);
            for (const RigFitStrategy& strategy : rig_fit_strategies(options)) {
                if (!chosen(strategy, solvers))
                    continue;
                const RigFitOutcome outcome = run_rig_fit(definition, fit_case.inner, targets, strategy, {});
                print_fit_row(outcome, targets, skull_contact);
                runs.push_back(outcome_json(outcome, definition, targets, skull_contact));
                all_converged = all_converged && outcome.result.status == Status::converged;
            }
            if (noise == 0.0)
                exact_cases.push_back(std::move(fit_case));
        }
    }
    std::cout << "\n### One outer iteration at θ*\n\n"
              << "| tets | equilibrium from rest s | equilibrium warm s | factorization + adjoint gradient s | "
                 "forward sensitivities s | parameters |\n|---|---|---|---|---|---|\n";
    for (const RigFitCase& fit_case : exact_cases)
        runs.push_back(iteration_cost(fit_case, fit_case.definition.mesh.num_elements()));
    return all_converged;
}

} // namespace sinew::cli
