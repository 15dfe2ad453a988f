#include "anisompm_bench.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/mpm_run.hpp"
#include "sinew/runs/scene_runner.hpp"
#include "sinew/runs/scene_run_settings.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <variant>
#include <vector>

namespace sinew::cli {
namespace {

/// The scene files of scenes/anisompm, by name.
std::vector<std::string> scene_files()
{
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(SINEW_ANISOMPM_SCENES_DIR))
        if (entry.path().extension() == ".json")
            files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

/// The frames' sums of one row field.
template <typename Field>
double summed(const MpmRunOutcome& outcome, Field field)
{
    double sum = 0.0;
    for (const MpmFrameRow& row : outcome.frames)
        sum += static_cast<double>(row.*field);
    return sum;
}

} // namespace

bool run_anisompm_bench(const SolverOptions& options, nlohmann::json& runs)
{
    std::cout << "Scenes of scenes/anisompm as their files say (the file name says the damage update or the "
                 "stepping; explicit steps sub-stepped below the CFL bound)\n\n"
              << "| scene | particles | frames | steps | s / frame | transfer | damage | inextensibility | momentum | "
                 "damage CG iterations / step | capped at 1 | decrease refused | mean d | max d | Schur-CG "
                 "iterations / step | max \\|B v\\| (1/s) | drift max |\n"
              << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    bool converged = true;
    for (const std::string& file : scene_files()) {
        Scene scene = read_scene_file(file);
        SceneRunRequest request;
        request.options = options;
        ResolvedSceneRun resolved = resolve_scene_run(scene, request);  // the scene's solver (implicit steps)
        resolved.settings.folder.clear();
        const MpmRunOutcome outcome = run_mpm(*scene.mpm, resolved.settings);
        converged = converged && outcome.converged;
        const int particles = std::visit([](const auto& setup) { return setup.particles.size(); }, scene.mpm->setup);
        const double frames = static_cast<double>(outcome.frames.size() - 1);
        const double steps = std::max(1.0, static_cast<double>(outcome.steps));
        const double updates = steps * particles;  // particle updates of d
        const double transfer = summed(outcome, &MpmFrameRow::transfer_s);
        const double damage = summed(outcome, &MpmFrameRow::damage_s);
        const double momentum = summed(outcome, &MpmFrameRow::momentum_s);
        const double inextensibility = summed(outcome, &MpmFrameRow::inextensibility_s);
        const double schur_iterations = summed(outcome, &MpmFrameRow::inextensibility_cg_iterations);
        double violation = 0.0;
        for (const MpmFrameRow& row : outcome.frames)
            violation = std::max(violation, row.constraint_violation);
        const double iterations = summed(outcome, &MpmFrameRow::damage_cg_iterations);
        const double capped = summed(outcome, &MpmFrameRow::damage_capped);
        const double refused = summed(outcome, &MpmFrameRow::damage_decrease_refused);
        const MpmFrameRow& last = outcome.frames.back();
        const std::string name = std::filesystem::path(file).stem().string();
        std::cout << "| " << name << (outcome.converged ? "" : " (" + outcome.stopped + ")") << " | " << particles
                  << " | " << frames << " | " << outcome.steps << " | " << table_cell("%.2f", outcome.run.time_s / frames)
                  << " | " << table_cell("%.0f", 100.0 * transfer / outcome.run.time_s) << " %" << " | "
                  << table_cell("%.0f", 100.0 * damage / outcome.run.time_s) << " %" << " | "
                  << table_cell("%.0f", 100.0 * inextensibility / outcome.run.time_s) << " %" << " | "
                  << table_cell("%.0f", 100.0 * momentum / outcome.run.time_s) << " %" << " | "
                  << table_cell("%.1f", iterations / steps) << " | " << table_cell("%.2g", capped / updates) << " | "
                  << table_cell("%.2g", refused / updates) << " | " << table_cell("%.3f", last.mean_damage) << " | "
                  << table_cell("%.3f", last.max_damage) << " | " << table_cell("%.0f", schur_iterations / steps) << " | "
                  << table_cell("%.1e", violation) << " | " << table_cell("%.1e", last.fiber_drift_max) << " |"
                  << std::endl;
        runs.push_back({{"scene", name},
                        {"particles", particles},
                        {"frames", frames},
                        {"steps", outcome.steps},
                        {"converged", outcome.converged},
                        {"stopped", outcome.stopped},
                        {"seconds", outcome.run.time_s},
                        {"transfer_s", transfer},
                        {"damage_s", damage},
                        {"momentum_s", momentum},
                        {"inextensibility_s", inextensibility},
                        {"schur_cg_iterations", schur_iterations},
                        {"constraint_violation", violation},
                        {"fiber_drift_max", last.fiber_drift_max},
                        {"damage_cg_iterations", iterations},
                        {"damage_capped", capped},
                        {"damage_decrease_refused", refused},
                        {"mean_damage", last.mean_damage},
                        {"max_damage", last.max_damage}});
    }
    std::cout << "\nShares are of the run's wall time; the rest is the CFL bound each step re-evaluates (a model "
                 "call per particle), the colliders' placement and the frames' measurements; an implicit step's "
                 "solve is momentum (its constrained NLP too). capped at 1 and decrease refused: the fraction of "
                 "particle updates of d where min(1, ·) and (implicit) max(d_p, ·) acted. max |B v|: the largest "
                 "inextensibility residual of a step; drift max: max |F a0|^2 - 1 at the end.\n";
    return converged;
}

} // namespace sinew::cli
