#include "sinew/runs/mpm_run.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/core/rotation_vector.hpp"
#include "sinew/mesh/cell_vtu_writer.hpp"
#include "sinew/mesh/pvd_writer.hpp"
#include "sinew/mesh/vtp_writer.hpp"
#include "sinew/mpm/active_grid.hpp"
#include "sinew/mpm/cfl.hpp"
#include "sinew/mpm/damage/damage_update.hpp"
#include "sinew/mpm/explicit_step.hpp"
#include "sinew/mpm/grid_velocity_nlp.hpp"
#include "sinew/mpm/implicit_step.hpp"
#include "sinew/mpm/inextensibility/fiber_drift.hpp"
#include "sinew/mpm/inextensibility/inextensibility_rows.hpp"
#include "sinew/mpm/particle_buckets.hpp"
#include "sinew/mpm/particle_measures.hpp"
#include "sinew/runs/jacobi_cg.hpp"
#include "sinew/runs/output_file.hpp"
#include "sinew/runs/result_json.hpp"
#include "sinew/runs/scene_run_settings.hpp"
#include "sinew/runs/step_gradient_target.hpp"
#include "sinew/solvers/solver.hpp"

#include <Eigen/LU>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <utility>

namespace sinew {
namespace {

/// N = ⌈T/Δt⌉ steps (Δt·N within round-off of T counts as T).
long long step_count(const MpmScene& scene, double time_step)
{
    return static_cast<long long>(std::ceil(scene.duration / time_step * (1.0 - 1e-12)));
}

template <int Dim>
MpmFrameRow measure(const MpmSetup<Dim>& setup, const Particles<Dim>& particles, double dx, double cfl)
{
    const auto models = setup.model_pointers();
    MpmFrameRow row;
    row.kinetic_energy = kinetic_energy(particles);
    row.elastic_energy = elastic_energy(particles, models);
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        row.gravity_energy -= particles.mass[i] * setup.step.gravity.dot(particles.x[i]);  // −m g·x
        const double J = particles.F[i].determinant();
        row.min_J = p == 0 ? J : std::min(row.min_J, J);
        row.max_J = p == 0 ? J : std::max(row.max_J, J);
    }
    row.total_energy = row.kinetic_energy + row.elastic_energy + row.gravity_energy;
    double volume = 0.0;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        row.max_damage = std::max(row.max_damage, particles.point[i].damage);
        row.mean_damage += particles.volume[i] * particles.point[i].damage;
        volume += particles.volume[i];
    }
    row.mean_damage /= volume;  // Σ V⁰ d / Σ V⁰
    row.linear_momentum.head<Dim>() = linear_momentum(particles);
    row.cfl_time_step = cfl_time_step(particles, models, dx, cfl);
    return row;
}

/// The particles' point data: velocity, det F, ‖P‖, material, current fiber F a₀, damage.
/// The active grid's node data: mass and velocity.
template <int Dim>
VtuArrays grid_arrays(const SparseGrid<Dim>& grid, const ActiveGrid<Dim>& active)
{
    const auto count = static_cast<Eigen::Index>(active.slots.size());
    Eigen::MatrixXd mass(1, count), velocity(Dim, count);
    for (Eigen::Index k = 0; k < count; ++k) {
        const auto s = static_cast<std::size_t>(active.slots[static_cast<std::size_t>(k)]);
        mass(0, k) = grid.mass[s];
        velocity.col(k) = grid.velocity[s];
    }
    return {{"mass", mass}, {"velocity", velocity}};
}

