#pragma once
// `sinew compare` on an mpm scene: the strategies on the grid inextensibility.
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/runs/strategy_comparison.hpp"

#include <functional>

namespace sinew {

/// An implicit mpm scene with "mpm_inextensibility" (InputError otherwise):
/// every strategy runs the scene's first frame (its steps) with the cells'
/// rows as equality constraints of each step's grid-velocity NLP (method
/// nlp, whatever the scene says), and the variant "schur-cg (seed)" runs it
/// with the unconstrained step by projected Newton followed by the seed's
/// Schur-CG projection (Alg. 11). make_nlp() is the first step's constrained
/// NLP; positions are the particles' positions at the end of the frame (m);
/// notes give the largest ‖B v‖ of a step and the drift of |F a₀|² − 1.
ComparisonSubject mpm_subject(const std::function<Scene()>& make_scene);

} // namespace sinew
