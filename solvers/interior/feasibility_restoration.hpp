#pragma once
#include "sinew/solvers/interior/barrier_bounds.hpp"
#include "sinew/solvers/interior/slack_formulation.hpp"
#include "sinew/solvers/newton/kkt_matrix.hpp"
#include "sinew/solvers/newton/newton_recorder.hpp"
#include "sinew/solvers/newton/regularized_factorization.hpp"

#include <functional>
#include <string>

namespace sinew {

enum class RestorationOutcome {
    returned,    ///< a point the filter accepts, with θ reduced: the main iteration goes on from it
    infeasible,  ///< a stationary point of the constraint violation with θ > 0: locally infeasible
    failed,      ///< no further progress, and no certificate of infeasibility
};

struct RestorationResult {
    RestorationOutcome outcome = RestorationOutcome::failed;
    int iterations = 0;
    double stationarity = 0.0;  ///< ‖w − P(w − J̃ᵀr)‖∞ / (‖r‖∞ max(1, |J̃|max)) at the end
    std::string message;
};

/// The feasibility restoration phase (Wächter & Biegler 2006, §3.3): entered
/// when the filter line search finds no acceptable step, it decreases the
/// constraint violation alone until the filter accepts a point again. Ours
/// is Newton's method on
///
///     ψ(w) = ½‖r(w)‖² + ζ/2 ‖D_R (w − w_R)‖² − μ_R Σ ln(bound distances),
///
/// ζ = √μ, D_R = diag(min(1, 1/|w_R|)), w_R the previous iterate (a
/// Levenberg–Marquardt proximal term, re-centred each iteration), with the
/// exact Hessian J̃ᵀJ̃ + Σᵢ rᵢ∇²rᵢ + ζD_R² + μ_R/d² written as the KKT system
///
///     [ Σᵢ rᵢ∇²rᵢ + ζD_R² + μ_R/d² + δw   J̃ᵀ ] [ dw ]   = − [ ∇ψ − J̃ᵀr ]
///     [ J̃                               −I  ] [ y  ]       [ r         ]
///
/// (the Hessian of the Lagrangian at σ = 0, λ = r), factorized with the main
/// iteration's inertia correction, and a backtracking Armijo search on ψ
/// within the fraction to the boundary. μ_R falls by 5 each time its barrier
/// problem is solved. Ipopt instead solves an ℓ₁ restoration NLP by a second
/// interior-point method; ours is simpler and certifies infeasibility the
/// same way: Newton converging to a stationary point of ½‖r‖² with r ≠ 0.
class FeasibilityRestoration {
public:
    FeasibilityRestoration(SlackFormulation& nlp, const BarrierBounds& bounds, KktMatrix& kkt,
                           RegularizedFactorization& factorization, NewtonRecorder& recorder);

    /// From w (changed in place) at barrier parameter μ; `acceptable(w, θ)`
    /// says whether the main iteration's filter accepts w (θ = ‖r(w)‖₁).
    /// At most `max_iterations` Newton steps; `tolerance` is the solve's tol.
    RestorationResult run(Eigen::VectorXd& w, double mu, double tolerance, int max_iterations,
                          const std::function<bool(const Eigen::VectorXd& w, double theta)>& acceptable);

private:
    /// ψ at w (+∞ outside the box or where r is not finite).
    double merit(const Eigen::VectorXd& w, const Eigen::VectorXd& center, double zeta, double mu_r);
    /// Relative stationarity of ½‖r‖² over the box at w, from r_ and jv_;
    /// leaves J̃ᵀr in residual_gradient_.
    double stationarity(const Eigen::VectorXd& w);

    SlackFormulation& nlp_;
    const BarrierBounds& bounds_;
    KktMatrix& kkt_;
    RegularizedFactorization& factorization_;
    NewtonRecorder& recorder_;
    InertiaCorrection schedule_;
    int n_, m_;
    Eigen::VectorXd r_, jv_, hv_, scale_, r_trial_, residual_gradient_;
};

} // namespace sinew
