#pragma once
#include <deque>
#include <functional>
#include <string>

namespace sinew {

/// What the barrier parameter update reads at an iterate.
struct BarrierMeasures {
    /// E_μ: the optimality error of the barrier problem at a given μ (Wächter
    /// & Biegler 2006, eq. 7), as a function since it depends on μ.
    std::function<double(double mu)> barrier_error;
    double optimality_error = 0.0;         ///< E_0, the error of the original problem
    double average_complementarity = 0.0;  ///< (w − w_L)ᵀz_L + (w_U − w)ᵀz_U over the number of finite bounds
    double smallest_complementarity = 0.0;  ///< the smallest such product
};

/// The barrier parameter μ and its update, one of two rules (both Ipopt's):
///
/// monotone (Fiacco–McCormick; Wächter & Biegler 2006, eq. 7): once the
///   barrier problem is solved, E_μ ≤ κ_ε μ, μ ← max(μ_min, min(κ_μ μ, μ^θ_μ))
///   with κ_ε = 10, κ_μ = 0.2, θ_μ = 1.5, repeated while it holds;
/// adaptive (Nocedal, Wächter & Waltz 2009, "Adaptive barrier update
///   strategies for nonlinear interior methods", SIAM J. Optim. 19): every
///   iteration μ = σ · (average complementarity) by the LOQO rule
///   σ = 0.1 min(0.05 (1 − ξ)/ξ, 2)³, ξ = smallest/average product, while
///   E_0 keeps falling (each accepted E_0 ≤ 0.9999 × the largest of the last
///   four that did); when it does not, the monotone rule takes over from
///   μ = 0.8 × (average complementarity) until its barrier problem is solved
///   with E_0 falling again (Ipopt's kkt-error globalization).
class BarrierParameter {
public:
    enum class Rule { monotone, adaptive };

    BarrierParameter(Rule rule, double initial, double smallest);

    double mu() const { return mu_; }
    /// τ = max(0.99, 1 − μ), the fraction-to-the-boundary parameter (eq. 8).
    double fraction_to_boundary() const;
    /// Updates μ at a new iterate; true when μ changed (the filter, defined
    /// for one barrier problem, must then be reset).
    bool update(const BarrierMeasures& measures);
    /// The monotone decrease once, whatever the error (after a step below round-off).
    void force_decrease();
    /// μ at its floor with the barrier problem solved: nothing more to decrease.
    bool at_floor() const { return mu_ <= smallest_; }
    /// "monotone" or "adaptive (free)" / "adaptive (monotone)" for messages.
    std::string mode() const;

private:
    bool monotone_decrease(const BarrierMeasures& measures);
    bool sufficient_progress(double error) const;
    void remember(double error);

    Rule rule_;
    double mu_;
    double smallest_;
    bool free_mode_ = true;      ///< adaptive rule: LOQO (true) or its monotone safeguard
    std::deque<double> references_;  ///< the last accepted values of E_0 (adaptive rule)
};

} // namespace sinew
