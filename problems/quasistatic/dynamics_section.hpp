#pragma once
#include "sinew/problems/quasistatic/strict_json.hpp"
#include "sinew/time/dynamics_settings.hpp"

namespace sinew {

/// Reads a scene's "dynamics" object (docs/scenes.md, "Dynamics") for a mesh
/// of `dimension` 2 or 3. InputError with the JSON path for an unknown key or
/// integrator, a time step or duration that is not finite and > 0, more than
/// 1e7 steps, negative damping, a velocity of the wrong size, keyframes out
/// of order or not finite.
DynamicsSettings read_dynamics(const JsonCursor& d, int dimension);

} // namespace sinew