template <int Dim>
VtuArrays particle_arrays(const MpmScene& scene, const MpmSetup<Dim>& setup, const Particles<Dim>& particles)
{
    const auto count = static_cast<Eigen::Index>(particles.size());
    Eigen::MatrixXd velocity(Dim, count), fiber(Dim, count), J(1, count), stress(1, count), material(1, count),
        damage(1, count);
    for (Eigen::Index p = 0; p < count; ++p) {
        const auto i = static_cast<std::size_t>(p);
        typename ConstitutiveModel<Dim, Dim>::Stress P;
        setup.models[static_cast<std::size_t>(particles.material[i])]->evaluate(particles.F[i], particles.point[i], &P,
                                                                                nullptr, Projection::none);
        velocity.col(p) = particles.v[i];
        fiber.col(p) = particles.F[i] * particles.point[i].fiber;
        J(0, p) = particles.F[i].determinant();
        stress(0, p) = P.norm();
        material(0, p) = particles.material[i];
        damage(0, p) = particles.point[i].damage;
    }
    VtuArrays arrays{{"velocity", velocity}, {"J", J}, {"stress_norm", stress}, {"material", material}, {"fiber", fiber},
                     {"damage", damage}};
    if (!particles.phase_field.empty()) {  // D̃ᴴ, the driving force's history
        Eigen::MatrixXd history(1, count);
        for (Eigen::Index p = 0; p < count; ++p)
            history(0, p) = particles.phase_field[static_cast<std::size_t>(p)].history;
        arrays["damage_history"] = history;
    }
    if (scene.inextensibility) {  // a₀ᵀ C a₀ − 1, and which particles carry the constraint
        Eigen::MatrixXd stretch(1, count), inextensible(1, count);
        for (Eigen::Index p = 0; p < count; ++p) {
            const auto i = static_cast<std::size_t>(p);
            stretch(0, p) = (particles.F[i] * particles.point[i].fiber).squaredNorm() - 1.0;
            inextensible(0, p) = scene.inextensibility->carries(particles.material[i]) ? 1.0 : 0.0;
        }
        arrays["fiber_stretch"] = stretch;
        arrays["inextensible"] = inextensible;
    }
    return arrays;
}

Eigen::MatrixXd positions_of(const std::vector<Eigen::Vector2d>& x)
{
    Eigen::MatrixXd out(2, static_cast<Eigen::Index>(x.size()));
    for (std::size_t p = 0; p < x.size(); ++p)
        out.col(static_cast<Eigen::Index>(p)) = x[p];
    return out;
}

Eigen::MatrixXd positions_of(const std::vector<Eigen::Vector3d>& x)
{
    Eigen::MatrixXd out(3, static_cast<Eigen::Index>(x.size()));
    for (std::size_t p = 0; p < x.size(); ++p)
        out.col(static_cast<Eigen::Index>(p)) = x[p];
    return out;
}

nlohmann::json to_json(const MpmFrameRow& row, bool damage, bool inextensibility)
{
    nlohmann::json out = {{"frame", row.frame},
            {"time", row.time},
            {"steps", row.steps},
            {"kinetic_energy", number(row.kinetic_energy)},
            {"elastic_energy", number(row.elastic_energy)},
            {"gravity_energy", number(row.gravity_energy)},
            {"total_energy", number(row.total_energy)},
            {"linear_momentum", {number(row.linear_momentum[0]), number(row.linear_momentum[1]), number(row.linear_momentum[2])}},
            {"min_J", number(row.min_J)},
            {"max_J", number(row.max_J)},
            {"cfl_time_step", number(row.cfl_time_step)},
            {"iterations", row.iterations},
            {"time_s", row.time_s},
            {"transfer_s", row.transfer_s},
            {"momentum_s", row.momentum_s}};
    if (damage) {
        out["damage_s"] = row.damage_s;
        out["damage_cg_iterations"] = row.damage_cg_iterations;
        out["damage_grown"] = row.damage_grown;
        out["damage_capped"] = row.damage_capped;
        out["damage_decrease_refused"] = row.damage_decrease_refused;
        out["max_damage"] = number(row.max_damage);
        out["mean_damage"] = number(row.mean_damage);
    }
    if (inextensibility) {
        out["inextensibility_s"] = row.inextensibility_s;
        out["inextensibility_cg_iterations"] = row.inextensibility_cg_iterations;
        out["constraint_violation"] = number(row.constraint_violation);
        out["fiber_drift_max"] = number(row.fiber_drift_max);
        out["fiber_drift_rms"] = number(row.fiber_drift_rms);
    }
    return out;
}

/// The largest diagonal entry of the NLP's Hessian at x.
double largest_hessian_diagonal(Nlp& nlp, const Eigen::VectorXd& x)
{
    Eigen::VectorXd values(nlp.hessian_pattern().nonzeros());
    nlp.hessian(x, 1.0, Eigen::VectorXd(), Projection::none, values);
    double largest = 0.0;
    for (int k = 0; k < values.size(); ++k)
        if (nlp.hessian_pattern().rows[static_cast<std::size_t>(k)] == nlp.hessian_pattern().cols[static_cast<std::size_t>(k)])
            largest = std::max(largest, std::abs(values[k]));
    return largest;
}

