#include "sinew/runs/time_stepping.hpp"
#include "sinew/runs/refreshed_solve.hpp"

#include "sinew/runs/output_file.hpp"
#include "sinew/runs/result_json.hpp"
#include "sinew/runs/scene_vtu.hpp"
#include "sinew/runs/step_gradient_target.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/pvd_writer.hpp"
#include "sinew/solvers/solver.hpp"
#include "sinew/time/state_measures.hpp"

#include <Eigen/Geometry>

#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace sinew {
namespace {

/// The scene's potentials that are physics, not the time step's own terms.
std::vector<std::shared_ptr<Potential>> physical_terms(const Scene& scene)
{
    std::vector<std::shared_ptr<Potential>> terms;
    for (const auto& term : scene.problem->potential().terms())
        if (term != scene.inertia && term != scene.mass_damping && term != scene.stiffness_damping)
            terms.push_back(term);
    return terms;
}

/// Σ of the physical terms other than the elastic one at x: E_ext.
double external_potential(const Scene& scene, const Eigen::VectorXd& x)
{
    double sum = 0.0;
    for (const auto& term : physical_terms(scene))
        if (term != scene.elastic)
            sum += term->value(x);
    return sum;
}

/// v₀(X) = linear + ω × (X − c) on every node.
Eigen::VectorXd initial_velocity(const DynamicsSettings& d, const Eigen::VectorXd& x, int dimension)
{
    Eigen::VectorXd v(x.size());
    for (Eigen::Index i = 0; i < x.size() / dimension; ++i) {
        const Eigen::VectorXd r = x.segment(i * dimension, dimension) - d.center;
        Eigen::VectorXd turn(dimension);
        if (dimension == 3)
            turn = d.angular_velocity.head<3>().cross(Eigen::Vector3d(r[0], r[1], r[2]));
        else
            turn << -d.angular_velocity[0] * r[1], d.angular_velocity[0] * r[0];
        v.segment(i * dimension, dimension) = d.linear_velocity + turn;
    }
    return v;
}

/// a₀ = M⁻¹f(x₀) = −M⁻¹∇E(x₀) on the free coordinates, 0 on prescribed ones.
Eigen::VectorXd initial_acceleration(Scene& scene, const Eigen::VectorXd& x, int dimension)
{
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
    for (const auto& term : physical_terms(scene))
        term->add_gradient(x, gradient);
    Eigen::VectorXd a(x.size());
    for (Eigen::Index k = 0; k < x.size(); ++k)
        a[k] = -gradient[k] / scene.node_masses[k / dimension];
    for (int k : scene.problem->prescribed_coordinates())
        a[k] = 0.0;
    return a;
}

/// The measures of a row at state `state` (energies, momenta), with W the
/// external work done since t = 0.
void measure(Scene& scene, const TimeState& state, double work, int dimension, TimeStepRow& row)
{
    row.kinetic_energy = kinetic_energy(scene.node_masses, state.v, dimension);
    row.elastic_energy = scene.elastic->value(state.x);
    row.external_work = work;
    row.total_energy = row.kinetic_energy + row.elastic_energy - row.external_work;
    row.linear_momentum = linear_momentum(scene.node_masses, state.v, dimension);
    row.angular_momentum = angular_momentum(scene.node_masses, state.x, state.v, dimension);
}

/// Sets the inertia and damping terms for the integrator's next step.
void set_step_terms(Scene& scene, const TimeIntegrator& integrator, const DynamicsSettings& d)
{
    const Eigen::VectorXd predictor = integrator.predictor();
    scene.inertia->set_step(predictor, integrator.force_scaling());
    const double g = integrator.velocity_slope();
    const Eigen::VectorXd v_bar = integrator.velocity_at(predictor);  // v̄ = v(x̃)
    if (scene.mass_damping)  // vᵀ(αM)v/(2g) = ½‖y − (x̃ − v̄/g)‖²_M · αg
        scene.mass_damping->set_step(predictor - v_bar / g, 1.0 / (d.mass_damping * g));
    if (scene.stiffness_damping)
        scene.stiffness_damping->set_step(integrator.state().x, v_bar, predictor, g);
}

/// The largest diagonal entry of the step's Hessian ∇²(inertia + E) at x:
/// the scale of the gradient's round-off, ε·‖x‖∞·max Hᵢᵢ (a gradient entry
/// is a sum of terms of size Hᵢᵢ·|x|, each rounded).
double largest_hessian_diagonal(Scene& scene, const Eigen::VectorXd& x)
{
    TotalPotential& total = scene.problem->potential();
    const HessianPattern& pattern = total.hessian_pattern();
    Eigen::VectorXd values(pattern.nonzeros());
    total.hessian_values(x, Projection::none, values);
    double largest = 0.0;
    for (int k = 0; k < pattern.nonzeros(); ++k)
        if (pattern.rows()[k] == pattern.cols()[k])
            largest = std::max(largest, std::abs(values[k]));
    return largest;
}

/// ‖∇f‖∞ of the step's NLP at y = xₙ: the step's own force scale (M vₙ/h
/// and the unbalanced forces). The gradient at the explicit guess would
/// measure only how good the guess was, and the gradient at the solution is
/// zero: tolerances of a step are relative to this.
double step_force_scale(Scene& scene, const TimeIntegrator& integrator)
{
    QuasistaticProblem& problem = *scene.problem;
    const Eigen::VectorXd at_start = problem.variables_of(integrator.state().x);
    Eigen::VectorXd gradient(at_start.size());
    problem.gradient(at_start, gradient);
    return gradient.cwiseAbs().maxCoeff();
}

/// Text of x with every digit, for a backend option.
std::string exact_text(double x)
{
    std::ostringstream out;
    out << std::setprecision(17) << x;
    return out.str();
}

nlohmann::json row_json(const TimeStepRow& r)
{
    auto vector3 = [](const Eigen::Vector3d& v) { return nlohmann::json{number(v[0]), number(v[1]), number(v[2])}; };
    return {{"step", r.step},
            {"time", number(r.time)},
            {"status", r.step == 0 ? "initial" : to_string(r.status)},
            {"iterations", r.iterations},
            {"factorizations", r.factorizations},
            {"kinetic_energy", number(r.kinetic_energy)},
            {"elastic_energy", number(r.elastic_energy)},
            {"external_work", number(r.external_work)},
            {"total_energy", number(r.total_energy)},
            {"linear_momentum", vector3(r.linear_momentum)},
            {"angular_momentum", vector3(r.angular_momentum)},
            {"max_constraint_violation", number(r.max_constraint_violation)},
            {"time_s", number(r.time_s)}};
}

/// The output folder's files as the run goes.
class TimeSteppingOutput {
public:
    TimeSteppingOutput(Scene& scene, const SceneRunSettings& settings) : scene_(scene), settings_(settings)
    {
        if (settings.folder.empty())
            return;
        std::error_code error;
        std::filesystem::create_directories(settings.folder, error);
        if (error)
            throw InputError("cannot create output folder '" + settings.folder + "': " + error.message());
        folder_ = settings.folder + "/";
        check_writable(folder_ + "result.json");
    }

