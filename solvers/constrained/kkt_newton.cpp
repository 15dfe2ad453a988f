#include "sinew/solvers/constrained/kkt_newton.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/solvers/constrained/equality_constraints.hpp"
#include "sinew/solvers/kkt_measures.hpp"
#include "sinew/solvers/newton/active_bounds.hpp"
#include "sinew/solvers/newton/kkt_matrix.hpp"
#include "sinew/solvers/newton/line_search.hpp"
#include "sinew/solvers/newton/newton_recorder.hpp"
#include "sinew/solvers/newton/regularized_factorization.hpp"

#include <cmath>
#include <optional>

namespace sinew {
namespace {

using Eigen::VectorXd;

struct KktNewtonSettings {
    std::string linear_solver;
    LineSearchSettings line_search;
    bool second_order_correction = true;
};

std::vector<OptionDeclaration> kkt_newton_options()
{
    return {choice_option("linear_solver", "mumps-ldlt", "LDL^T of the KKT matrix; it must report the inertia",
                          {"mumps-ldlt", "cholmod-ldlt"}),
            real_option("armijo", "1e-4", "sufficient-decrease constant c1 on the l1 merit", 0.0, 0.5, true, true),
            integer_option("max_backtracks", "40", "halvings of the step before line_search_failed", 1, 1000),
            choice_option("second_order_correction", "yes", "try a second-order correction when the full step fails",
                          {"yes", "no"})};
}

KktNewtonSettings read_settings(const SolverOptions& options)
{
    const OptionValues values = read_options("kkt-newton", kkt_newton_options(), {}, options.backend);
    KktNewtonSettings settings;
    settings.linear_solver = values.text("linear_solver");
    settings.line_search.armijo = values.real("armijo");
    settings.line_search.max_backtracks = values.integer("max_backtracks");
    settings.second_order_correction = values.text("second_order_correction") == "yes";
    return settings;
}

class KktNewtonRun {
public:
    KktNewtonRun(Nlp& nlp, const SolverOptions& options, const KktNewtonSettings& settings)
        : nlp_(nlp), options_(options), settings_(settings), n_(nlp.num_variables()), m_(nlp.num_constraints()),
          constraints_(nlp), bounds_(nlp), kkt_(nlp.hessian_pattern(), nlp.jacobian_pattern(), n_, m_),
          factorization_(make_linear_solver(settings.linear_solver)), recorder_(options, "kkt-newton", nlp.name()),
          lambda_(VectorXd::Zero(m_)), g_(n_), gl_(n_), c_(m_), jv_(nlp.jacobian_pattern().nonzeros()),
          hv_(nlp.hessian_pattern().nonzeros()), rhs_(n_ + m_), solution_(n_ + m_), trial_(n_), c_trial_(m_)
    {
    }

    Result run();

private:
    void evaluate_first_order();
    bool compute_step(bool hold_active_bounds);
    double merit_slope();
    double merit(double f, const VectorXd& c) const { return f + nu_ * c.lpNorm<1>(); }
    double merit_at(const VectorXd& x);
    bool second_order_correction(double merit0, double slope);
    void update_multipliers(double primal_before_step);
    Result finish(Status status, const std::string& message);