/// The implicit steps' solve: the settings' solver, its counts and
/// verdicts summed. Each step's KKT tolerance, and the gradient target of a
/// solver that declares one (unless the caller set it), are relative to the
/// step's force scale max(‖∇E(v*)‖∞, ‖v*‖∞ · max Hᵢᵢ), as a time step's are
/// (runs/step_gradient_target.hpp): a step that starts at its solution up to
/// round-off (free fall) ends there, converged.
struct ImplicitSolves {
    const SceneRunSettings& settings;
    Result counts;  ///< every solve's iterations, evaluations and statistics (assembly and factorization time)
    int not_converged = 0;

    GridVelocitySolve solve()
    {
        return [this](Nlp& nlp, Eigen::VectorXd& v) {
            SolverOptions options = settings.options;
            options.verbosity = 0;
            Eigen::VectorXd gradient(v.size());
            nlp.gradient(v, gradient);
            const double diagonal = largest_hessian_diagonal(nlp, v);
            const double predictor = v.cwiseAbs().maxCoeff();
            const double force_scale = std::max(gradient.cwiseAbs().maxCoeff(), predictor * diagonal);
            options.kkt_tolerance = settings.options.kkt_tolerance * std::max(1.0, force_scale);
            if (step_sets(settings, "gradient_target"))
                options.backend["gradient_target"] =
                    option_text(step_gradient_target(settings.options.tolerance, force_scale, predictor, diagonal));
            const Result result = sinew::solve(nlp, settings.solver, options);
            v = result.x;
            add_counts(counts, result);
            const bool converged = result.status == Status::converged;
            not_converged += converged ? 0 : 1;
            return converged;
        };
    }
};

template <int Dim>
class MpmRun {
public:
    MpmRun(const MpmScene& scene, const SceneRunSettings& settings)
        : scene_(scene), settings_(settings), setup_(std::get<MpmSetup<Dim>>(scene.setup)),
          particles_(setup_.particles), grid_(scene.dx), solves_{settings, Result{}, 0}, damage_grid_(scene.dx)
    {
        if (scene.damage)
            damage_solve_ = jacobi_cg(scene.damage->cg_tolerance, scene.damage->cg_max_iterations);
        if (scene.inextensibility)
            inextensibility_ = GridInextensibility<Dim>{*scene.inextensibility,
                                                        jacobi_cg(scene.inextensibility->cg_tolerance,
                                                                  scene.inextensibility->cg_max_iterations)};
        sort_particles_by_block(particles_, scene.dx, setup_.step.transfer.order);  // the run's numbering from frame 0
        for (const GridCollider<Dim>& collider : setup_.step.colliders)
            moving_.push_back(std::make_shared<PlacedBody>(*collider.body));
    }

    /// The explicit bound at t = 0, and the implicit solver on the first step's NLP.
    void check() const
    {
        const double bound = cfl_time_step(particles_, setup_.model_pointers(), scene_.dx, scene_.cfl);
        if (scene_.stepping == MpmStepping::explicit_steps && !scene_.substeps && step_length() > bound)
            throw InputError("mpm: time_step " + format_number(step_length()) + " s exceeds the explicit CFL bound " +
                             format_number(bound) + " s (cfl " + format_number(scene_.cfl) +
                             "); lower it, set \"substeps\": true, or use \"stepping\": \"implicit\"");
        const bool sub_stepped = scene_.stepping == MpmStepping::explicit_steps && scene_.substeps;
        if (!sub_stepped && step_length() > damage_time_step())
            throw InputError("mpm_damage: time_step " + format_number(step_length()) +
                             " s exceeds the explicit damage's stability bound " + format_number(damage_time_step()) +
                             " s (2η/(1 + 4 dim l0²/dx²)); lower it, or use \"integration\": \"implicit\"");
        if (scene_.stepping == MpmStepping::implicit_steps) {
            SparseGrid<Dim> grid(scene_.dx);
            const ParticleBuckets<Dim> layout = particles_to_grid(particles_, setup_.step.transfer, grid);
            const auto models = setup_.model_pointers();
            const MpmStepSettings<Dim> step = step_settings();
            GridVelocityMap<Dim> map(particles_, grid, step, GridVelocityMap<Dim>::Predictor::momentum_and_gravity);
            LinearVelocityRows rows;
            if (inextensibility_ && inextensibility_->settings.method == InextensibilityMethod::nlp)
                rows = independent_rows(inextensibility_rows(particles_, map, scene_.dx, inextensibility_->settings));
            GridVelocityNlp<Dim> nlp(particles_, models, std::move(map), layout, step.time_step, std::move(rows));
            check_solve(nlp, settings_.solver, settings_.options);
        }
    }