    /// A VTU of step k when every_step asks for it.
    void step(int k, double time, const TimeState& state, const Eigen::VectorXd& multipliers)
    {
        if (folder_.empty() || settings_.vtu != VtuOutput::every_step || k % scene_output_settings(scene_).every != 0)
            return;
        const std::string name = "step_" + std::to_string(k) + ".vtu";
        write(name, state, multipliers);
        collection_.push_back({time, name});
    }

    void finish(const TimeSteppingOutcome& outcome, const std::string& stopped, const TimeIntegrator& integrator)
    {
        if (folder_.empty())
            return;
        nlohmann::json vtu = nlohmann::json::array();
        if (settings_.vtu != VtuOutput::none) {
            write("result.vtu", outcome.state, outcome.last.constraint_multipliers);
            if (collection_.empty())
                collection_.push_back({outcome.steps.back().time, "result.vtu"});
            for (const PvdEntry& e : collection_)
                vtu.push_back(e.file);
            if (collection_.back().file != "result.vtu")
                vtu.push_back("result.vtu");
            write_pvd(folder_ + "result.pvd", collection_);
        }
        const DynamicsSettings& d = *scene_.dynamics;
        nlohmann::json steps = nlohmann::json::array();
        for (const TimeStepRow& r : outcome.steps)
            steps.push_back(row_json(r));
        const nlohmann::json out = {{"scene", scene_.name},
                                    {"description", scene_.description},
                                    {"solver", settings_.solver},
                                    {"integrator", integrator.name()},
                                    {"time_step", d.time_step},
                                    {"duration", d.duration},
                                    {"planned_steps", d.num_steps()},
                                    {"converged", outcome.converged},
                                    {"stopped", stopped},
                                    {"total_iterations", outcome.total_iterations},
                                    {"total_time_s", outcome.total_time_s},
                                    {"steps", steps},
                                    {"vtu", vtu},
                                    {"pvd", settings_.vtu != VtuOutput::none ? "result.pvd" : ""},
                                    {"result", to_json(outcome.last)}};
        write_text_file(folder_ + "result.json", out.dump(2) + "\n");
    }

private:
    void write(const std::string& name, const TimeState& state, const Eigen::VectorXd& multipliers)
    {
        const int dimension = static_cast<int>(scene_.mesh.nodes.rows());
        VtuArrays velocity;
        velocity["velocity"] = Eigen::Map<const Eigen::MatrixXd>(state.v.data(), dimension, state.v.size() / dimension);
        write_scene_vtu(folder_ + name, scene_, state.x, multipliers, settings_.encoding, velocity);
    }

