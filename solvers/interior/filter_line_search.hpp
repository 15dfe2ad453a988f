#pragma once
#include "sinew/solvers/interior/filter.hpp"

#include <functional>
#include <optional>

namespace sinew {

/// A trial point's measures: θ = ‖r‖₁ (constraint violation) and φ_μ (the
/// barrier objective); φ = +∞ where f is undefined.
struct TrialMeasures {
    double theta = 0.0;
    double phi = 0.0;
};

enum class FilterStepKind {
    f_type,        ///< Armijo on φ under the switching condition: the filter is kept
    h_type,        ///< sufficient decrease of θ or φ: the iterate joins the filter
    restoration,   ///< α fell below α_min: the feasibility restoration phase must run
    no_decrease,   ///< α fell below α_min at a feasible point (θ = 0): no restoration can help
};

struct FilterStep {
    FilterStepKind kind = FilterStepKind::no_decrease;
    double alpha = 0.0;
    int backtracks = 0;
    bool second_order_correction = false;  ///< the accepted point came from a correction step
};

/// The filter line search of Wächter & Biegler 2006 (§2.3–2.4), with Ipopt's
/// constants: backtracking from α_max (fraction to the boundary) by halving;
/// a trial is acceptable when the filter and the current iterate accept it
/// (sufficient decrease of θ or φ, eq. 18) or, under the switching condition
/// α(−∇φᵀd)^{s_φ} > δ θ_k^{s_θ} at θ_k ≤ θ_min, when φ satisfies Armijo
/// (eq. 20); θ above θ_max is never acceptable. A first trial rejected with
/// θ grown is followed by up to four second-order corrections (§2.4).
class FilterLineSearch {
public:
    /// θ_max = 1e4 max(1, θ₀) and θ_min = 1e-4 max(1, θ₀) from the first iterate's θ₀.
    explicit FilterLineSearch(double theta0);

    Filter& filter() { return filter_; }

    /// `trial(α)` evaluates w + α d (the caller keeps the point); `correction(α, k)`
    /// evaluates the k-th second-order correction from the first trial
    /// (empty: no correction possible). The accepted point is the last one
    /// evaluated; h-type steps add the current iterate to the filter.
    FilterStep search(const TrialMeasures& current, double slope, double alpha_max,
                      const std::function<TrialMeasures(double alpha)>& trial,
                      const std::function<std::optional<TrialMeasures>(int k)>& correction);

private:
    /// f_type or h_type when acceptable at α, nothing otherwise.
    std::optional<FilterStepKind> judge(const TrialMeasures& current, const TrialMeasures& point, double slope,
                                        double alpha) const;
    double smallest_alpha(const TrialMeasures& current, double slope) const;
    bool switching(double theta_k, double slope, double alpha) const;

    Filter filter_;
    double theta_max_, theta_min_;
};

} // namespace sinew
