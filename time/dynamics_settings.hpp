#pragma once
#include "sinew/time/keyframe_curve.hpp"

#include <Eigen/Core>

#include <string>

namespace sinew {

/// A scene's "dynamics" object (docs/scenes.md, "Dynamics"): how its time
/// stepping runs. Plain data, read by the scene reader, used by runs/.
struct DynamicsSettings {
    std::string integrator = "implicit-euler";
    double time_step = 0.0;  ///< h, s
    double duration = 0.0;   ///< T, s: ⌈T/h⌉ steps of h
    /// v₀(X) = linear + angular × (X − center) on every node (2D: angular is
    /// the one rate ω about the out-of-plane axis).
    Eigen::VectorXd linear_velocity;
    Eigen::VectorXd angular_velocity;
    Eigen::VectorXd center;
    double mass_damping = 0.0;       ///< Rayleigh α, 1/s: D = αM + βK
    double stiffness_damping = 0.0;  ///< Rayleigh β, s
    /// The load factor s(t) that scales gravity, loads, prescribed motions
    /// and activations as a load step does (Scene::apply_load_factor);
    /// constant 1 when not given.
    KeyframeCurve load_factor;

    /// N = ⌈T/h⌉ (at least 1): the run ends at N·h ≥ T.
    long long num_steps() const;
};

/// The most steps a scene may ask for (duration / time_step).
constexpr double kMaxTimeSteps = 1e7;

} // namespace sinew
