#pragma once
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/runs/scene_runner.hpp"
#include "sinew/runs/strategy_comparison.hpp"

#include <functional>

namespace sinew {

/// A scene to compare strategies on, built afresh by `make_scene` for every
/// run (a solve moves a scene's load factor and state). Each run goes
/// through the scene runner with `request` (its tolerance, iteration limit
/// and load steps; the strategy's solver and options replace its own),
/// writes nothing, and reports the positions of every node.
ComparisonSubject scene_subject(const std::function<Scene()>& make_scene, const SceneRunRequest& request = {});

/// A built-in problem: a scene through scene_subject, any other NLP solved
/// directly (its positions are x).
ComparisonSubject builtin_subject(const BuiltinProblem& problem, const SceneRunRequest& request = {});

} // namespace sinew
