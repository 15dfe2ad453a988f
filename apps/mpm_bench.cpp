#include "mpm_bench.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/threads.hpp"
#include "sinew/energies/models/model_catalog.hpp"
#include "sinew/mpm/cfl.hpp"
#include "sinew/mpm/explicit_step.hpp"
#include "sinew/mpm/particle_buckets.hpp"
#include "sinew/mpm/particle_sampling.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/mpm_run.hpp"
#include "sinew/runs/scene_run_settings.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numeric>
#include <variant>
#include <vector>

namespace sinew::cli {
namespace {

/// Bytes one explicit particle-step reads and writes of particle data (3D,
/// doubles): the stress pass reads F, V⁰ and writes ψ and the impulse S;
/// P2G reads x, v, C, m, S; G2P with the advection reads x, F and writes
/// v, C, x, F. The grid's nodes (27 per particle) stay in cache when
/// particles are visited in block order.
constexpr double kParticleBytes = 8.0 * ((9 + 1 + 1 + 9) + (3 + 3 + 9 + 1 + 9) + (3 + 9 + 3 + 9 + 3 + 9));

/// The machine's memory bandwidth: a[i] = b[i] + s·c[i] over three arrays of
/// 64 MB (STREAM's triad, one thread), the best of five, in bytes/s.
double triad_bandwidth()
{
    const std::size_t n = std::size_t(8) << 20;
    std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
    double best = 0.0;
    for (int trial = 0; trial < 5; ++trial) {
        const auto start = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < n; ++i)
            a[i] = b[i] + 3.0 * c[i];
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best = std::max(best, 3.0 * 8.0 * static_cast<double>(n) / seconds);
    }
    volatile double keep = a[n / 2];
    static_cast<void>(keep);
    return best;
}

/// A cube of about `count` particles (2 × 2 × 2 a cell of dx = 1 cm),
/// stretched 1 % and spinning at 1 rad/s, so that every particle has a
/// stress; numbered block after block, as an mpm run numbers its particles.
Particles<3> spinning_cube(double count)
{
    LatticeSampling<3> sampling;
    sampling.dx = 0.01;
    const double side = std::cbrt(count) * 0.5 * sampling.dx;
    Particles<3> particles = sample_box<3>(Eigen::Vector3d::Constant(0.5 - side / 2), Eigen::Vector3d::Constant(0.5 + side / 2), sampling);
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        const Eigen::Vector3d r = particles.x[i] - Eigen::Vector3d::Constant(0.5);
        particles.v[i] = Eigen::Vector3d(-r[1], r[0], 0.0);
        particles.C[i] << 0, -1, 0, 1, 0, 0, 0, 0, 0;
        particles.F[i] = Eigen::Vector3d(1.01, 1.0, 1.0).asDiagonal();
    }
    sort_particles_by_block(particles, sampling.dx, SplineOrder::quadratic);
    return particles;
}

struct ExplicitRun {
    int particles = 0, threads = 1, steps = 0;
    double seconds = 0.0, to_grid = 0.0, stress = 0.0, grid = 0.0, to_particles = 0.0;
    std::vector<double> transfer_s;  ///< each step's P2G + G2P
    bool finite = true;

    /// The median step's P2G + G2P (s): the figure a neighbour's burst on a
    /// shared machine moves least.
    double median_transfers() const
    {
        std::vector<double> sorted = transfer_s;
        std::sort(sorted.begin(), sorted.end());
        const std::size_t n = sorted.size();
        return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }
};

ExplicitRun run_explicit(double count, int threads, int steps)
{
    set_threads(threads);
    const auto model = make_model<3, 3>("fixed-corotated", ParameterValues{{"mu", 1e5}, {"lambda", 1e5}});
    const std::vector<const Model3d*> models{model.get()};
    Particles<3> particles = spinning_cube(count);
    MpmStepSettings<3> settings;
    settings.time_step = 1e-5;
    SparseGrid<3> grid(0.01);
    ExplicitRun run;
    run.particles = particles.size();
    run.threads = threads;
    run.steps = steps;
    explicit_step(particles, models, settings, grid);  // the grid's blocks allocated once, not timed
    for (int n = 0; n < steps; ++n) {
        const ExplicitStepReport report = explicit_step(particles, models, settings, grid);
        run.finite = run.finite && report.failure.empty();
        run.to_grid += report.to_grid_s;
        run.stress += report.stress_s;
        run.grid += report.grid_update_s;
        run.to_particles += report.to_particles_s;
        run.transfer_s.push_back(report.to_grid_s + report.to_particles_s);
    }
    run.seconds = run.to_grid + run.stress + run.grid + run.to_particles;
    return run;
}

