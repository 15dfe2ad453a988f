#pragma once

namespace sinew {

/// Forcing terms η_k for inexact Newton, the step d_k solving H d = −g_k to
/// ‖H d + g_k‖ ≤ η_k ‖g_k‖: Eisenstat and Walker's choice 2 ("Choosing the
/// forcing terms in an inexact Newton method", SIAM J. Sci. Comput. 17,
/// 1996), bounded by the relative gradient ‖g_k‖/‖g₀‖:
///   η₀ = η_max,
///   η_k = γ (‖g_k‖ / ‖g_{k−1}‖)^α                  with γ = 0.9, α = 2,
///   η_k ← max(η_k, γ η_{k−1}^α)   when γ η_{k−1}^α > 0.1 (no sudden drop),
///   η_k ← min(η_k, η_max, ‖g_k‖ / ‖g₀‖)            with η_max = 0.5.
/// Loose early, so the first steps cost few inner iterations. The last bound,
/// η_k = O(‖g_k‖), keeps the convergence q-quadratic (Dembo, Eisenstat &
/// Steihaug, "Inexact Newton methods", SIAM J. Numer. Anal. 19, 1982, Cor.
/// 3.5), so the last step overshoots the stopping test as far as an exact
/// Newton step would and the solution is as accurate as exact Newton's.
class ForcingTerm {
public:
    /// η for the step from a point whose gradient norm is `gradient_norm`;
    /// call once per Newton iteration, the first call at the starting point.
    double next(double gradient_norm);

    static constexpr double gamma = 0.9;
    static constexpr double alpha = 2.0;
    static constexpr double eta_max = 0.5;

private:
    double initial_norm_ = -1.0;   ///< ‖g₀‖; negative before the first call
    double previous_norm_ = -1.0;  ///< ‖g_{k−1}‖
    double previous_eta_ = eta_max;
};

} // namespace sinew
