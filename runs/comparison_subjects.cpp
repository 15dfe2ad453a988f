#include "sinew/runs/comparison_subjects.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/mesh/mesh.hpp"
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/problems/quasistatic/constraint_ranks.hpp"
#include "sinew/runs/mpm_comparison.hpp"
#include "sinew/runs/scene_runner.hpp"
#include "sinew/solvers/solver.hpp"

namespace sinew {

ComparisonSubject scene_subject(const std::function<Scene()>& make_scene, const SceneRunRequest& request)
{
    const Scene first = make_scene();
    if (first.mpm)
        return mpm_subject(make_scene);
    ComparisonSubject subject;
    subject.name = first.name;
    subject.size = first.size;
    subject.dimension = space_dimension(first.mesh.kind);
    subject.make_nlp = [make_scene]() -> std::unique_ptr<Nlp> { return std::move(make_scene().problem); };
    subject.run = [make_scene, request](const ComparedStrategy& strategy, const SolverOptions& options) {
        Scene scene = make_scene();
        SceneRunRequest run_request = request;
        run_request.solver = strategy.solver;
        run_request.options = options;
        ResolvedSceneRun resolved = resolve_scene_run(scene, run_request);
        resolved.settings.folder.clear();  // a comparison writes its own files, not each run's
        ComparisonSubject::Outcome outcome;
        outcome.notes = resolved.notes;
        for (const ConstraintSetRank& rank : constraint_ranks(scene))
            outcome.constraint_ranks.push_back(describe(rank));
        const SceneRunOutcome run = run_scene(scene, resolved.settings);
        outcome.result = run.last;
        outcome.contact = run.contact;
        outcome.positions = scene.problem->full_configuration(outcome.result.x);
        return outcome;
    };
    return subject;
}

ComparisonSubject builtin_subject(const BuiltinProblem& problem, const SceneRunRequest& request)
{
    if (!problem.scene.empty()) {
        const std::string name = problem.scene;
        return scene_subject([name] { return make_builtin_scene(name); }, request);
    }
    ComparisonSubject subject;
    subject.name = problem.name;
    subject.make_nlp = problem.make;
    subject.run = [make = problem.make](const ComparedStrategy& strategy, const SolverOptions& options) {
        const std::unique_ptr<Nlp> nlp = make();
        ComparisonSubject::Outcome outcome;
        outcome.result = solve(*nlp, strategy.solver, options);
        outcome.positions = outcome.result.x;
        return outcome;
    };
    return subject;
}

ComparisonSubject rig_subject(const std::string& name, const RigFitCase& fit_case)
{
    ComparisonSubject subject;
    subject.name = name;
    subject.size = MuscleRig(fit_case.definition, fit_case.inner).size();
    subject.dimension = 3;
    subject.make_nlp = [fit_case]() -> std::unique_ptr<Nlp> {
        return std::make_unique<RigFitProblem>(std::make_shared<MuscleRig>(fit_case.definition, fit_case.inner),
                                               fit_case.targets.targets, RigFitSettings{});
    };
    subject.run = [fit_case](const ComparedStrategy& strategy, const SolverOptions& options) {
        const OrthogonalityForm form =
            strategy.form.empty() ? OrthogonalityForm::constraints : orthogonality_form(strategy.form);
        const RigFitOutcome fit = run_rig_fit(fit_case.definition, fit_case.inner, fit_case.targets,
                                              {strategy.label, strategy.solver, form, options}, {});
        ComparisonSubject::Outcome outcome;
        outcome.result = fit.result;
        outcome.positions = fit.landmarks;
        outcome.notes.push_back("|Mc^T Mc - I| = " + table_cell("%.1e", fit.cranium_violation) +
                                ", |Mj^T Mj - I| = " + table_cell("%.1e", fit.jaw_violation) +
                                ", landmark RMS " + table_cell("%.3g", 1e3 * fit.rms) + " mm");
        return outcome;
    };
    // Ipopt on make_nlp() runs its limited-memory mode (the Hessian is Gauss-Newton's, not exact).
    subject.variants.push_back({"ipopt (Gauss-Newton)", "ipopt", std::nullopt,
                                to_string(OrthogonalityForm::constraints), ipopt_gauss_newton_options()});
    subject.variants.push_back(
        {"penalty (seed)", "projected-newton", std::nullopt, to_string(OrthogonalityForm::penalty), {}});
    subject.variants.push_back(
        {"rotation vectors", "projected-newton", std::nullopt, to_string(OrthogonalityForm::rotation_vectors), {}});
    return subject;
}

} // namespace sinew
