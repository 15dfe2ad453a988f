#pragma once
#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace sinew {

/// Positions, velocities and accelerations of every coordinate (node-major,
/// DESIGN.md) at one time.
struct TimeState {
    Eigen::VectorXd x, v, a;
};

/// An implicit integrator in incremental-potential form (DESIGN.md "Time: a
/// step is an NLP"). Each step minimizes, over y, the configuration at which
/// the forces act,
///
///     ½‖y − x̃‖²_M / s + E(y)          (stationarity: M(y − x̃)/s = f(y)),
///
/// and the integrator gives four small answers: the predictor x̃, the force
/// scaling s = c·h², the velocity v(y) = v̄ + g·(y − x̃) at the force point
/// (where damping acts), and the next state from the solved y. It knows no
/// mass, potential or solver: those belong to the caller (runs/).
class TimeIntegrator {
public:
    explicit TimeIntegrator(double time_step) : h_(time_step) {}
    virtual ~TimeIntegrator() = default;

    virtual std::string name() const = 0;
    double time_step() const { return h_; }

    /// Starts from x₀, v₀ and a₀ = M⁻¹f(x₀) (a₀ is used by Newmark and by
    /// every explicit guess of the first step).
    virtual void start(const TimeState& initial) { state_ = initial; }
    /// The state at the end of the last step taken (at start: the initial one).
    const TimeState& state() const { return state_; }

    /// x̃, the configuration the inertia term pulls y towards.
    virtual Eigen::VectorXd predictor() const = 0;
    /// s = c·h²: the inertia term is ½‖y − x̃‖²_M / s.
    virtual double force_scaling() const = 0;
    /// Where in [tₙ, tₙ₊₁] the forces act, as the weight of tₙ₊₁: 1 for the
    /// end of the step, ½ for the midpoint (loads and prescribed motions are
    /// blended with the same weight).
    virtual double force_time_weight() const { return 1.0; }
    /// g = ∂v/∂y of the velocity at the force point.
    virtual double velocity_slope() const = 0;
    /// v(y), the velocity at the force point, for damping.
    virtual Eigen::VectorXd velocity_at(const Eigen::VectorXd& y) const = 0;
    /// An explicit guess of y: x̃ + s·aₙ (the step's starting point).
    Eigen::VectorXd explicit_guess() const { return predictor() + force_scaling() * state_.a; }
    /// Accepts the solved y and moves to tₙ₊₁.
    virtual void advance(const Eigen::VectorXd& y) = 0;

protected:
    double h_;
    TimeState state_;
};

/// The integrators by name: implicit-euler, bdf2, newmark (average
/// acceleration, β = ¼, γ = ½), implicit-midpoint.
const std::vector<std::string>& integrator_names();

/// A new integrator with time step h > 0. InputError for an unknown name
/// (listing the valid ones) or a step that is not finite and positive.
std::unique_ptr<TimeIntegrator> make_integrator(const std::string& name, double time_step);

} // namespace sinew
