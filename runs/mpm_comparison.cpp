#include "sinew/runs/mpm_comparison.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mpm/grid_velocity_nlp.hpp"
#include "sinew/mpm/inextensibility/inextensibility_rows.hpp"
#include "sinew/core/format_number.hpp"
#include "sinew/runs/mpm_run.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <utility>

namespace sinew {
namespace {

/// What the first step's NLP refers to: the scene (which owns the models),
/// the particles at t = 0, their grid after P2G, the map of the implicit
/// predictor and its independent rows.
template <int Dim>
struct FirstStepState {
    std::shared_ptr<const MpmScene> scene;
    Particles<Dim> particles;
    std::vector<const ConstitutiveModel<Dim, Dim>*> models;
    SparseGrid<Dim> grid;
    ParticleBuckets<Dim> layout;
    std::optional<GridVelocityMap<Dim>> first_map;
    LinearVelocityRows first_rows;

    FirstStepState(std::shared_ptr<const MpmScene> owner, const MpmSetup<Dim>& setup)
        : scene(std::move(owner)), particles(setup.particles), models(setup.model_pointers()), grid(scene->dx)
    {
        layout = particles_to_grid(particles, setup.step.transfer, grid);
        first_map.emplace(particles, grid, setup.step, GridVelocityMap<Dim>::Predictor::momentum_and_gravity);
        first_rows = independent_rows(inextensibility_rows(particles, *first_map, scene->dx, *scene->inextensibility));
    }
};

/// The first step's constrained NLP, owning what it refers to (the state is
/// a base so that it is built first).
template <int Dim>
class FirstStepNlp final : private FirstStepState<Dim>, public GridVelocityNlp<Dim> {
public:
    FirstStepNlp(std::shared_ptr<const MpmScene> owner, const MpmSetup<Dim>& setup)
        : FirstStepState<Dim>(std::move(owner), setup),
          GridVelocityNlp<Dim>(this->particles, this->models, std::move(*this->first_map), this->layout, setup.step.time_step,
                               this->first_rows)
    {
    }
};

std::unique_ptr<Nlp> first_step_nlp(const std::shared_ptr<const MpmScene>& scene)
{
    if (scene->dimension == 2)
        return std::make_unique<FirstStepNlp<2>>(scene, std::get<MpmSetup<2>>(scene->setup));
    return std::make_unique<FirstStepNlp<3>>(scene, std::get<MpmSetup<3>>(scene->setup));
}

/// The diagonal of the particles' bounding box (m).
template <int Dim>
double particle_extent(const MpmSetup<Dim>& setup)
{
    const auto& x = setup.particles.x;
    if (x.empty())
        return 1.0;
    Eigen::Matrix<double, Dim, 1> lower = x.front(), upper = x.front();
    for (const auto& p : x) {
        lower = lower.cwiseMin(p);
        upper = upper.cwiseMax(p);
    }
    return std::max((upper - lower).norm(), 1e-12);
}

const MpmScene& compared_scene(const Scene& scene)
{
    const MpmScene& mpm = *scene.mpm;
    if (mpm.stepping != MpmStepping::implicit_steps || !mpm.inextensibility)
        throw InputError("'" + scene.name +
                         "': compare on an mpm scene needs implicit steps and \"mpm_inextensibility\" (the "
                         "constrained step is what the strategies solve)");
    return mpm;
}

} // namespace

ComparisonSubject mpm_subject(const std::function<Scene()>& make_scene)
{
    const Scene first = make_scene();
    const MpmScene& scene = compared_scene(first);
    ComparisonSubject subject;
    subject.name = first.name;
    subject.dimension = scene.dimension;
    subject.size = scene.dimension == 2 ? particle_extent(std::get<MpmSetup<2>>(scene.setup))
                                        : particle_extent(std::get<MpmSetup<3>>(scene.setup));
    subject.make_nlp = [make_scene]() {
        const Scene fresh = make_scene();
        compared_scene(fresh);
        return first_step_nlp(fresh.mpm);
    };
    subject.run = [make_scene](const ComparedStrategy& strategy, const SolverOptions& options) {
        const Scene fresh = make_scene();
        MpmScene frame = compared_scene(fresh);
        frame.duration /= frame.frames;  // the first frame only
        frame.frames = 1;
        frame.inextensibility->method =
            strategy.form == "schur-cg" ? InextensibilityMethod::schur_cg : InextensibilityMethod::nlp;
        SceneRunSettings settings;
        settings.solver = strategy.solver;
        settings.options = options;
        const MpmRunOutcome run = run_mpm(frame, settings);
        ComparisonSubject::Outcome outcome;
        outcome.result = run.run;
        const MpmFrameRow& last = run.frames.back();
        outcome.result.objective = last.total_energy;                // the mechanical energy at the frame's end (J)
        outcome.result.constraint_violation = last.constraint_violation;  // the largest ‖B v‖∞ of a step (1/s)
        outcome.result.kkt_residual = std::numeric_limits<double>::quiet_NaN();  // one per step: not one number
        outcome.positions = run.positions;
        outcome.notes.push_back(std::to_string(run.steps) + " steps, largest |B v| of a step " +
                                table_cell("%.1e", last.constraint_violation) + " 1/s, drift max |F a0|^2 - 1 = " +
                                table_cell("%.1e", last.fiber_drift_max) +
                                (last.inextensibility_cg_iterations > 0
                                     ? ", " + std::to_string(last.inextensibility_cg_iterations) + " Schur-CG iterations"
                                     : std::string()));
        return outcome;
    };
    subject.variants.push_back({"schur-cg (seed)", "projected-newton", std::nullopt, "schur-cg", {}});
    return subject;
}

} // namespace sinew
