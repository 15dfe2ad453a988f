#include "sinew/solvers/interior/interior_point.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/solvers/interior/barrier_bounds.hpp"
#include "sinew/solvers/interior/barrier_parameter.hpp"
#include "sinew/solvers/interior/feasibility_restoration.hpp"
#include "sinew/solvers/interior/filter_line_search.hpp"
#include "sinew/solvers/interior/slack_formulation.hpp"
#include "sinew/solvers/newton/kkt_matrix.hpp"
#include "sinew/solvers/newton/newton_recorder.hpp"
#include "sinew/solvers/newton/regularized_factorization.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew {
namespace {

using Eigen::VectorXd;

struct InteriorPointSettings {
    std::string linear_solver;
    BarrierParameter::Rule rule = BarrierParameter::Rule::monotone;
    double mu_init = 0.1;
    double bound_push = 1e-2;
    double bound_frac = 1e-2;
    double bound_relax_factor = 1e-8;
    bool second_order_correction = true;
};

std::vector<OptionDeclaration> interior_point_options()
{
    return {choice_option("linear_solver", "mumps-ldlt", "LDL^T of the KKT matrix; it must report the inertia",
                          {"mumps-ldlt", "cholmod-ldlt"}),
            choice_option("mu_strategy", "monotone",
                          "barrier parameter update: monotone (Fiacco-McCormick) or adaptive (LOQO rule with "
                          "Ipopt's kkt-error safeguard)",
                          {"monotone", "adaptive"}),
            real_option("mu_init", "0.1", "first barrier parameter mu", 0.0, 1e10, true),
            real_option("bound_push", "1e-2", "the start is moved at least this far (relative) inside each bound",
                        0.0, 0.5, true, true),
            real_option("bound_frac", "1e-2", "... and at least this fraction of the gap between two bounds",
                        0.0, 0.5, true),
            real_option("bound_relax_factor", "1e-8",
                        "bounds and inequalities are relaxed by this (relative) so that the iterates have an "
                        "interior; 0 keeps them exact (then no x_L = x_U or equal inequality bounds)",
                        0.0, 1e-2),
            choice_option("second_order_correction", "yes",
                          "try second-order corrections when the first trial step is rejected", {"yes", "no"})};
}

InteriorPointSettings read_settings(const SolverOptions& options)
{
    const OptionValues values = read_options("interior-point", interior_point_options(), {}, options.backend);
    InteriorPointSettings settings;
    settings.linear_solver = values.text("linear_solver");
    settings.rule = values.text("mu_strategy") == "adaptive" ? BarrierParameter::Rule::adaptive
                                                             : BarrierParameter::Rule::monotone;
    settings.mu_init = values.real("mu_init");
    settings.bound_push = values.real("bound_push");
    settings.bound_frac = values.real("bound_frac");
    settings.bound_relax_factor = values.real("bound_relax_factor");
    settings.second_order_correction = values.text("second_order_correction") == "yes";
    return settings;
}

/// The iterate's errors (Wächter & Biegler 2006, eq. 5): unscaled, and the
/// scale factors s_d, s_c of the barrier problem's error E_μ.
struct Errors {
    double primal = 0.0;  ///< ‖r‖∞
    double dual = 0.0;    ///< ‖∇f + J̃ᵀλ − z_L + z_U‖∞
    double s_d = 1.0, s_c = 1.0;
};

class InteriorPointRun {
public:
    InteriorPointRun(Nlp& problem, const SolverOptions& options, const InteriorPointSettings& settings)
        : options_(options), settings_(settings), nlp_(problem), bounds_(nlp_, settings.bound_relax_factor), n_(problem.num_variables()),
          N_(nlp_.num_variables()), m_(nlp_.num_constraints()),
          kkt_(nlp_.hessian_pattern(), nlp_.jacobian_pattern(), N_, m_),
          factorization_(make_linear_solver(settings.linear_solver)),
          recorder_(options, "interior-point", problem.name()),
          barrier_(settings.rule, settings.mu_init, 0.1 * options.tolerance),
          restoration_(nlp_, bounds_, kkt_, factorization_, recorder_), g_(N_), r_(m_),
          jv_(nlp_.jacobian_pattern().nonzeros()), hv_(nlp_.hessian_pattern().nonzeros()), jtl_(N_),
          r_trial_(m_), rhs_(N_ + m_), solution_(N_ + m_)
    {
    }

