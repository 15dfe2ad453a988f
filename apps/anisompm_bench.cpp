#include "anisompm_bench.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/mpm_run.hpp"
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
    std::cout << "Scenes of scenes/anisompm as their files say (explicit MPM steps, sub-stepped below the CFL bound; "
                 "the file name says the damage update)\n\n"
              << "| scene | particles | frames | steps | s / frame | transfer | damage | momentum | damage CG "
                 "iterations / step | capped at 1 | decrease refused | mean d | max d |\n"
              << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    bool converged = true;
    for (const std::string& file : scene_files()) {
        const Scene scene = read_scene_file(file);
        SceneRunSettings settings;
        settings.options = options;
        const MpmRunOutcome outcome = run_mpm(*scene.mpm, settings);
        converged = converged && outcome.converged;
        const int particles = std::visit([](const auto& setup) { return setup.particles.size(); }, scene.mpm->setup);
        const double frames = static_cast<double>(outcome.frames.size() - 1);
        const double steps = std::max(1.0, static_cast<double>(outcome.steps));
        const double updates = steps * particles;  // particle updates of d
        const double transfer = summed(outcome, &MpmFrameRow::transfer_s);
        const double damage = summed(outcome, &MpmFrameRow::damage_s);
        const double momentum = summed(outcome, &MpmFrameRow::momentum_s);
        const double iterations = summed(outcome, &MpmFrameRow::damage_cg_iterations);
        const double capped = summed(outcome, &MpmFrameRow::damage_capped);
        const double refused = summed(outcome, &MpmFrameRow::damage_decrease_refused);
        const MpmFrameRow& last = outcome.frames.back();
        const std::string name = std::filesystem::path(file).stem().string();
        std::cout << "| " << name << (outcome.converged ? "" : " (" + outcome.stopped + ")") << " | " << particles
                  << " | " << frames << " | " << outcome.steps << " | " << table_cell("%.2f", outcome.run.time_s / frames)
                  << " | " << table_cell("%.0f", 100.0 * transfer / outcome.run.time_s) << " %" << " | "
                  << table_cell("%.0f", 100.0 * damage / outcome.run.time_s) << " %" << " | "
                  << table_cell("%.0f", 100.0 * momentum / outcome.run.time_s) << " %" << " | "
                  << table_cell("%.1f", iterations / steps) << " | " << table_cell("%.2g", capped / updates) << " | "
                  << table_cell("%.2g", refused / updates) << " | " << table_cell("%.3f", last.mean_damage) << " | "
                  << table_cell("%.3f", last.max_damage) << " |" << std::endl;
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
                        {"damage_cg_iterations", iterations},
                        {"damage_capped", capped},
                        {"damage_decrease_refused", refused},
                        {"mean_damage", last.mean_damage},
                        {"max_damage", last.max_damage}});
    }
    std::cout << "\nShares are of the run's wall time; the rest is the CFL bound each step re-evaluates (a model "
                 "call per particle), the colliders' placement and the frames' measurements. capped at 1 and decrease "
                 "refused: the fraction of particle updates of d where min(1, ·) and (implicit) max(d_p, ·) acted.\n";
    return converged;
}

} // namespace sinew::cli