    MpmRunOutcome run(const std::function<void(const MpmFrameRow&)>& on_frame)
    {
        const auto start = std::chrono::steady_clock::now();
        const long long steps = step_count(scene_, setup_.step.time_step);
        MpmRunOutcome outcome;
        record(0, 0, outcome, on_frame, start);
        for (int frame = 1; frame <= scene_.frames && outcome.stopped.empty(); ++frame) {
            const long long last = steps * frame / scene_.frames;
            for (; taken_ < last && outcome.stopped.empty(); ++taken_)
                outcome.stopped = step();
            record(frame, taken_, outcome, on_frame, start);
        }
        outcome.steps = sub_steps_;
        outcome.positions.resize(Dim * particles_.size());
        for (int p = 0; p < particles_.size(); ++p)
            outcome.positions.segment<Dim>(Dim * p) = particles_.x[static_cast<std::size_t>(p)];
        const bool solved = solves_.not_converged == 0 && damage_not_converged_ == 0 && projections_not_converged_ == 0;
        if (outcome.stopped.empty() && solves_.not_converged > 0)
            outcome.stopped = std::to_string(solves_.not_converged) + " implicit solves did not converge";
        if (outcome.stopped.empty() && damage_not_converged_ > 0)
            outcome.stopped = std::to_string(damage_not_converged_) + " damage solves did not converge";
        if (outcome.stopped.empty() && projections_not_converged_ > 0)
            outcome.stopped = std::to_string(projections_not_converged_) + " inextensibility projections did not converge";
        outcome.converged = outcome.stopped.empty();
        outcome.run.solver = scene_.stepping == MpmStepping::implicit_steps ? settings_.solver : "explicit";
        outcome.run.problem = "mpm";
        outcome.run.status = outcome.converged ? Status::converged : solved ? Status::failed : Status::max_iterations;
        outcome.run.message = outcome.converged ? "reached t = " + format_number(scene_.duration) + " s" : outcome.stopped;
        add_counts(outcome.run, solves_.counts);
        outcome.run.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        outcome.run.statistics["steps"] = static_cast<double>(sub_steps_);
        write_result(outcome);
        return outcome;
    }

    /// Creates the folder (after every check) and remembers where to write.
    void open_folder()
    {
        if (settings_.folder.empty())
            return;
        std::error_code error;
        std::filesystem::create_directories(settings_.folder, error);
        if (error)
            throw InputError("cannot create output folder '" + settings_.folder + "': " + error.message());
        folder_ = settings_.folder + "/";
        check_writable(folder_ + "result.json");
    }

private:
    double step_length() const { return scene_.duration / static_cast<double>(step_count(scene_, setup_.step.time_step)); }

    /// The explicit damage's stability bound on Δt (+∞ without it).
    double damage_time_step() const
    {
        if (!scene_.damage || scene_.damage->integration != DamageIntegration::explicit_damage)
            return std::numeric_limits<double>::infinity();
        return explicit_damage_time_step(particles_, scene_.dx);
    }

    /// One damage update of `dt` before a step (none without "mpm_damage"),
    /// added to the frame's counts; why the run must end, or "".
    std::string advance_damage(const std::vector<const ConstitutiveModel<Dim, Dim>*>& models, double dt)
    {
        if (!scene_.damage)
            return {};
        const auto start = std::chrono::steady_clock::now();
        const DamageReport report = update_damage(particles_, models, dt, *scene_.damage, damage_grid_, damage_solve_);
        damage_counts_.damage_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        damage_counts_.damage_cg_iterations += report.cg_iterations;
        damage_counts_.damage_grown += report.grown;
        damage_counts_.damage_capped += report.capped_at_one;
        damage_counts_.damage_decrease_refused += report.decrease_refused;
        damage_not_converged_ += report.cg_converged ? 0 : 1;
        return report.failure;
    }