void explicit_table(nlohmann::json& runs, bool& all_finite)
{
    const double bandwidth = triad_bandwidth();
    std::cout << "Explicit steps, 3D cube, quadratic B-splines, APIC, fixed corotated (P2G scatters mass, momentum "
                 "and the stress impulses in one pass); one particle-step moves about "
              << table_cell("%.0f", kParticleBytes) << " bytes of particle data; triad bandwidth "
              << table_cell("%.1f", bandwidth / 1e9) << " GB/s\n\n"
              << "| particles | threads | steps | particle-steps/s | P2G+G2P particle-steps/s | P2G+G2P, median step | P2G | "
                 "stress | grid | G2P | GB/s moved |\n"
              << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    const int cores = available_cores();
    for (const double count : {1e4, 1e5, 1e6}) {
        for (int threads = 1; threads <= std::min(cores, 2); ++threads) {
            const int steps = count >= 1e6 ? 10 : count >= 1e5 ? 30 : 100;
            const ExplicitRun run = run_explicit(count, threads, steps);
            all_finite = all_finite && run.finite;
            const double particle_steps = static_cast<double>(run.particles) * run.steps;
            const double transfers = run.to_grid + run.to_particles;
            auto share = [&](double part) { return table_cell("%.0f", 100.0 * part / run.seconds) + " %"; };
            std::cout << "| " << run.particles << " | " << run.threads << " | " << run.steps << " | "
                      << table_cell("%.3g", particle_steps / run.seconds) << " | "
                      << table_cell("%.3g", particle_steps / transfers) << " | "
                      << table_cell("%.3g", run.particles / run.median_transfers()) << " | " << share(run.to_grid) << " | "
                      << share(run.stress) << " | " << share(run.grid) << " | " << share(run.to_particles) << " | "
                      << table_cell("%.2f", particle_steps * kParticleBytes / run.seconds / 1e9) << " |" << std::endl;
            runs.push_back({{"kind", "explicit"},
                            {"particles", run.particles},
                            {"threads", run.threads},
                            {"steps", run.steps},
                            {"seconds", run.seconds},
                            {"p2g_s", run.to_grid},
                            {"stress_s", run.stress},
                            {"grid_s", run.grid},
                            {"g2p_s", run.to_particles},
                            {"transfer_s_per_step", run.transfer_s},
                            {"bandwidth_bytes_per_s", bandwidth}});
        }
    }
    set_threads(available_cores());
    std::cout << "\n";
}

/// The explicit CFL bound of a scene's particles at t = 0.
double initial_cfl_bound(const MpmScene& scene)
{
    return std::visit([&](const auto& setup) { return cfl_time_step(setup.particles, setup.model_pointers(), scene.dx, scene.cfl); },
                      scene.setup);
}

/// The scene in steps of Δt with the given stepping (explicit: sub-steps
/// wherever the particles' speed lowers the bound below Δt).
MpmRunOutcome run_scene_as(const Scene& scene, MpmStepping stepping, double time_step, const SolverOptions& options)
{
    SceneRunRequest request;
    request.options = options;
    SceneRunSettings settings = resolve_scene_run(scene, request).settings;
    settings.folder.clear();  // a bench writes only its table and JSON
    MpmScene mpm = *scene.mpm;
    mpm.stepping = stepping;
    mpm.substeps = true;
    std::visit([&](auto& setup) { setup.step.time_step = time_step; }, mpm.setup);
    return run_mpm(mpm, settings);
}

/// A statistic the run's solver reported (0 when it reported none).
double statistic(const Result& run, const std::string& name)
{
    const auto found = run.statistics.find(name);
    return found == run.statistics.end() ? 0.0 : found->second;
}

/// Implicit steps at ten times the explicit CFL bound, explicit at the bound.
constexpr double kImplicitStepFactor = 10.0;

bool implicit_table(const SolverOptions& options, nlohmann::json& runs)
{
    std::cout << "Implicit steps of scenes/mpm at 10 times the explicit CFL bound (the scene's solver), against "
                 "explicit steps at the bound (cfl 0.5 of the scene, sub-stepped where the particles speed up)\n\n"
              << "| scene | particles | implicit steps | iterations / step | time / step (ms) | assembly / step (ms) | "
                 "factorization / step (ms) | wall s per simulated s | explicit steps | explicit wall s per simulated s | "
                 "implicit / explicit |\n"
              << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    bool converged = true;
    for (const std::string name : {"colliding-disks", "dropped-block"}) {
        const Scene scene = read_scene_file(std::string(SINEW_MPM_SCENES_DIR) + "/" + name + ".json");
        const double bound = initial_cfl_bound(*scene.mpm);
        const MpmRunOutcome implicit =
            run_scene_as(scene, MpmStepping::implicit_steps, kImplicitStepFactor * bound, options);
        const MpmRunOutcome explicit_ = run_scene_as(scene, MpmStepping::explicit_steps, bound, options);
        converged = converged && implicit.converged && explicit_.converged;
        const double duration = implicit.frames.back().time;
        const double per_step = implicit.steps > 0 ? 1.0 / static_cast<double>(implicit.steps) : 0.0;
        const int particles = std::visit([](const auto& setup) { return setup.particles.size(); }, scene.mpm->setup);
        std::cout << "| " << name << " | " << particles << " | " << implicit.steps << " | "
                  << table_cell("%.2f", implicit.run.iterations * per_step) << " | "
                  << table_cell("%.1f", 1e3 * implicit.run.time_s * per_step) << " | "
                  << table_cell("%.1f", 1e3 * statistic(implicit.run, "assembly_s") * per_step) << " | "
                  << table_cell("%.1f", 1e3 * statistic(implicit.run, "factorization_s") * per_step) << " | "
                  << table_cell("%.3g", implicit.run.time_s / duration) << " | " << explicit_.steps << " | "
                  << table_cell("%.3g", explicit_.run.time_s / duration) << " | "
                  << table_cell("%.2f", implicit.run.time_s / explicit_.run.time_s) << " |" << std::endl;
        runs.push_back({{"kind", "implicit"},
                        {"scene", name},
                        {"cfl_time_step", bound},
                        {"steps", implicit.steps},
                        {"iterations", implicit.run.iterations},
                        {"statistics", implicit.run.statistics},
                        {"converged", implicit.converged},
                        {"seconds", implicit.run.time_s},
                        {"explicit_steps", explicit_.steps},
                        {"explicit_seconds", explicit_.run.time_s},
                        {"simulated_seconds", duration}});
    }
    return converged;
}

} // namespace

bool run_mpm_bench(const SolverOptions& options, nlohmann::json& runs)
{
    bool finite = true;
    explicit_table(runs, finite);
    return implicit_table(options, runs) && finite;
}

} // namespace sinew::cli