    Result run();

private:
    void evaluate_derivatives();
    Errors errors() const;
    double barrier_error(const Errors& e, double mu) const;
    BarrierMeasures measures(const Errors& e) const;
    bool initial_multipliers();
    bool compute_direction();
    bool solve_with_constraint_rows(const VectorXd& constraint_rows);
    void dual_directions();
    TrialMeasures evaluate_trial(const VectorXd& w);
    TrialMeasures trial(double alpha);
    std::optional<TrialMeasures> correction(int k, double alpha_max);
    void accept(double alpha, double alpha_dual);
    void update_multiplier_products();
    bool converged(const Errors& e) const;
    bool restore(Result& stop);
    Result finish(Status status, const std::string& message);

    const SolverOptions& options_;
    InteriorPointSettings settings_;
    SlackFormulation nlp_;
    BarrierBounds bounds_;
    const int n_, N_, m_;
    KktMatrix kkt_;
    RegularizedFactorization factorization_;
    InertiaCorrection schedule_;
    NewtonRecorder recorder_;
    BarrierParameter barrier_;
    FeasibilityRestoration restoration_;
    VectorXd w_, lambda_, z_lower_, z_upper_;  ///< the iterate (w, λ, z_L, z_U)
    VectorXd g_, r_, jv_, hv_, jtl_;           ///< ∇f, r, J̃, ∇²L values, J̃ᵀλ at w
    VectorXd sigma_, barrier_gradient_, to_lower_, to_upper_;
    VectorXd dw_, dlambda_, dz_lower_, dz_upper_;
    VectorXd w_trial_, r_trial_, c_soc_, rhs_, solution_;
    double f_ = 0.0, f_trial_ = 0.0;
    double alpha_soc_ = 1.0;  ///< the step length of the last second-order correction
    int restoration_iterations_ = 0;
    int recorder_iterations_ = 0;  ///< iterations so far, restoration's included
    std::optional<FilterLineSearch> search_;  ///< made once θ₀ is known
};

/// ∇f, r, J̃ and J̃ᵀλ at w_.
void InteriorPointRun::evaluate_derivatives()
{
    recorder_.begin_assembly();
    nlp_.gradient(w_, g_);
    nlp_.constraints(w_, r_);
    nlp_.jacobian_values(w_, jv_);
    recorder_.end_assembly();
    update_multiplier_products();
}

/// J̃ᵀλ from J̃'s values and λ.
void InteriorPointRun::update_multiplier_products()
{
    const SparsityPattern& J = nlp_.jacobian_pattern();
    jtl_.setZero();
    for (int k = 0; k < J.nonzeros(); ++k)
        jtl_[J.cols[k]] += jv_[k] * lambda_[J.rows[k]];
}

Errors InteriorPointRun::errors() const
{
    Errors e;
    e.primal = m_ > 0 ? r_.cwiseAbs().maxCoeff() : 0.0;
    e.dual = N_ > 0 ? (g_ + jtl_ - z_lower_ + z_upper_).cwiseAbs().maxCoeff() : 0.0;
    // s_d = max(s_max, (‖λ‖₁ + ‖z‖₁)/(m + 2N)) / s_max, s_c likewise with z alone; s_max = 100.
    const double z_sum = z_lower_.lpNorm<1>() + z_upper_.lpNorm<1>();
    e.s_d = std::max(100.0, (lambda_.lpNorm<1>() + z_sum) / std::max(1, m_ + 2 * N_)) / 100.0;
    e.s_c = std::max(100.0, z_sum / std::max(1, 2 * N_)) / 100.0;
    return e;
}

/// E_μ = max(‖∇L‖∞/s_d, ‖r‖∞, ‖WZe − μe‖∞/s_c), eq. 5.
double InteriorPointRun::barrier_error(const Errors& e, double mu) const
{
    return std::max({e.dual / e.s_d, e.primal, bounds_.complementarity(w_, z_lower_, z_upper_, mu) / e.s_c});
}

BarrierMeasures InteriorPointRun::measures(const Errors& e) const
{
    BarrierMeasures m;
    m.barrier_error = [this, e](double mu) { return barrier_error(e, mu); };
    m.optimality_error = barrier_error(e, 0.0);
    VectorXd to_lower, to_upper;
    bounds_.distances(w_, to_lower, to_upper);
    const VectorXd lower = to_lower.cwiseProduct(z_lower_), upper = to_upper.cwiseProduct(z_upper_);
    double sum = 0.0, smallest = kInfinity;
    int count = 0;
    for (int i = 0; i < N_; ++i) {
        if (bounds_.has_lower(i)) {
            sum += lower[i];
            smallest = std::min(smallest, lower[i]);
            ++count;
        }
        if (bounds_.has_upper(i)) {
            sum += upper[i];
            smallest = std::min(smallest, upper[i]);
            ++count;
        }
    }
    m.average_complementarity = count > 0 ? sum / count : 0.0;
    m.smallest_complementarity = count > 0 ? smallest : 0.0;
    return m;
}

/// λ⁰ by least squares (§3.6): [I, J̃ᵀ; J̃, 0] (u, λ) = (−(∇f − z_L + z_U), 0),
/// discarded (λ = 0) when ‖λ‖∞ > 1e3 or the system cannot be solved.
bool InteriorPointRun::initial_multipliers()
{
    lambda_.setZero(m_);
    if (m_ == 0)
        return true;
    InertiaCorrection once;
    const VectorXd zero_hessian = VectorXd::Zero(hv_.size());
    auto assemble = [&](double delta_w, double delta_c) -> const SparseMatrix& {
        return kkt_.fill(zero_hessian, jv_, VectorXd::Constant(N_, 1.0 + delta_w), VectorXd::Constant(m_, delta_c));
    };
    if (!factorization_.factorize_with_inertia(assemble, N_, m_, once))
        return false;
    rhs_.head(N_) = -(g_ - z_lower_ + z_upper_);
    rhs_.tail(m_).setZero();
    if (!factorization_.solve(rhs_, solution_))
        return false;
    if (solution_.tail(m_).cwiseAbs().maxCoeff() <= 1e3)
        lambda_ = solution_.tail(m_);
    return true;
}

/// The primal-dual direction (dw, dλ) and (dz_L, dz_U) at w_ for μ.
bool InteriorPointRun::compute_direction()
{
    const double mu = barrier_.mu();
    recorder_.begin_assembly();
    nlp_.hessian(w_, 1.0, lambda_, Projection::none, hv_);
    recorder_.end_assembly();
    bounds_.sigma(w_, z_lower_, z_upper_, sigma_);
    bounds_.barrier_gradient(w_, mu, barrier_gradient_);
    auto assemble = [&](double delta_w, double delta_c) -> const SparseMatrix& {
        return kkt_.fill(hv_, jv_, sigma_.array() + delta_w, VectorXd::Constant(m_, delta_c));
    };
    if (!factorization_.factorize_with_inertia(assemble, N_, m_, schedule_))
        return false;
    if (!solve_with_constraint_rows(r_))
        return false;
    dual_directions();
    return true;
}

/// Solves K (dw, dλ) = −(∇φ_μ + J̃ᵀλ, c) with the current factorization.
bool InteriorPointRun::solve_with_constraint_rows(const VectorXd& constraint_rows)
{
    rhs_.head(N_) = -(g_ + barrier_gradient_ + jtl_);
    rhs_.tail(m_) = -constraint_rows;
    if (!factorization_.solve(rhs_, solution_))
        return false;
    dw_ = solution_.head(N_);
    dlambda_ = solution_.tail(m_);
    return true;
}

/// dz_L = μ/(w − w_L) − z_L − Σ_L dw, dz_U = μ/(w_U − w) − z_U + Σ_U dw (eq. 11), on finite bounds.
void InteriorPointRun::dual_directions()
{
    const double mu = barrier_.mu();
    bounds_.distances(w_, to_lower_, to_upper_);
    dz_lower_ = (mu * to_lower_.cwiseInverse() - z_lower_ - z_lower_.cwiseQuotient(to_lower_).cwiseProduct(dw_))
                    .cwiseProduct(bounds_.lower_mask());
    dz_upper_ = (mu * to_upper_.cwiseInverse() - z_upper_ + z_upper_.cwiseQuotient(to_upper_).cwiseProduct(dw_))
                    .cwiseProduct(bounds_.upper_mask());
}

/// θ = ‖r‖₁ and φ_μ = f + barrier at w (into w_trial_, f_trial_, r_trial_).
TrialMeasures InteriorPointRun::evaluate_trial(const VectorXd& w)
{
    w_trial_ = w;
    TrialMeasures point;
    const double barrier = bounds_.barrier(w_trial_, barrier_.mu());
    recorder_.count_evaluation();
    f_trial_ = std::isfinite(barrier) ? nlp_.objective(w_trial_) : kInfinity;
    nlp_.constraints(w_trial_, r_trial_);
    point.theta = r_trial_.allFinite() ? r_trial_.lpNorm<1>() : kInfinity;
    point.phi = std::isfinite(f_trial_) ? f_trial_ + barrier : kInfinity;
    return point;
}

TrialMeasures InteriorPointRun::trial(double alpha) { return evaluate_trial(w_ + alpha * dw_); }

/// The k-th second-order correction (§2.4): c_soc ← α c_soc + r(trial), starting
/// from c_soc = α_max r(w), solved with the same factorization; the step is cut
/// to the fraction to the boundary. The duals keep the uncorrected direction.
std::optional<TrialMeasures> InteriorPointRun::correction(int k, double alpha_max)
{
    if (!settings_.second_order_correction || m_ == 0)
        return std::nullopt;
    if (k == 1) {
        c_soc_ = r_;
        alpha_soc_ = alpha_max;
    }
    c_soc_ = alpha_soc_ * c_soc_ + r_trial_;
    const VectorXd dw = dw_, dlambda = dlambda_;
    if (!solve_with_constraint_rows(c_soc_))
        return std::nullopt;
    const VectorXd corrected = dw_;
    dw_ = dw;
    dlambda_ = dlambda;
    alpha_soc_ = bounds_.max_step(w_, corrected, barrier_.fraction_to_boundary());
    recorder_.add_statistic("second_order_corrections", 1.0);
    return evaluate_trial(w_ + alpha_soc_ * corrected);
}

/// w ← the accepted trial, λ ← λ + α dλ, z ← z + α_z dz (kept near μ/d, eq. 16).
void InteriorPointRun::accept(double alpha, double alpha_dual)
{
    w_ = w_trial_;
    f_ = f_trial_;
    lambda_ += alpha * dlambda_;
    z_lower_ += alpha_dual * dz_lower_;
    z_upper_ += alpha_dual * dz_upper_;
    bounds_.safeguard(w_, barrier_.mu(), z_lower_, z_upper_);
    evaluate_derivatives();
}

/// The stopping test of every Newton strategy: ‖r‖∞ ≤ min(constr_tol, tol),
/// and stationarity and complementarity (at μ = 0) within tol · max(1, ‖∇f‖∞).
bool InteriorPointRun::converged(const Errors& e) const
{
    const double scale = options_.tolerance * std::max(1.0, g_.head(n_).cwiseAbs().maxCoeff());
    return e.primal <= std::min(options_.constraint_tolerance, options_.tolerance) && e.dual <= scale &&
           bounds_.complementarity(w_, z_lower_, z_upper_, 0.0) <= scale;
}

/// The feasibility restoration phase from w_; true when the iteration goes on
/// (from the restored point, λ by least squares, z = μ/d), false with `stop`
/// set when it ends the solve.
bool InteriorPointRun::restore(Result& stop)
{
    const double mu = barrier_.mu();
    // The iterate the phase leaves joins the filter, so that it does not come back (§3.3).
    search_->filter().add(r_.lpNorm<1>(), f_ + bounds_.barrier(w_, mu));
    auto acceptable = [&](const VectorXd& w, double theta) {
        recorder_.count_evaluation();
        const double phi = nlp_.objective(w) + bounds_.barrier(w, mu);
        return std::isfinite(phi) && search_->filter().accepts(theta, phi);
    };
    const int budget = std::max(0, options_.max_iterations - recorder_iterations_);
    const VectorXd last_accepted = w_;
    const RestorationResult outcome = restoration_.run(w_, mu, options_.tolerance, budget, acceptable);
    restoration_iterations_ += outcome.iterations;
    recorder_.add_statistic("restoration_phases", 1.0);
    if (outcome.outcome == RestorationOutcome::infeasible) {
        stop = finish(Status::infeasible, "converged to a point of local infeasibility: " + outcome.message);
        return false;
    }
    if (outcome.outcome == RestorationOutcome::failed) {
        w_ = last_accepted;  // the phase's own last point may be far worse than the iterate it started from
        recorder_.count_evaluation();
        f_ = nlp_.objective(w_);
        evaluate_derivatives();
        stop = finish(Status::stalled, "the feasibility restoration phase failed: " + outcome.message);
        return false;
    }
    recorder_.count_evaluation();
    f_ = nlp_.objective(w_);
    bounds_.distances(w_, to_lower_, to_upper_);
    z_lower_ = (mu * to_lower_.cwiseInverse()).cwiseProduct(bounds_.lower_mask());
    z_upper_ = (mu * to_upper_.cwiseInverse()).cwiseProduct(bounds_.upper_mask());
    lambda_.setZero();
    evaluate_derivatives();
    if (initial_multipliers())
        update_multiplier_products();
    return true;
}

Result InteriorPointRun::finish(Status status, const std::string& message)
{
    recorder_.add_statistic("restoration_iterations", restoration_iterations_);
    recorder_.add_statistic("final_mu", barrier_.mu());
    VectorXd w = w_;
    bounds_.original(w);
    Result result = recorder_.finish(status, message, w.head(n_), factorization_);
    result.constraint_multipliers = lambda_;
    result.bound_multipliers_lower = z_lower_.head(n_);
    result.bound_multipliers_upper = z_upper_.head(n_);
    return result;
}

Result InteriorPointRun::run()
{
    w_ = nlp_.starting_point();
    bounds_.push_inside(w_, settings_.bound_push, settings_.bound_frac);
    z_lower_ = bounds_.lower_mask();  // z⁰ = 1 on finite bounds (Ipopt's bound_mult_init_val)
    z_upper_ = bounds_.upper_mask();
    lambda_.setZero(m_);
    recorder_.count_evaluation();
    f_ = nlp_.objective(w_);
    if (!std::isfinite(f_))
        return finish(Status::numerical_error, "objective not finite at the starting point (moved inside the bounds)");
    evaluate_derivatives();
    if (!g_.allFinite() || !r_.allFinite() || !jv_.allFinite())
        return finish(Status::numerical_error, "gradient, constraints or Jacobian not finite at the starting point");
    // J̃ (m × N) cannot have full row rank: K is singular for every δw.
    if (m_ > N_)
        return finish(Status::failed, std::to_string(m_) + " equality constraints on " + std::to_string(N_) +
                                          " variables (slacks included): the KKT system is singular (use "
                                          "relaxed-kkt, penalty or augmented-lagrangian, which relax it)");
    if (initial_multipliers())
        update_multiplier_products();
    search_.emplace(r_.lpNorm<1>());
    double step_norm = 0.0, alpha = 0.0;
    for (int iteration = 0;; ++iteration) {
        const Errors e = errors();
        recorder_.record(iteration, f_, e.primal, e.dual, step_norm, alpha);
        if (converged(e))
            return finish(Status::converged, "KKT conditions hold to tol (barrier parameter " +
                                                 format_number(barrier_.mu()) + ")");
        // Ipopt's diverging_iterates_tol.
        if (w_.cwiseAbs().maxCoeff() > 1e20)
            return finish(Status::failed, "the iterates diverge (|x| > 1e20): the problem may be unbounded below");
        recorder_iterations_ = iteration + restoration_iterations_;
        if (recorder_iterations_ >= options_.max_iterations)
            return finish(Status::max_iterations, "iteration limit reached");
        recorder_.set_iterations(recorder_iterations_ + 1);
        if (barrier_.update(measures(e)))
            search_->filter().clear();
        if (!compute_direction())
            return finish(Status::numerical_error, factorization_.failure());
        // A step below the round-off of w (Ipopt's tiny step): the barrier problem is as solved as it can be.
        if ((dw_.array().abs() / (1.0 + w_.array().abs())).maxCoeff() < 10.0 * std::numeric_limits<double>::epsilon()) {
            if (barrier_.at_floor())
                return finish(Status::stalled, "the step is below the round-off of x at the smallest barrier parameter");
            barrier_.force_decrease();
            search_->filter().clear();
            step_norm = alpha = 0.0;
            continue;
        }
        const double tau = barrier_.fraction_to_boundary();
        const double alpha_max = bounds_.max_step(w_, dw_, tau);
        const double alpha_dual = std::min(bounds_.max_dual_step(z_lower_, dz_lower_, bounds_.lower_mask(), tau),
                                           bounds_.max_dual_step(z_upper_, dz_upper_, bounds_.upper_mask(), tau));
        const double slope = (g_ + barrier_gradient_).dot(dw_);  // ∇φ_μᵀ dw
        const TrialMeasures current{m_ > 0 ? r_.lpNorm<1>() : 0.0, f_ + bounds_.barrier(w_, barrier_.mu())};
        const FilterStep step = search_->search(
            current, slope, alpha_max, [&](double a) { return trial(a); },
            [&](int k) { return correction(k, alpha_max); });
        if (step.kind == FilterStepKind::restoration) {
            Result stop;
            if (!restore(stop))
                return stop;
            step_norm = alpha = 0.0;
            continue;
        }
        if (step.kind == FilterStepKind::no_decrease)
            return finish(Status::stalled, "no step along the direction decreases the barrier objective at a "
                                           "feasible point (round-off?)");
        step_norm = (w_trial_ - w_).head(n_).cwiseAbs().maxCoeff();
        alpha = step.alpha;
        accept(step.alpha, alpha_dual);
    }
}

class InteriorPoint final : public Solver {
public:
    std::string name() const override { return "interior-point"; }
    std::string description() const override
    {
        return "primal-dual interior point with a filter line search (after Ipopt), slacks for inequalities, "
               "MUMPS LDL^T with inertia correction, feasibility restoration; bounds, equalities, inequalities";
    }
    std::vector<OptionDeclaration> declared_options() const override { return interior_point_options(); }
    std::optional<std::string> refusal(const Nlp&) const override { return std::nullopt; }
    void check_options(const SolverOptions& options) const override { read_settings(options); }
    Result run(Nlp& nlp, const SolverOptions& options) const override
    {
        return InteriorPointRun(nlp, options, read_settings(options)).run();
    }
};

} // namespace

std::unique_ptr<Solver> make_interior_point_solver() { return std::make_unique<InteriorPoint>(); }

} // namespace sinew
