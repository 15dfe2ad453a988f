#include "sinew/solvers/interior/feasibility_restoration.hpp"

#include "sinew/solvers/newton/line_search.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

constexpr double kReduction = 0.9;  ///< κ_resto: θ must fall below 0.9 θ_R before returning

} // namespace

FeasibilityRestoration::FeasibilityRestoration(SlackFormulation& nlp, const BarrierBounds& bounds, KktMatrix& kkt,
                                               RegularizedFactorization& factorization, NewtonRecorder& recorder)
    : nlp_(nlp), bounds_(bounds), kkt_(kkt), factorization_(factorization), recorder_(recorder),
      n_(nlp.num_variables()), m_(nlp.num_constraints()), r_(m_), jv_(nlp.jacobian_pattern().nonzeros()),
      hv_(nlp.hessian_pattern().nonzeros()), r_trial_(m_)
{
}

double FeasibilityRestoration::merit(const Eigen::VectorXd& w, const Eigen::VectorXd& center, double zeta,
                                     double mu_r)
{
    const double barrier = bounds_.barrier(w, mu_r);
    if (!std::isfinite(barrier))
        return kInfinity;
    recorder_.count_evaluation();
    nlp_.constraints(w, r_trial_);
    if (!r_trial_.allFinite())
        return kInfinity;
    // ψ = ½‖r‖² + ζ/2 ‖D_R (w − w_R)‖² − μ_R Σ ln d
    return 0.5 * r_trial_.squaredNorm() + 0.5 * zeta * (scale_.cwiseProduct(w - center)).squaredNorm() + barrier;
}

double FeasibilityRestoration::stationarity(const Eigen::VectorXd& w)
{
    // g = J̃ᵀr, projected on the box: a component pointing out of a bound
    // counts only up to the distance to it.
    Eigen::VectorXd& g = residual_gradient_;
    g.setZero(n_);
    const SparsityPattern& J = nlp_.jacobian_pattern();
    for (int k = 0; k < J.nonzeros(); ++k)
        g[J.cols[k]] += jv_[k] * r_[J.rows[k]];
    Eigen::VectorXd to_lower, to_upper;
    bounds_.distances(w, to_lower, to_upper);
    double worst = 0.0;
    for (int i = 0; i < n_; ++i) {
        double gi = g[i];
        if (gi > 0.0 && bounds_.has_lower(i))
            gi = std::min(gi, to_lower[i]);
        if (gi < 0.0 && bounds_.has_upper(i))
            gi = std::max(gi, -to_upper[i]);
        worst = std::max(worst, std::abs(gi));
    }
    const double jacobian_scale = jv_.size() > 0 ? std::max(1.0, jv_.cwiseAbs().maxCoeff()) : 1.0;
    const double violation = r_.cwiseAbs().maxCoeff();
    return violation > 0.0 ? worst / (violation * jacobian_scale) : 0.0;
}

RestorationResult FeasibilityRestoration::run(Eigen::VectorXd& w, double mu, double tolerance, int max_iterations,
                                              const std::function<bool(const Eigen::VectorXd&, double)>& acceptable)
{
    RestorationResult result;
    const double zeta = std::sqrt(mu);
    double mu_r = mu;
    double theta_start = -1.0;
    Eigen::VectorXd barrier_gradient, to_lower, to_upper, diagonal(n_), rhs(n_ + m_), solution(n_ + m_), dw, trial;
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(m_);
    for (;; ++result.iterations) {
        recorder_.begin_assembly();
        nlp_.constraints(w, r_);
        nlp_.jacobian_values(w, jv_);
        recorder_.end_assembly();
        const double theta = r_.lpNorm<1>();
        if (theta_start < 0.0)
            theta_start = theta;
        else if (theta <= kReduction * theta_start && acceptable(w, theta)) {
            result.outcome = RestorationOutcome::returned;
            return result;
        }
        result.stationarity = stationarity(w);
        if (theta > 0.0 && result.stationarity <= tolerance) {
            result.outcome = RestorationOutcome::infeasible;
            result.message = "the constraint violation is stationary (relative " +
                             std::to_string(result.stationarity) + ") at ||r||_1 = " + std::to_string(theta);
            return result;
        }
        if (result.iterations >= max_iterations) {
            result.message = "no acceptable point within the iteration limit";
            return result;
        }
        // The Newton system of ψ at w_R = w (the proximal term's gradient vanishes there).
        const Eigen::VectorXd center = w;
        scale_ = w.cwiseAbs().cwiseMax(1.0).cwiseInverse();  // D_R = min(1, 1/|w_R|)
        bounds_.barrier_gradient(w, mu_r, barrier_gradient);
        bounds_.distances(w, to_lower, to_upper);
        diagonal = zeta * scale_.cwiseAbs2() + mu_r * (bounds_.lower_mask().cwiseQuotient(to_lower.cwiseAbs2()) +
                                                       bounds_.upper_mask().cwiseQuotient(to_upper.cwiseAbs2()));
        recorder_.begin_assembly();
        nlp_.hessian(w, 0.0, r_, Projection::none, hv_);  // Σᵢ rᵢ∇²rᵢ
        recorder_.end_assembly();
        auto assemble = [&](double delta_w, double delta_c) -> const SparseMatrix& {
            return kkt_.fill(hv_, jv_, diagonal.array() + delta_w, ones.array() + delta_c);
        };
        if (!factorization_.factorize_with_inertia(assemble, n_, m_, schedule_)) {
            result.message = factorization_.failure();
            return result;
        }
        rhs.head(n_) = -barrier_gradient;
        rhs.tail(m_) = -r_;
        if (!factorization_.solve(rhs, solution)) {
            result.message = factorization_.failure();
            return result;
        }
        dw = solution.head(n_);
        const double slope = (residual_gradient_ + barrier_gradient).dot(dw);  // ∇ψᵀdw, ∇ψ = J̃ᵀr + ∇barrier
        const double alpha_max = bounds_.max_step(w, dw, std::max(0.99, 1.0 - mu_r));
        const double psi0 = merit(w, center, zeta, mu_r);
        LineSearchSettings settings;
        auto along = [&](double alpha) {
            trial = w + (alpha * alpha_max) * dw;
            return merit(trial, center, zeta, mu_r);
        };
        const LineSearchOutcome search =
            slope < 0.0 ? backtracking_line_search(along, psi0, alpha_max * slope, settings, {}) : LineSearchOutcome{};
        if (search.status != LineSearchStatus::accepted || step_below_roundoff(w, trial)) {
            if (theta > 0.0 && result.stationarity <= std::sqrt(tolerance)) {
                result.outcome = RestorationOutcome::infeasible;
                result.message = "no further decrease of the constraint violation, which is stationary (relative " +
                                 std::to_string(result.stationarity) + ") at ||r||_1 = " + std::to_string(theta);
            } else {
                result.message = "no decrease of the constraint violation along the restoration step";
            }
            return result;
        }
        // The barrier problem of ψ solved (‖∇ψ‖∞ ≤ 10 μ_R): μ_R falls.
        if ((residual_gradient_ + barrier_gradient).cwiseAbs().maxCoeff() <= 10.0 * mu_r)
            mu_r = std::max(0.1 * tolerance, 0.2 * mu_r);
        w = trial;
    }
}

} // namespace sinew
