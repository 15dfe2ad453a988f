#include "sinew/runs/comparison_subjects.hpp"

#include "sinew/mesh/mesh.hpp"
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/problems/quasistatic/constraint_ranks.hpp"
#include "sinew/runs/scene_runner.hpp"
#include "sinew/solvers/solver.hpp"

namespace sinew {

ComparisonSubject scene_subject(const std::function<Scene()>& make_scene, const SceneRunRequest& request)
{
    const Scene first = make_scene();
    ComparisonSubject subject;
    subject.name = first.name;
    subject.size = first.size;
    subject.dimension = space_dimension(first.mesh.kind);
    subject.make_nlp = [make_scene]() -> std::unique_ptr<Nlp> { return std::move(make_scene().problem); };
    subject.run = [make_scene, request](const std::string& solver, const SolverOptions& options) {
        Scene scene = make_scene();
        SceneRunRequest run_request = request;
        run_request.solver = solver;
        run_request.options = options;
        ResolvedSceneRun resolved = resolve_scene_run(scene, run_request);
        resolved.settings.folder.clear();  // a comparison writes its own files, not each run's
        ComparisonSubject::Outcome outcome;
        outcome.notes = resolved.notes;
        for (const ConstraintSetRank& rank : constraint_ranks(scene))
            outcome.constraint_ranks.push_back(describe(rank));
        outcome.result = run_scene(scene, resolved.settings).last;
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
    subject.run = [make = problem.make](const std::string& solver, const SolverOptions& options) {
        const std::unique_ptr<Nlp> nlp = make();
        ComparisonSubject::Outcome outcome;
        outcome.result = solve(*nlp, solver, options);
        outcome.positions = outcome.result.x;
        return outcome;
    };
    return subject;
}

} // namespace sinew
