#pragma once
#include "sinew/inverse/rig_fit_run.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/runs/scene_runner.hpp"
#include "sinew/runs/strategy_comparison.hpp"

#include <functional>

namespace sinew {

/// A scene to compare strategies on (an mpm scene: mpm_subject), built afresh by `make_scene` for every
/// run (a solve moves a scene's load factor and state). Each run goes
/// through the scene runner with `request` (its tolerance, iteration limit
/// and load steps; the strategy's solver and options replace its own),
/// writes nothing, and reports the positions of every node.
ComparisonSubject scene_subject(const std::function<Scene()>& make_scene, const SceneRunRequest& request = {});

/// A built-in problem: a scene through scene_subject, any other NLP solved
/// directly (its positions are x).
ComparisonSubject builtin_subject(const BuiltinProblem& problem, const SceneRunRequest& request = {});

/// A rig fit (rig_fit_run.hpp): make_nlp() is the fit with orthogonality
/// constraints, which every solver that takes equalities and bounds runs;
/// the variants are Ipopt with the Gauss-Newton Hessian
/// (ipopt_gauss_newton_options), and the seed's penalty form and the
/// rotation-vector form by projected Newton. Each run fits a fresh rig from the neutral one; its
/// positions are the landmarks at the end (m), and a note gives
/// ‖MᵀM − I‖ of both maps and the landmark RMS.
ComparisonSubject rig_subject(const std::string& name, const RigFitCase& fit_case);

} // namespace sinew