    /// The scene's step settings with Δt = T/N and the run's own colliders,
    /// each placed where its motion has carried it by `time`: a point x₀ of
    /// the body at x = Q (x₀ − c₀) + c₀ + v t, Q = exp(t [ω]×), its centre at c₀ + v t.
    MpmStepSettings<Dim> step_settings(double time = 0.0) const
    {
        MpmStepSettings<Dim> step = setup_.step;
        step.time_step = step_length();
        for (std::size_t k = 0; k < moving_.size(); ++k) {
            const GridCollider<Dim>& scene_collider = setup_.step.colliders[k];
            const PlacedBody& start = *scene_collider.body;
            const Eigen::Matrix3d Q = rotation_matrix(time * scene_collider.angular_velocity);
            Eigen::Vector3d center = Eigen::Vector3d::Zero(), travel = Eigen::Vector3d::Zero();
            center.head<Dim>() = scene_collider.center;
            travel.head<Dim>() = time * scene_collider.velocity;
            moving_[k]->set_placement(Q * start.rotation(), Q * (start.translation() - center) + center + travel);
            step.colliders[k].body = moving_[k];
            step.colliders[k].center = scene_collider.center + time * scene_collider.velocity;
        }
        return step;
    }

    const GridInextensibility<Dim>* inextensibility() const { return inextensibility_ ? &*inextensibility_ : nullptr; }

    /// A step's inextensibility into the frame's counts, then the drift
    /// correction by projection (the other corrections act inside the rows).
    void after_step(const InextensibilityStepReport& report)
    {
        if (!inextensibility_)
            return;
        const auto start = std::chrono::steady_clock::now();
        if (inextensibility_->settings.correction == FiberDriftCorrection::projection)
            project_fiber_lengths(particles_, inextensibility_->settings);
        inextensibility_counts_.inextensibility_s +=
            report.seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        inextensibility_counts_.inextensibility_cg_iterations += report.cg_iterations;
        inextensibility_counts_.constraint_violation =
            std::max(inextensibility_counts_.constraint_violation, report.violation);
        projections_not_converged_ += report.converged ? 0 : 1;
    }

    /// One step of the scene's Δt; why the run must end, or "".
    std::string step()
    {
        const auto models = setup_.model_pointers();
        const double time = static_cast<double>(taken_) * step_length();
        MpmStepSettings<Dim> step = step_settings(time);
        if (scene_.stepping == MpmStepping::implicit_steps) {
            ++sub_steps_;
            const std::string failure = advance_damage(models, step.time_step);
            if (!failure.empty())
                return failure;
            const auto start = std::chrono::steady_clock::now();
            const ImplicitStepReport report = implicit_step(particles_, models, step, grid_, solves_.solve(), inextensibility());
            step_times_.momentum_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() -
                                      report.inextensibility.seconds;
            after_step(report.inextensibility);
            return report.failure;
        }
        const double bound = std::min(cfl_time_step(particles_, models, scene_.dx, scene_.cfl), damage_time_step());
        int parts = 1;
        if (step.time_step > bound) {
            if (!scene_.substeps)
                return "step " + std::to_string(taken_ + 1) + ": time_step " + format_number(step.time_step) +
                       " s exceeds the explicit CFL (or explicit damage) bound " + format_number(bound) + " s at this state";
            parts = static_cast<int>(std::min(1e6, std::ceil(step.time_step / bound)));
        }
        const double part = step.time_step / parts;
        for (int k = 0; k < parts; ++k) {
            MpmStepSettings<Dim> sub_step = step_settings(time + k * part);
            sub_step.time_step = part;
            ++sub_steps_;
            std::string failure = advance_damage(models, part);
            if (failure.empty()) {
                const ExplicitStepReport report = explicit_step(particles_, models, sub_step, grid_, inextensibility());
                step_times_.transfer_s += report.to_grid_s + report.to_particles_s;
                step_times_.momentum_s += report.stress_s + report.grid_update_s;
                if (report.failure.empty())
                    after_step(report.inextensibility);
                failure = report.failure;
            }
            if (!failure.empty())
                return failure;
        }
        return {};
    }

