#pragma once
#include <utility>
#include <vector>

namespace sinew {

/// The filter of a filter line search (Fletcher & Leyffer 2002; Wächter &
/// Biegler 2006, §2.3): pairs (θ, φ) of constraint violation and barrier
/// objective that a trial point must not be dominated by. Entries are stored
/// already margined: adding (θ_k, φ_k) stores ((1 − γθ)θ_k, φ_k − γφ θ_k).
class Filter {
public:
    static constexpr double kGammaTheta = 1e-5;  ///< γθ
    static constexpr double kGammaPhi = 1e-8;    ///< γφ

    /// True when (θ, φ) improves on every entry in θ or in φ (θ < θ_j or φ < φ_j).
    bool accepts(double theta, double phi) const;
    /// Stores the margined pair of an iterate the search leaves by an
    /// h-type step, dropping entries it dominates.
    void add(double theta, double phi);
    void clear() { entries_.clear(); }
    bool empty() const { return entries_.empty(); }

private:
    std::vector<std::pair<double, double>> entries_;  ///< (θ_j, φ_j), margins included
};

/// Sufficient progress of a trial over the current iterate (eq. 18):
/// θ(α) ≤ (1 − γθ)θ_k or φ(α) ≤ φ_k − γφ θ_k.
bool improves_on(double theta, double phi, double theta_k, double phi_k);

} // namespace sinew