    Scene& scene_;
    const SceneRunSettings& settings_;
    std::string folder_;
    std::vector<PvdEntry> collection_;
};

/// Adds a step's solve to the whole run's result.
void add_step(Result& run, const Result& step, const TimeStepRow& row, double elapsed_s)
{
    add_counts(run, step);
    run.time_s += step.time_s;
    run.constraint_violation = std::max(run.constraint_violation, step.constraint_violation);
    run.kkt_residual = std::max(run.kkt_residual, step.kkt_residual);
    HistoryRow history;
    history.iteration = row.step;
    history.objective = row.total_energy;
    history.constraint_violation = step.constraint_violation;
    history.dual_residual = step.kkt_residual;
    history.time_s = elapsed_s;
    run.history.push_back(history);
}

/// The last step's x and multipliers on the whole run, and how it ended.
void finish_run(Result& run, const Result& last, const TimeSteppingOutcome& outcome, const std::string& stopped)
{
    run.solver = last.solver;
    run.problem = last.problem;
    run.x = last.x;
    run.constraint_multipliers = last.constraint_multipliers;
    run.bound_multipliers_lower = last.bound_multipliers_lower;
    run.bound_multipliers_upper = last.bound_multipliers_upper;
    run.multipliers_estimated = last.multipliers_estimated;
    run.objective = last.objective;
    run.status = outcome.converged ? Status::converged : outcome.interrupted ? Status::user_stop : last.status;
    run.message = outcome.converged ? "every time step converged" : stopped;
}

/// x₀ (rest, prescribed motions and loads at t = 0), v₀ and a₀.
TimeState initial_state(Scene& scene, const DynamicsSettings& d)
{
    const int dimension = static_cast<int>(scene.mesh.nodes.rows());
    scene.apply_time(0.0);
    TimeState initial;
    initial.x = scene.problem->prescribed_configuration();
    initial.v = initial_velocity(d, initial.x, dimension);
    initial.a = initial_acceleration(scene, initial.x, dimension);
    return initial;
}

/// The solver options of each step: the run's, with one SolverMemory for the
/// whole run (projected Newton keeps its symbolic analysis and its factors
/// across steps), the KKT tolerance relative to the step's force scale (not
/// to max(1, ‖∇f‖∞) at the solution, where ∇f vanishes) and, for a solver
/// that declares them and was not given them, gradient_target set to that
/// target and finishing_step off: the step's solution error at the target,
/// about tol times the step's own displacement, lies far below the
/// integrator's truncation error (docs/dynamics.md), which one more Newton
/// step would not change.
class StepOptions {
public:
    explicit StepOptions(const SceneRunSettings& settings)
        : base_(settings.options), options_(settings.options),
          set_target_(step_sets(settings, "gradient_target"))
    {
        options_.memory = std::make_shared<SolverMemory>();
        if (step_sets(settings, "finishing_step"))
            options_.backend["finishing_step"] = "off";
    }

