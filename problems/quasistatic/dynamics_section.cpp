#include "sinew/problems/quasistatic/dynamics_section.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/time/time_integrator.hpp"

#include <cmath>

namespace sinew {
namespace {

/// {"linear": [..], "angular": [..] (2D: [ω]), "center": [..]}
void read_initial_velocity(const JsonCursor& v, int dimension, DynamicsSettings& out)
{
    v.expect_object({"linear", "angular", "center"});
    constexpr double kMaxSpeed = 1e8;  // m/s, rad/s: anything beyond is a typo
    if (auto linear = v.find("linear"))
        out.linear_velocity = linear->vector_in(dimension, -kMaxSpeed, kMaxSpeed);
    if (auto angular = v.find("angular"))
        out.angular_velocity = angular->vector_in(dimension == 3 ? 3 : 1, -kMaxSpeed, kMaxSpeed);
    if (auto center = v.find("center"))
        out.center = center->vector(dimension);
}

/// A finite number > 0.
double positive(const JsonCursor& v)
{
    const double value = v.number();
    if (!(value > 0.0))
        v.fail("must be > 0, got " + format_number(value));
    return value;
}

/// [[t0, s0], [t1, s1], ...] with t increasing.
KeyframeCurve read_curve(const JsonCursor& list)
{
    if (list.size() == 0)
        list.fail("expected at least one keyframe [time, value]");
    std::vector<KeyframeCurve::Keyframe> keys;
    for (size_t k = 0; k < list.size(); ++k) {
        const Eigen::VectorXd pair = list[k].vector(2);
        if (k > 0 && !(pair[0] > keys.back().time))
            list[k].fail("time " + format_number(pair[0]) + " is not after the previous keyframe's " +
                         format_number(keys.back().time) + " (keyframes must be in increasing time)");
        keys.push_back({pair[0], pair[1]});
    }
    return KeyframeCurve(std::move(keys));
}

} // namespace

DynamicsSettings read_dynamics(const JsonCursor& d, int dimension)
{
    d.expect_object({"integrator", "time_step", "duration", "initial_velocity", "damping", "load_curve"});
    DynamicsSettings out;
    out.linear_velocity = out.center = Eigen::VectorXd::Zero(dimension);
    out.angular_velocity = Eigen::VectorXd::Zero(dimension == 3 ? 3 : 1);
    if (auto v = d.find("integrator")) {
        out.integrator = v->string();
        try {
            make_integrator(out.integrator, 1.0);
        } catch (const InputError& e) {
            v->fail(e.what());
        }
    }
    out.time_step = positive(d.at("time_step"));
    out.duration = positive(d.at("duration"));
    const double steps = std::ceil(out.duration / out.time_step * (1.0 - 1e-12));
    if (steps > kMaxTimeSteps)
        d.at("duration").fail("asks for " + format_number(steps) + " steps of time_step; at most 1e7");
    if (auto v = d.find("initial_velocity"))
        read_initial_velocity(*v, dimension, out);
    if (auto damping = d.find("damping")) {
        damping->expect_object({"mass", "stiffness"});
        if (auto v = damping->find("mass"))
            out.mass_damping = v->number_in(0.0, 1e12);
        if (auto v = damping->find("stiffness"))
            out.stiffness_damping = v->number_in(0.0, 1e12);
    }
    if (auto curve = d.find("load_curve"))
        out.load_factor = read_curve(*curve);
    return out;
}

} // namespace sinew
