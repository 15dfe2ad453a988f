#pragma once
// Scenes stepped in time for the tests: built from JSON text, run through
// the one time-stepping runner, every state kept.
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/time_stepping.hpp"

#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace sinew::test {

/// A run's states, step 0 (t = 0) first, with its rows.
struct Trajectory {
    std::vector<TimeState> states;
    TimeSteppingOutcome outcome;
};

/// Runs `scene` with projected Newton at a relative gradient tolerance of
/// `tolerance` (tight: the checks below measure the integrator, not the
/// solver), writing nothing.
inline Trajectory run_dynamic_scene(Scene& scene, double tolerance = 1e-10,
                                    const std::string& solver = "projected-newton")
{
    SceneRunSettings settings;
    settings.solver = solver;
    settings.options.tolerance = tolerance;
    Trajectory trajectory;
    TimeSteppingObserver observer;
    observer.on_step = [&](const TimeStepRow&, const TimeState& state) { trajectory.states.push_back(state); };
    trajectory.outcome = run_time_stepping(scene, settings, observer);
    return trajectory;
}

/// x written with every digit, for JSON text.
inline std::string exact(double x)
{
    std::ostringstream out;
    out << std::setprecision(17) << x;
    return out.str();
}

/// The "dynamics" object of a scene.
inline std::string dynamics_json(const std::string& integrator, double time_step, double duration,
                                 const std::string& extra = "")
{
    return "\"dynamics\": {\"integrator\": \"" + integrator + "\", \"time_step\": " + exact(time_step) +
           ", \"duration\": " + exact(duration) + extra + "}";
}

inline const std::vector<std::string>& all_integrators()
{
    static const std::vector<std::string> names{"implicit-euler", "bdf2", "newmark", "implicit-midpoint"};
    return names;
}

} // namespace sinew::test