    const SolverOptions& for_step(Scene& scene, const TimeIntegrator& integrator, const Eigen::VectorXd& x0)
    {
        const double force_scale = step_force_scale(scene, integrator);
        options_.kkt_tolerance = base_.kkt_tolerance * std::max(1.0, force_scale);
        if (set_target_ && hessian_diagonal_ == 0.0)
            hessian_diagonal_ = largest_hessian_diagonal(scene, x0);
        if (set_target_)
            options_.backend["gradient_target"] =
                exact_text(step_gradient_target(base_.tolerance, force_scale,
                                                    integrator.predictor().cwiseAbs().maxCoeff(), hessian_diagonal_));
        return options_;
    }

private:
    const SolverOptions& base_;
    SolverOptions options_;
    const bool set_target_;
    double hessian_diagonal_ = 0.0;  ///< at the run's start, for the round-off floor
};

/// The row of step k from its solve (energies and momenta come from measure()).
TimeStepRow solved_row(long long k, double time, const Result& result)
{
    TimeStepRow row;
    row.step = static_cast<int>(k);
    row.time = time;
    row.status = result.status;
    row.iterations = result.iterations;
    const auto factorizations = result.statistics.find("factorizations");
    if (factorizations != result.statistics.end())
        row.factorizations = static_cast<int>(factorizations->second);
    row.max_constraint_violation = result.constraint_violation;
    row.time_s = result.time_s;
    return row;
}

} // namespace

TimeSteppingOutcome run_time_stepping(Scene& scene, const SceneRunSettings& settings,
                                      const TimeSteppingObserver& observer)
{
    if (!scene.dynamics)
        throw InputError(scene.name + ": the scene has no \"dynamics\" object to step in time");
    if (settings.load_steps != 1)
        throw InputError(scene.name + ": load steps (" + std::to_string(settings.load_steps) +
                         ") do not apply to a scene stepped in time; its load factor over time is dynamics.load_curve");
    const DynamicsSettings& d = *scene.dynamics;
    check_solve(*scene.problem, settings.solver, settings.options);
    std::unique_ptr<TimeIntegrator> integrator = make_integrator(d.integrator, d.time_step);
    TimeSteppingOutput output(scene, settings);  // every input is checked before this

    QuasistaticProblem& problem = *scene.problem;
    const int dimension = static_cast<int>(scene.mesh.nodes.rows());
    const TimeState initial = initial_state(scene, d);
    integrator->start(initial);

    TimeSteppingOutcome outcome;
    outcome.state = initial;
    TimeStepRow row;
    double work = 0.0;  // W
    measure(scene, initial, work, dimension, row);
    outcome.steps.push_back(row);
    output.step(0, 0.0, initial, Eigen::VectorXd());
    if (observer.on_step)
        observer.on_step(row, initial);

    const long long n = d.num_steps();
    StepOptions step_options(settings);
    std::string stopped;
    for (long long k = 1; k <= n && stopped.empty(); ++k) {
        const double t0 = static_cast<double>(k - 1) * d.time_step, t1 = static_cast<double>(k) * d.time_step;
        scene.apply_time(t0, t1, integrator->force_time_weight());
        set_step_terms(scene, *integrator, d);
        const SolverOptions& options = step_options.for_step(scene, *integrator, initial.x);
        problem.set_starting_configuration(integrator->explicit_guess());
        outcome.last = solve_with_refreshed_rows(problem, settings.solver, options);
        const Result& result = outcome.last;
        const Eigen::VectorXd x_n = outcome.state.x;
        integrator->advance(problem.full_configuration(result.x));
        outcome.state = integrator->state();
        // W += E_ext(xₙ) − E_ext(xₙ₊₁) under the step's forces: f·Δx for gravity and loads
        work += external_potential(scene, x_n) - external_potential(scene, outcome.state.x);
        outcome.total_iterations += result.iterations;
        outcome.total_time_s += result.time_s;

        row = solved_row(k, t1, result);
        scene.apply_time(t1);  // energies at tₙ₊₁'s loads
        measure(scene, outcome.state, work, dimension, row);
        outcome.steps.push_back(row);
        add_step(outcome.run, result, row, outcome.total_time_s);
        output.step(static_cast<int>(k), t1, outcome.state, result.constraint_multipliers);
        if (observer.on_step)
            observer.on_step(row, outcome.state);
        if (result.status != Status::converged)
            stopped = "step " + std::to_string(k) + " did not converge (" + to_string(result.status) + ")";
        else if (k < n && observer.stop_requested && observer.stop_requested()) {
            outcome.interrupted = true;
            stopped = "interrupted after step " + std::to_string(k) + " of " + std::to_string(n);
        }
    }
    outcome.converged = stopped.empty();
    finish_run(outcome.run, outcome.last, outcome, stopped);
    output.finish(outcome, stopped, *integrator);
    return outcome;
}

} // namespace sinew