    void record(int frame, long long steps, MpmRunOutcome& outcome, const std::function<void(const MpmFrameRow&)>& on_frame,
                std::chrono::steady_clock::time_point start)
    {
        MpmFrameRow row = measure(setup_, particles_, scene_.dx, scene_.cfl);
        row.frame = frame;
        row.time = scene_.duration * static_cast<double>(steps) / static_cast<double>(step_count(scene_, setup_.step.time_step));
        row.steps = sub_steps_;
        row.damage_s = damage_counts_.damage_s;
        row.damage_cg_iterations = damage_counts_.damage_cg_iterations;
        row.damage_grown = damage_counts_.damage_grown;
        row.damage_capped = damage_counts_.damage_capped;
        row.damage_decrease_refused = damage_counts_.damage_decrease_refused;
        damage_counts_ = MpmFrameRow{};
        if (inextensibility_) {
            row.inextensibility_s = inextensibility_counts_.inextensibility_s;
            row.inextensibility_cg_iterations = inextensibility_counts_.inextensibility_cg_iterations;
            row.constraint_violation = inextensibility_counts_.constraint_violation;
            inextensibility_counts_ = MpmFrameRow{};
            const FiberDrift drift = fiber_drift(particles_, inextensibility_->settings);
            row.fiber_drift_max = drift.max;
            row.fiber_drift_rms = drift.rms;
        }
        row.transfer_s = step_times_.transfer_s;
        row.momentum_s = step_times_.momentum_s;
        step_times_ = MpmFrameRow{};
        row.iterations = solves_.counts.iterations - iterations_recorded_;
        iterations_recorded_ = solves_.counts.iterations;
        row.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        outcome.frames.push_back(row);
        if (!folder_.empty() && settings_.vtu != VtuOutput::none) {
            const std::string name = "frame_" + std::to_string(frame) + ".vtp";
            write_vtp(folder_ + name, positions_of(particles_.x), particle_arrays(scene_, setup_, particles_), settings_.encoding);
            collection_.push_back({row.time, name});
            if (scene_.grid_output)
                write_grid(frame, row.time);
        }
        if (on_frame)
            on_frame(row);
    }

    /// grid_k.vtu: the grid of the frame's last step (at t = 0, the particles' P2G).
    void write_grid(int frame, double time)
    {
        if (frame == 0)
            particles_to_grid(particles_, setup_.step.transfer, grid_);
        const ActiveGrid<Dim> active = active_grid(grid_);
        const std::string name = "grid_" + std::to_string(frame) + ".vtu";
        write_cell_vtu<Dim>(folder_ + name, active.positions, active.cells, grid_arrays(grid_, active), settings_.encoding);
        grid_collection_.push_back({time, name});
    }

