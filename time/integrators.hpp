#pragma once
// The four integrators of make_integrator (time_integrator.hpp). Each is the
// incremental-potential form of its textbook scheme; the comments derive x̃,
// s and v(y) from the scheme's update equations, with a = M⁻¹f(y).
#include "sinew/time/time_integrator.hpp"

namespace sinew {

/// xₙ₊₁ = xₙ + h vₙ₊₁, vₙ₊₁ = vₙ + h aₙ₊₁: first order, dissipative.
class ImplicitEuler final : public TimeIntegrator {
public:
    using TimeIntegrator::TimeIntegrator;
    std::string name() const override { return "implicit-euler"; }
    Eigen::VectorXd predictor() const override;
    double force_scaling() const override { return h_ * h_; }
    double velocity_slope() const override { return 1.0 / h_; }
    Eigen::VectorXd velocity_at(const Eigen::VectorXd& y) const override;
    void advance(const Eigen::VectorXd& y) override;
};

/// xₙ₊₁ = 4/3 xₙ − 1/3 xₙ₋₁ + 2/3 h vₙ₊₁, vₙ₊₁ = 4/3 vₙ − 1/3 vₙ₋₁ + 2/3 h aₙ₊₁:
/// second order, two states kept; its first step is an implicit Euler step.
class Bdf2 final : public TimeIntegrator {
public:
    using TimeIntegrator::TimeIntegrator;
    std::string name() const override { return "bdf2"; }
    void start(const TimeState& initial) override;
    Eigen::VectorXd predictor() const override;
    double force_scaling() const override;
    double velocity_slope() const override;
    Eigen::VectorXd velocity_at(const Eigen::VectorXd& y) const override;
    void advance(const Eigen::VectorXd& y) override;

private:
    bool has_previous_ = false;
    TimeState previous_;  ///< tₙ₋₁
};

/// Newmark with β = ¼, γ = ½ (average acceleration, the trapezoidal rule):
/// xₙ₊₁ = xₙ + h vₙ + h²(aₙ + aₙ₊₁)/4, vₙ₊₁ = vₙ + h(aₙ + aₙ₊₁)/2. Second order,
/// conserves the energy of a linear system.
class Newmark final : public TimeIntegrator {
public:
    using TimeIntegrator::TimeIntegrator;
    std::string name() const override { return "newmark"; }
    Eigen::VectorXd predictor() const override;
    double force_scaling() const override { return kBeta * h_ * h_; }
    double velocity_slope() const override { return kGamma / (kBeta * h_); }
    Eigen::VectorXd velocity_at(const Eigen::VectorXd& y) const override;
    void advance(const Eigen::VectorXd& y) override;

private:
    static constexpr double kBeta = 0.25;
    static constexpr double kGamma = 0.5;
};

/// xₙ₊₁ = xₙ + h(vₙ + vₙ₊₁)/2, vₙ₊₁ = vₙ + h a(xₙ₊½): the unknown y is the
/// midpoint xₙ₊½ = (xₙ + xₙ₊₁)/2, and forces act at tₙ₊½. Second order,
/// symplectic, conserves every quadratic invariant (angular momentum, the
/// energy of a linear system).
class ImplicitMidpoint final : public TimeIntegrator {
public:
    using TimeIntegrator::TimeIntegrator;
    std::string name() const override { return "implicit-midpoint"; }
    Eigen::VectorXd predictor() const override;
    double force_scaling() const override { return 0.25 * h_ * h_; }
    double force_time_weight() const override { return 0.5; }
    double velocity_slope() const override { return 2.0 / h_; }
    Eigen::VectorXd velocity_at(const Eigen::VectorXd& y) const override;
    void advance(const Eigen::VectorXd& y) override;
};

} // namespace sinew
