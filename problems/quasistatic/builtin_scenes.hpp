#pragma once
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/quasistatic/scene.hpp"

#include <string>
#include <vector>

namespace sinew {

/// The built-in scene `name`: scenes/<name>.json through the scene reader
/// (docs/scenes.md). InputError naming the valid names for an unknown one.
Scene make_builtin_scene(const std::string& name);

/// The built-in scenes as bench problems: the cantilevers of about 6k tets
/// (straight and twisted), the muscle spindle, the QR plate and the
/// membrane sheet in suite `quasistatic`; the 52k and 206k cantilevers in
/// `quasistatic-large`; the inextensibility scenes; the scenes stepped in
/// time (scenes/dynamics/) in `dynamics`, whose NLP is their time step. No
/// published optimum: a run counts when it converges.
std::vector<BuiltinProblem> quasistatic_scenes();

} // namespace sinew