    Nlp& nlp_;
    const SolverOptions& options_;
    KktNewtonSettings settings_;
    const int n_, m_;
    EqualityConstraints constraints_;
    ActiveBounds bounds_;
    KktMatrix kkt_;
    RegularizedFactorization factorization_;
    InertiaCorrection schedule_;
    NewtonRecorder recorder_;
    VectorXd x_, lambda_, g_, gl_, c_, jv_, hv_, rhs_, solution_, trial_, c_trial_, d_, lambda_plus_;
    double f_ = 0.0;
    double nu_ = 0.0;           ///< ℓ1 merit penalty parameter
    double max_delta_w_ = 0.0;  ///< the largest δw the inertia correction needed
};

/// ∇f, c̃, J and ∇L = ∇f + Jᵀλ at x_.
void KktNewtonRun::evaluate_first_order()
{
    recorder_.begin_assembly();
    nlp_.gradient(x_, g_);
    constraints_.residuals(x_, c_);
    constraints_.jacobian(x_, jv_);
    constraints_.transpose_times(jv_, lambda_, gl_);
    gl_ += g_;
    recorder_.end_assembly();
}

double KktNewtonRun::merit_at(const VectorXd& x)
{
    recorder_.count_evaluation();
    const double f = nlp_.objective(x);
    if (!std::isfinite(f))
        return kInfinity;
    constraints_.residuals(x, c_trial_);
    return c_trial_.allFinite() ? merit(f, c_trial_) : kInfinity;
}

/// The inertia-corrected KKT step (d, λ⁺), holding the ε-active bounds or
/// not; false when no factorization works.
bool KktNewtonRun::compute_step(bool hold_active_bounds)
{
    recorder_.begin_assembly();
    nlp_.hessian(x_, 1.0, lambda_, Projection::none, hv_);
    recorder_.end_assembly();
    bounds_.update(x_, gl_);
    const std::vector<char> fixed = hold_active_bounds && bounds_.any() ? bounds_.fixed() : std::vector<char>{};
    auto assemble = [&](double delta_w, double delta_c) -> const SparseMatrix& {
        return kkt_.fill(hv_, jv_, 1.0, delta_w, delta_c, fixed);
    };
    if (!factorization_.factorize_with_inertia(assemble, n_, m_, schedule_))
        return false;
    max_delta_w_ = std::max(max_delta_w_, schedule_.last_delta_w);
    rhs_.head(n_) = -g_;
    for (size_t i = 0; i < fixed.size(); ++i)
        if (fixed[i])
            rhs_[static_cast<Eigen::Index>(i)] = 0.0;
    rhs_.tail(m_) = -c_;
    if (!factorization_.solve(rhs_, solution_))
        return false;
    d_ = solution_.head(n_);
    lambda_plus_ = solution_.tail(m_);
    return true;
}

/// Second-order correction (Wächter & Biegler 2006, §2.4): the full step's
/// constraint values replace the linearization, c_soc = c̃(x) + c̃(x + d),
/// solved with the same factorization. Accepted on the same Armijo test.
bool KktNewtonRun::second_order_correction(double merit0, double slope)
{
    constraints_.residuals(trial_, c_trial_);
    rhs_.tail(m_) = -(c_ + c_trial_);
    VectorXd corrected(n_ + m_);
    if (!factorization_.solve(rhs_, corrected))
        return false;
    trial_ = x_ + corrected.head(n_);
    bounds_.project(trial_);
    const double value = merit_at(trial_);
    if (!(std::isfinite(value) && value <= merit0 + settings_.line_search.armijo * slope))
        return false;
    d_ = corrected.head(n_);
    lambda_plus_ = corrected.tail(m_);
    return true;
}

/// D φ(d) = ∇fᵀd + ν D‖c̃‖₁(d), D‖c̃‖₁(d) = Σ_{c̃ᵢ≠0} sign(c̃ᵢ)(Jd)ᵢ + Σ_{c̃ᵢ=0} |(Jd)ᵢ|.
/// ν first rises to 1.1‖λ⁺‖∞ (unless K was singular) and to (∇fᵀd + ½ max(dᵀHd, 0)) / ((1 − ρ)(−D‖c̃‖₁)),
/// ρ = 0.1 (Nocedal & Wright eq. 18.36), dᵀHd = −∇fᵀd − λ⁺ᵀJd from the KKT rows.
double KktNewtonRun::merit_slope()
{
    const SparsityPattern& J = constraints_.pattern();
    VectorXd jd = VectorXd::Zero(m_);
    for (int k = 0; k < J.nonzeros(); ++k)
        jd[J.rows[k]] += jv_[k] * d_[J.cols[k]];
    double violation_slope = 0.0;
    for (int i = 0; i < m_; ++i)
        violation_slope += c_[i] > 0.0 ? jd[i] : c_[i] < 0.0 ? -jd[i] : std::abs(jd[i]);
    const double gd = g_.dot(d_);
    // ν > ‖λ*‖∞ makes the ℓ1 merit exact; λ⁺ of a singular K (δc > 0) says nothing of λ*.
    if (m_ > 0 && factorization_.attempts().back().delta_c == 0.0)
        nu_ = std::max(nu_, 1.1 * lambda_plus_.cwiseAbs().maxCoeff());
    if (violation_slope < 0.0) {
        const double curvature = -gd - lambda_plus_.dot(jd);
        nu_ = std::max(nu_, (gd + 0.5 * std::max(0.0, curvature)) / (0.9 * -violation_slope));
    }
    return gd + nu_ * violation_slope;
}

/// λ after a step. The KKT system's λ⁺ whatever α (a step shortened by the
/// line search still gives λ⁺ at x), except
/// - when the inertia correction added δw > 0 and λ⁺ is more than ten times
///   the least-squares multipliers at x (∞-norm): ∇f + Jᵀλ⁺ = −(H + δw I)d
///   carries δw·d, which grows with δw while c̃ ≠ 0 and feeds back through
///   H = ∇²f + Σλᵢ∇²cᵢ into a larger δw (HS 81 from its start: λ to 1e8,
///   δw to 1e10, then a stall). λ is then the least-squares estimate, which
///   has no δw in it (a reset like Ipopt's constr_mult_reset_threshold);
/// - far from feasibility (‖c̃‖∞ > √tol), when J is rank-deficient (δc > 0):
///   λ⁺ of a singular system says nothing of λ* and is not taken. Near
///   feasibility such a λ⁺ is a valid choice among many multipliers.
void KktNewtonRun::update_multipliers(double primal_before_step)
{
    const FactorizationAttempt& used = factorization_.attempts().back();
    if (used.delta_w > 0.0 && m_ > 0) {
        VectorXd least_squares, z_lower, z_upper;
        estimate_multipliers(nlp_, x_, std::sqrt(options_.constraint_tolerance), least_squares, z_lower, z_upper);
        recorder_.count_evaluation();
        if (lambda_plus_.cwiseAbs().maxCoeff() > 10.0 * std::max(1.0, least_squares.cwiseAbs().maxCoeff())) {
            lambda_ = least_squares;
            recorder_.add_statistic("multiplier_resets", 1.0);
            return;
        }
    }
    if (used.delta_c == 0.0 || primal_before_step <= std::sqrt(options_.tolerance))
        lambda_ = lambda_plus_;
}

Result KktNewtonRun::finish(Status status, const std::string& message)
{
    recorder_.add_statistic("max_delta_w", max_delta_w_);
    Result result = recorder_.finish(status, message, x_, factorization_);
    result.constraint_multipliers = lambda_;
    bounds_.multipliers(x_, gl_, result.bound_multipliers_lower, result.bound_multipliers_upper);
    return result;
}

Result KktNewtonRun::run()
{
    x_ = nlp_.starting_point();
    bounds_.project(x_);
    f_ = nlp_.objective(x_);
    recorder_.count_evaluation();
    if (!std::isfinite(f_))
        return finish(Status::numerical_error, "objective not finite at the starting point");
    evaluate_first_order();
    // J (m × n) cannot have full row rank: K is singular for every δw.
    if (m_ > n_)
        return finish(Status::failed, std::to_string(m_) + " equality constraints on " + std::to_string(n_) +
                                          " variables: the exact KKT system is singular (use relaxed-kkt, penalty "
                                          "or augmented-lagrangian, which relax it)");
    double step_norm = 0.0, alpha = 0.0;
    VectorXd infeasibility_gradient(n_);
    for (int iteration = 0;; ++iteration) {
        const double primal = m_ > 0 ? c_.cwiseAbs().maxCoeff() : 0.0;
        const double dual = bounds_.projected_gradient_norm(x_, gl_);
        recorder_.record(iteration, f_, primal, dual, step_norm, alpha);
        if (primal <= std::min(options_.constraint_tolerance, options_.tolerance) &&
            dual <= options_.tolerance * std::max(1.0, g_.cwiseAbs().maxCoeff()))
            return finish(Status::converged, "KKT conditions hold to tol");
        // x stationary for ½‖c̃‖² while c̃ ≠ 0: no step of Newton's reduces the violation.
        constraints_.transpose_times(jv_, c_, infeasibility_gradient);
        if (primal > options_.constraint_tolerance &&
            bounds_.projected_gradient_norm(x_, infeasibility_gradient) <= options_.tolerance * primal)
            return finish(Status::infeasible, "stationary point of the constraint violation with |c| = " +
                                                  std::to_string(primal) + ": the constraints look inconsistent");
        if (iteration >= options_.max_iterations)
            return finish(Status::max_iterations, "iteration limit reached");
        recorder_.set_iterations(iteration + 1);
        if (!compute_step(true))
            return finish(Status::numerical_error, factorization_.failure());
        double slope = merit_slope();
        // Bounds held at the ε-active set can leave Jd = −c̃ unreachable and
        // the step uphill for the merit: then the step without them.
        if (!(slope < 0.0) && bounds_.any()) {
            if (!compute_step(false))
                return finish(Status::numerical_error, factorization_.failure());
            slope = merit_slope();
        }
        if (!(slope < 0.0))
            return finish(Status::stalled, "the KKT step is not a descent direction of the l1 merit at a constraint "
                                           "violation of " + format_number(primal) +
                                               (primal > options_.constraint_tolerance
                                                    ? " (inconsistent or degenerate constraints?)"
                                                    : " (round-off)"));
        const double merit0 = merit(f_, c_);
        const double primal_before_step = primal;
        auto merit_along = [&](double a) {
            trial_ = x_ + a * d_;
            bounds_.project(trial_);
            return merit_at(trial_);
        };
        const double full = merit_along(1.0);
        LineSearchOutcome search;
        if (std::isfinite(full) && full <= merit0 + settings_.line_search.armijo * slope) {
            search.status = LineSearchStatus::accepted;
            search.alpha = 1.0;
        } else if (settings_.second_order_correction && m_ > 0 && std::isfinite(full) &&
                   second_order_correction(merit0, slope)) {
            search.status = LineSearchStatus::accepted;
            search.alpha = 1.0;
            recorder_.add_statistic("second_order_corrections", 1.0);
        } else {
            search = backtracking_line_search(merit_along, merit0, slope, settings_.line_search, {});
        }
        if (search.status == LineSearchStatus::stalled)
            return finish(Status::stalled, "no measurable decrease of the merit along the KKT step");
        if (search.status == LineSearchStatus::failed)
            return finish(Status::line_search_failed,
                          "no sufficient decrease of the l1 merit after " + std::to_string(search.backtracks) +
                              " halvings");
        if (step_below_roundoff(x_, trial_))
            return finish(Status::stalled, "the step is below the round-off of x");
        alpha = search.alpha;
        step_norm = (trial_ - x_).cwiseAbs().maxCoeff();
        x_ = trial_;
        update_multipliers(primal_before_step);
        f_ = nlp_.objective(x_);
        recorder_.count_evaluation();
        evaluate_first_order();
    }
}

class KktNewton final : public Solver {
public:
    std::string name() const override { return "kkt-newton"; }
    std::string description() const override
    {
        return "Newton on the KKT system (SQP), MUMPS LDL^T with inertia correction, l1 merit with second-order "
               "correction; bounds, equalities";
    }
    std::vector<OptionDeclaration> declared_options() const override { return kkt_newton_options(); }
    std::optional<std::string> refusal(const Nlp& nlp) const override { return refuse_inequalities(name(), nlp); }
    void check_options(const SolverOptions& options) const override { read_settings(options); }
    Result run(Nlp& nlp, const SolverOptions& options) const override
    {
        return KktNewtonRun(nlp, options, read_settings(options)).run();
    }
};

} // namespace

std::unique_ptr<Solver> make_kkt_newton_solver() { return std::make_unique<KktNewton>(); }

} // namespace sinew