    void write_result(const MpmRunOutcome& outcome) const
    {
        if (folder_.empty())
            return;
        nlohmann::json frames = nlohmann::json::array(), files = nlohmann::json::array();
        for (const MpmFrameRow& row : outcome.frames)
            frames.push_back(to_json(row, scene_.damage.has_value(), scene_.inextensibility.has_value()));
        for (const PvdEntry& entry : collection_)
            files.push_back(entry.file);
        if (!collection_.empty())
            write_pvd(folder_ + "result.pvd", collection_);
        nlohmann::json grid_files = nlohmann::json::array();
        for (const PvdEntry& entry : grid_collection_)
            grid_files.push_back(entry.file);
        if (!grid_collection_.empty())
            write_pvd(folder_ + "grid.pvd", grid_collection_);
        nlohmann::json result = {
            {"scene", "mpm"},
            {"dimension", Dim},
            {"particles", particles_.size()},
            {"materials", scene_.materials},
            {"dx", scene_.dx},
            {"stepping", scene_.stepping == MpmStepping::implicit_steps ? "implicit" : "explicit"},
            {"solver", scene_.stepping == MpmStepping::implicit_steps ? nlohmann::json(settings_.solver) : nlohmann::json()},
            {"time_step", step_length()},
            {"duration", scene_.duration},
            {"cfl", scene_.cfl},
            {"substeps", scene_.substeps},
            {"steps", outcome.steps},
            {"converged", outcome.converged},
            {"stopped", outcome.stopped},
            {"status", to_string(outcome.run.status)},
            {"iterations", outcome.run.iterations},
            {"statistics", outcome.run.statistics},
            {"time_s", outcome.run.time_s},
            {"vtp", files},
            {"grid_vtu", grid_files},
            {"frames", frames}};
        if (scene_.damage) {
            const DamageSettings& damage = *scene_.damage;
            const bool implicit = damage.integration == DamageIntegration::implicit_damage;
            nlohmann::json summary = {{"integration", implicit ? "implicit" : "explicit"},
                                      {"solves_not_converged", damage_not_converged_}};
            if (implicit) {
                summary["preconditioner"] =
                    damage.implicit.preconditioner == DamagePreconditioner::lumped ? "lumped" : "full_diagonal";
                summary["transfer"] = damage.implicit.transfer == DamageTransfer::seed ? "seed" : "increment";
                summary["cg_tolerance"] = damage.cg_tolerance;
            }
            result["damage"] = summary;
        }
        if (scene_.inextensibility) {
            const InextensibilitySettings& inextensible = *scene_.inextensibility;
            nlohmann::json materials = nlohmann::json::array();
            for (std::size_t k = 0; k < scene_.materials.size(); ++k)
                if (inextensible.carries(static_cast<int>(k)))
                    materials.push_back(scene_.materials[k]);
            const bool schur = inextensible.method == InextensibilityMethod::schur_cg;
            nlohmann::json summary = {
                {"materials", materials},
                {"method", schur ? "schur-cg" : "nlp"},
                {"drift_correction", inextensible.correction == FiberDriftCorrection::projection ? "projection" : "none"},
                {"projections_not_converged", projections_not_converged_}};
            if (schur) {
                summary["cg_tolerance"] = inextensible.cg_tolerance;
                summary["cg_max_iterations"] = inextensible.cg_max_iterations;
            }
            result["inextensibility"] = summary;
        }
        write_text_file(folder_ + "result.json", result.dump(2) + "\n");
    }

    const MpmScene& scene_;
    const SceneRunSettings& settings_;
    const MpmSetup<Dim>& setup_;
    Particles<Dim> particles_;
    SparseGrid<Dim> grid_;
    ImplicitSolves solves_;
    DamageGrid<Dim> damage_grid_;
    SpdSolve damage_solve_;
    MpmFrameRow damage_counts_;     ///< the damage fields only: since the last frame
    MpmFrameRow step_times_;        ///< transfer_s and momentum_s only: since the last frame
    int damage_not_converged_ = 0;  ///< implicit damage solves that missed their tolerance
    std::optional<GridInextensibility<Dim>> inextensibility_;
    MpmFrameRow inextensibility_counts_;  ///< the inextensibility fields only: since the last frame
    int projections_not_converged_ = 0;   ///< Schur solves that missed their tolerance
    long long taken_ = 0;      ///< steps of the scene's Δt taken
    long long sub_steps_ = 0;  ///< steps taken, sub-steps counted
    int iterations_recorded_ = 0;
    std::string folder_;
    std::vector<PvdEntry> collection_;
    std::vector<PvdEntry> grid_collection_;  ///< grid_k.vtu, with grid_output
    /// The colliders as this run places them (the scene's stay where they start).
    std::vector<std::shared_ptr<PlacedBody>> moving_;
};

template <int Dim>
MpmRunOutcome run_in(const MpmScene& scene, const SceneRunSettings& settings,
                     const std::function<void(const MpmFrameRow&)>& on_frame)
{
    MpmRun<Dim> run(scene, settings);
    run.check();
    run.open_folder();
    return run.run(on_frame);
}

} // namespace

void check_mpm_run(const MpmScene& scene, const SceneRunSettings& settings)
{
    if (scene.dimension == 2)
        MpmRun<2>(scene, settings).check();
    else
        MpmRun<3>(scene, settings).check();
}

MpmRunOutcome run_mpm(const MpmScene& scene, const SceneRunSettings& settings,
                      const std::function<void(const MpmFrameRow&)>& on_frame)
{
    return scene.dimension == 2 ? run_in<2>(scene, settings, on_frame) : run_in<3>(scene, settings, on_frame);
}

} // namespace sinew
