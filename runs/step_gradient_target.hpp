#pragma once
// What a run that solves one NLP per step (a time step, an implicit MPM
// step) sets in each step's solver options.
#include "sinew/runs/scene_runner.hpp"

#include <algorithm>
#include <limits>
#include <string>

namespace sinew {

/// The stopping target of one step of a run (a time step, an implicit MPM
/// step) for a solver that takes an absolute `gradient_target`: tol times
/// the step's force scale, and never below the gradient's round-off,
/// 16ε·‖x̃‖∞·max Hᵢᵢ (x̃ the step's predictor, H its Hessian; the floors seen
/// on the test scenes lie between 1 and 20 times ε‖x̃‖∞·max Hᵢᵢ), where
/// Newton can only stall. A target relative to the gradient at the start
/// fails a step that starts at its solution up to round-off (a body in free
/// fall), whose gradient is round-off itself.
inline double step_gradient_target(double tolerance, double force_scale, double predictor_norm,
                                   double hessian_diagonal)
{
    const double roundoff = 16.0 * std::numeric_limits<double>::epsilon() * predictor_norm * hessian_diagonal;
    return std::max(tolerance * force_scale, roundoff);
}

/// Whether the run sets backend option `name` of its solver on every step:
/// the solver declares it and the caller did not set it.
bool step_sets(const SceneRunSettings& settings, const std::string& name);

} // namespace sinew
