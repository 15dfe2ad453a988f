#include "sinew/runs/scene_runner.hpp"

#include "sinew/runs/output_file.hpp"
#include "sinew/runs/result_json.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/energies/constraints/fiber_inextensibility.hpp"
#include "sinew/energies/constraints/weak_fiber_inextensibility.hpp"
#include "sinew/mesh/vtu_writer.hpp"
#include "sinew/problems/quasistatic/constraint_ranks.hpp"
#include "sinew/solvers/solver.hpp"

#include <filesystem>

namespace sinew {
namespace {

/// The node-major vector v (dimension·n entries) as a dimension × n matrix.
Eigen::MatrixXd by_node(const Eigen::VectorXd& v, int dimension)
{
    return Eigen::Map<const Eigen::MatrixXd>(v.data(), dimension, v.size() / dimension);
}

/// The element columns of the inextensibility cell data, filled per set.
struct InextensibilityCells {
    Eigen::MatrixXd flag, value, multiplier, cell;
    bool any = false, weak = false;
};

/// Per element: c_e = a₀ᵀC_e a₀ − 1 at the configuration, and the multiplier
/// of the element's row (`row_of` the element's index in the set's list).
template <typename RowOf>
void add_fiber_elements(FiberInextensibility& fibers, const Eigen::VectorXd& configuration,
                        const Eigen::VectorXd& multipliers, int offset, RowOf row_of, InextensibilityCells& cells)
{
    Eigen::VectorXd c(fibers.num_constraints());
    fibers.values(configuration, c);
    for (int k = 0; k < fibers.num_constraints(); ++k) {
        const int e = fibers.elements()[static_cast<size_t>(k)];
        const int row = row_of(k);
        cells.flag(0, e) = 1.0;
        cells.value(0, e) = c[k];
        if (offset >= 0 && offset + row < multipliers.size())
            cells.multiplier(0, e) = multipliers[offset + row];
    }
    cells.any = true;
}

/// Cell data of the scene's inextensible fibers: "inextensible" (1 where an
/// element carries a₀ᵀCa₀ − 1 = 0, alone or in a weak-form cell), the
/// element's own value c_e and the multiplier of its row (Ipopt's sign
/// convention: λ_e per element, λ_z of its grid cell in weak form; 0 where
/// the element carries none), and in weak form "inextensibility_cell", the
/// grid cell z of each element (−1 elsewhere).
void add_inextensibility_cells(const Scene& scene, const Eigen::VectorXd& configuration,
                               const Eigen::VectorXd& multipliers, VtuArrays& arrays)
{
    const int count = scene.mesh.num_elements();
    InextensibilityCells cells;
    cells.flag = cells.value = cells.multiplier = Eigen::MatrixXd::Zero(1, count);
    cells.cell = Eigen::MatrixXd::Constant(1, count, -1.0);
    for (const auto& set : scene.constraints) {
        const int offset = scene.problem->constraint_offset(*set);
        if (auto* fibers = dynamic_cast<FiberInextensibility*>(set.get()))
            add_fiber_elements(*fibers, configuration, multipliers, offset, [](int k) { return k; }, cells);
        if (auto* weak = dynamic_cast<WeakFiberInextensibility*>(set.get())) {
            const std::vector<int>& row_of_element = weak->row_of_element();
            const auto row_of = [&row_of_element](int k) { return row_of_element[static_cast<size_t>(k)]; };
            add_fiber_elements(weak->per_element(), configuration, multipliers, offset, row_of, cells);
            for (size_t k = 0; k < row_of_element.size(); ++k)
                cells.cell(0, weak->per_element().elements()[k]) = row_of_element[k];
            cells.weak = true;
        }
    }
    if (!cells.any)
        return;
    arrays["inextensible"] = cells.flag;
    arrays["inextensibility_value"] = cells.value;
    arrays["inextensibility_multiplier"] = cells.multiplier;
    if (cells.weak)
        arrays["inextensibility_cell"] = cells.cell;
}

void write_scene_vtu(const std::string& path, Scene& scene, const Eigen::VectorXd& configuration,
                     const Eigen::VectorXd& multipliers)
{
    const Mesh& mesh = scene.mesh;
    const int dimension = static_cast<int>(mesh.nodes.rows());
    Eigen::VectorXd gradient(configuration.size());
    scene.problem->potential().gradient(configuration, gradient);
    const Eigen::MatrixXd positions = by_node(configuration, dimension);

    VtuArrays points;
    points["displacement"] = positions - mesh.nodes;
    points["force"] = -by_node(gradient, dimension);  // net force −∂E/∂x
    points["fixed"] = scene.fixed_flags().transpose();

    const int count = mesh.num_elements();
    const int fiber_rows = material_dimension(mesh.kind);
    Eigen::MatrixXd group(1, count), activation(1, count), damage(1, count), fiber(fiber_rows, count);
    for (int e = 0; e < count; ++e) {
        group(0, e) = mesh.element_groups[static_cast<size_t>(e)];
        activation(0, e) = scene.elastic->activation(e);
        damage(0, e) = scene.elastic->damage(e);
        fiber.col(e) = scene.elastic->fiber(e);
    }
    VtuArrays cells;
    cells["group"] = group;
    cells["activation"] = activation;
    cells["damage"] = damage;
    cells["fiber"] = fiber;
    cells["stress_norm"] = scene.elastic->stress_norms(configuration).transpose();
    add_inextensibility_cells(scene, configuration, multipliers, cells);
    write_vtu(path, mesh, positions, points, cells);
}

nlohmann::json step_summary(int step, double load_factor, const Result& result)
{
    return {{"step", step},
            {"load_factor", load_factor},
            {"status", to_string(result.status)},
            {"iterations", result.iterations},
            {"objective", number(result.objective)},
            {"kkt_residual", number(result.kkt_residual)},
            {"time_s", number(result.time_s)}};
}

} // namespace

ResolvedSceneRun resolve_scene_run(const Scene& scene, const SceneRunRequest& request)
{
    ResolvedSceneRun resolved;
    SceneRunSettings& settings = resolved.settings;
    std::vector<std::string>& notes = resolved.notes;
    SolverOptions options = request.options;
    settings.solver = request.solver.value_or(scene.solver.name);
    const std::string source = scene.solver.source.empty() ? scene.name : scene.solver.source;
    options.tolerance = request.tolerance.value_or(scene.solver.tolerance.value_or(options.tolerance));
    if (request.tolerance && scene.solver.tolerance)
        notes.push_back("tol " + format_number(*request.tolerance) + " overrides " + source + ".tol = " +
                        format_number(*scene.solver.tolerance));
    options.max_iterations = request.max_iterations.value_or(scene.solver.max_iterations.value_or(options.max_iterations));
    if (request.max_iterations && scene.solver.max_iterations)
        notes.push_back("max_iter " + std::to_string(*request.max_iterations) + " overrides " + source +
                        ".max_iter = " + std::to_string(*scene.solver.max_iterations));
    if (settings.solver == scene.solver.name) {
        SolverOptions scene_options = options;
        scene_options.backend = scene.solver.options;
        try {
            find_solver(scene.solver.name).check_options(scene_options);
        } catch (const InputError& e) {
            throw InputError(source + ": " + e.what());
        }
        for (const auto& [key, value] : scene.solver.options)
            if (!options.backend.emplace(key, value).second)
                notes.push_back("option " + key + "=" + options.backend.at(key) + " overrides " + source +
                                ".options." + key + " = " + value);
    } else {
        std::string ignored;
        for (const auto& [key, value] : scene.solver.options)
            ignored += (ignored.empty() ? "" : ", ") + key + "=" + value;
        notes.push_back("solver " + settings.solver + " replaces the scene's " + scene.solver.name +
                        (ignored.empty() ? "" : "; its options (" + ignored + ") are not passed to " + settings.solver));
    }
    settings.options = options;
    settings.load_steps = request.load_steps.value_or(scene.load_steps);
    if (request.load_steps && scene.load_steps != 1 && *request.load_steps != scene.load_steps)
        notes.push_back("load steps " + std::to_string(*request.load_steps) + " override the scene's " +
                        std::to_string(scene.load_steps));
    settings.folder = !request.folder.empty() ? request.folder : scene.output.folder;
    settings.vtu = scene.output.vtu;
    return resolved;
}

SceneRunOutcome run_scene(Scene& scene, const SceneRunSettings& settings)
{
    // Every input is checked before the output folder is made.
    check_solve(*scene.problem, settings.solver, settings.options);
    const bool writes = !settings.folder.empty();
    const std::string folder = settings.folder + "/";
    if (writes) {
        std::error_code error;
        std::filesystem::create_directories(settings.folder, error);
        if (error)
            throw InputError("cannot create output folder '" + settings.folder + "': " + error.message());
        check_writable(folder + "result.json");  // fail on an unwritable folder before the solve
    }

    QuasistaticProblem& problem = *scene.problem;
    nlohmann::json ranks = nlohmann::json::array();
    if (writes)
        for (const ConstraintSetRank& r : constraint_ranks(scene))
            ranks.push_back({{"constraints", r.set},
                             {"rows", r.rank.rows},
                             {"rank", r.rank.rank >= 0 ? nlohmann::json(r.rank.rank) : nlohmann::json()},
                             {"singular_value_ratio", number(r.rank.singular_value_ratio)}});
    nlohmann::json steps = nlohmann::json::array();
    nlohmann::json vtu_files = nlohmann::json::array();
    SceneRunOutcome outcome;
    Result& result = outcome.last;
    const int n = settings.load_steps;
    for (int k = 1; k <= n; ++k) {
        const double s = static_cast<double>(k) / n;
        scene.apply_load_factor(s);
        result = solve(problem, settings.solver, settings.options);
        outcome.total_time_s += result.time_s;
        outcome.total_iterations += result.iterations;
        steps.push_back(step_summary(k, s, result));
        const Eigen::VectorXd configuration = problem.full_configuration(result.x);
        if (writes && settings.vtu == VtuOutput::every_step && n > 1) {
            const std::string name = "step_" + std::to_string(k) + ".vtu";
            write_scene_vtu(folder + name, scene, configuration, result.constraint_multipliers);
            vtu_files.push_back(name);
        }
        if (result.status != Status::converged || k == n) {
            if (writes && settings.vtu != VtuOutput::none) {
                write_scene_vtu(folder + "result.vtu", scene, configuration, result.constraint_multipliers);
                vtu_files.push_back("result.vtu");
            }
            break;
        }
        problem.set_starting_configuration(configuration);
    }
    outcome.converged = result.status == Status::converged && static_cast<int>(steps.size()) == n;
    if (!writes)
        return outcome;
    const nlohmann::json out = {{"scene", scene.name},
                                {"description", scene.description},
                                {"solver", settings.solver},
                                {"load_steps", n},
                                {"constraint_ranks", ranks},
                                {"converged", outcome.converged},
                                {"total_iterations", outcome.total_iterations},
                                {"total_time_s", outcome.total_time_s},
                                {"steps", steps},
                                {"vtu", vtu_files},
                                {"result", to_json(result)}};
    write_text_file(folder + "result.json", out.dump(2) + "\n");
    return outcome;
}

} // namespace sinew
