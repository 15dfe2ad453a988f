#include "sinew/solvers/newton/projected_newton.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/solvers/linear/linear_solver.hpp"
#include "sinew/solvers/newton/active_bounds.hpp"
#include "sinew/solvers/newton/factorization_reuse.hpp"
#include "sinew/solvers/newton/forcing_term.hpp"
#include "sinew/solvers/newton/newton_recorder.hpp"
#include "sinew/solvers/newton/pattern_matrix.hpp"
#include "sinew/solvers/newton/regularized_factorization.hpp"
#include "sinew/solvers/newton/stagnation_watch.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace sinew {
namespace {

using Eigen::VectorXd;

/// The shift of the next exact try after H + σI was found indefinite:
/// next_shift's first (1e-8·diagonal_scale) after none, then 100σ, at most
/// 1e20. Each try that fails costs an iteration on the projected Hessian, so
/// the shift climbs two decades a try, as Ipopt's δw does by κ̄w⁺ = 100
/// (Wächter & Biegler 2006, §3.1); it comes down a decade per well-predicted
/// step (line_search_and_update).
double raised_shift(double shift, double diagonal_scale)
{
    constexpr double kGrowth = 100.0;
    return shift == 0.0 ? next_shift(0.0, diagonal_scale) : std::min(kGrowth * shift, 1e20);
}

/// What projected Newton keeps across the solves of one SolverMemory (the
/// time steps of a run): its factorization, whose symbolic analysis then
/// serves every solve, and whether its factors may be reused. With reuse on,
/// a solve's first iteration tries CG preconditioned by the last solve's
/// factors before it factorizes: the 52k cantilever's 10 steps then
/// factorize once (docs/dynamics.md).
struct NewtonMemory {
    std::shared_ptr<RegularizedFactorization> factorization;
    std::string linear_solver;
    int variables = 0;
    bool factors_kept = false;
    ReuseBackoff backoff;
};

constexpr const char* kNewtonMemory = "newton factorization";

/// The memory's state when it fits this solve, else a new one it keeps from now on.
std::shared_ptr<NewtonMemory> remembered_state(SolverMemory* memory, const std::string& linear_solver,
                                               int variables)
{
    if (memory && memory->kind == kNewtonMemory) {
        auto kept = std::static_pointer_cast<NewtonMemory>(memory->state);
        if (kept->linear_solver == linear_solver && kept->variables == variables)
            return kept;
    }
    auto state = std::make_shared<NewtonMemory>();
    state->factorization = std::make_shared<RegularizedFactorization>(make_linear_solver(linear_solver));
    state->linear_solver = linear_solver;
    state->variables = variables;
    if (memory) {
        memory->kind = kNewtonMemory;
        memory->state = state;
    }
    return state;
}

/// One run of projected Newton: the Hessian policy (which H, which shift)
/// over the shared line search, regularized factorization and recorder.
class ProjectedNewtonRun {
public:
    ProjectedNewtonRun(Nlp& nlp, const SolverOptions& options, const NewtonSettings& settings,
                       const std::string& solver_name)
        : nlp_(nlp), options_(options), settings_(settings), recorder_(options, solver_name, nlp.name()),
          memory_(remembered_state(options.memory.get(), settings.linear_solver, nlp.num_variables())),
          factorization_(memory_->factorization),
          reuse_(*factorization_, settings.reuse),
          hessian_(nlp.hessian_pattern(), nlp.num_variables()), hessian_values_(nlp.hessian_pattern().nonzeros()),
          projected_(nlp.supports(Projection::clamp)),
          inexact_(settings.reuse.enabled || is_iterative_linear_solver(settings.linear_solver)), bounds_(nlp)
    {
        const int n = nlp.num_variables();
        gradient_.resize(n);
        rhs_.resize(n);
        step_.resize(n);
        trial_.resize(n);
        trial_gradient_.resize(n);
        recorder_.add_statistic("projected_iterations", 0.0);
        recorder_.set_row_annotation(settings.annotate_row);
        recorder_.set_baseline(*factorization_);
        reuse_.resume(memory_->factors_kept, memory_->backoff);
        resumed_ = reuse_.kept();
    }

    Result run();

    /// Whether this run started on the factors a previous solve kept.
    bool resumed() const { return resumed_; }
    /// The next run on the same memory factorizes at its first iteration.
    void drop_kept_factors() { memory_->factors_kept = false; }

private:
    Result finish(Status status, const std::string& message)
    {
        recorder_.add_statistic("cg_iterations", reuse_.cg_iterations());
        recorder_.add_statistic("reused_factorization_steps", reuse_.reused_steps());
        recorder_.add_statistic("cg_refused_steps", reuse_.refused_steps());
        recorder_.add_statistic("cg_skipped_steps", reuse_.skipped_steps());
        recorder_.add_statistic("cg_s", reuse_.cg_seconds());
        memory_->factors_kept = reuse_.kept();
        memory_->backoff = reuse_.backoff();
        return recorder_.finish(status, message, x_, *factorization_);
    }
    void evaluate_gradient(const VectorXd& at, VectorXd& into)
    {
        recorder_.begin_assembly();
        nlp_.gradient(at, into);
        recorder_.end_assembly();
    }
    void assemble_hessian(Projection projection)
    {
        recorder_.begin_assembly();
        nlp_.hessian(x_, 1.0, no_multipliers_, projection, hessian_values_);
        hessian_.fill(hessian_values_);
        if (bounds_.any())
            hessian_.fix_variables(bounds_.fixed());
        diagonal_scale_ = std::max(1.0, hessian_.matrix().diagonal().cwiseAbs().maxCoeff());
        recorder_.end_assembly();
    }
    /// Solves (H + shift·I) d = −∇f (zero at variables held at a bound) into
    /// `direction`: by CG on the kept factorization to the forcing term η
    /// when reuse is on and CG gets there (FactorizationReuse); otherwise by
    /// factorizing the assembled H + shift·I, the shift raised until Cholesky
    /// accepts it, and keeping that factorization. An iterative linear solver
    /// (reuse off) solves to η instead, its algebraic multigrid built with
    /// the problem's near null space at x, the shift raised when its CG
    /// meets non-positive curvature.
    bool solve_shifted(double& shift, VectorXd& direction, double diagonal_scale)
    {
        step_reused_ = reuse_.solve(hessian_.matrix(), shift, rhs_, eta_, direction);
        if (step_reused_)
            return true;
        prepare_linear_solver();
        if (!factorization_->solve_shifted(hessian_, shift, diagonal_scale, rhs_, direction))
            return false;
        reuse_.keep();
        return true;
    }
    /// solve_shifted with `shift` tried once, not raised: `indefinite` when
    /// CG on the kept factorization, the Cholesky of H + shift·I or an
    /// iterative solver's CG finds H + shift·I not positive definite.
    ShiftedSolve attempt_shifted(double shift, VectorXd& direction)
    {
        step_reused_ = reuse_.solve(hessian_.matrix(), shift, rhs_, eta_, direction);
        if (step_reused_)
            return ShiftedSolve::solved;
        if (reuse_.found_indefinite())
            return ShiftedSolve::indefinite;
        prepare_linear_solver();
        const ShiftedSolve outcome = factorization_->attempt_shifted(hessian_, shift, rhs_, direction);
        if (outcome == ShiftedSolve::solved)
            reuse_.keep();
        else
            reuse_.forget();
        return outcome;
    }
    /// An algebraic multigrid gets the near null space at x; an iterative
    /// solver the forcing term η as its relative residual.
    void prepare_linear_solver()
    {
        if (factorization_->solver().uses_near_null_space())
            factorization_->set_near_null_space(nlp_.near_null_space(x_));
        factorization_->set_tolerance(eta_);
    }
    /// The (projected) gradient is at most target_ and, unless an outer
    /// loop set the target, at most the KKT tolerance solve() checks
    /// afterwards, kkt_tol · max(1, ‖∇f‖∞): an exact Newton step overshoots
    /// the first test far enough as a rule, an inexact one not always.
    bool reached() const
    {
        const double norm = bounds_.projected_gradient_norm(x_, gradient_);
        const bool kkt = settings_.gradient_target > 0.0 ||
                         norm <= options_.kkt_tolerance * std::max(1.0, gradient_.cwiseAbs().maxCoeff());
        return norm <= target_ && kkt;
    }
    bool newton_step(bool& exact);
    ShiftedSolve exact_step();
    bool projected_step();
    /// The line search along step_ and the update of x and the policy; a
    /// Result when the solve ends here.
    std::optional<Result> line_search_and_update(int iteration, bool exact);

    Nlp& nlp_;
    const SolverOptions& options_;
    NewtonSettings settings_;
    NewtonRecorder recorder_;
    std::shared_ptr<NewtonMemory> memory_;  ///< kept in SolverMemory across solves when given
    std::shared_ptr<RegularizedFactorization> factorization_;
    FactorizationReuse reuse_;
    ForcingTerm forcing_;
    double eta_ = ForcingTerm::eta_max;  ///< this iteration's forcing term
    /// η of the finishing step: its linear residual, 1e-4 of a gradient
    /// already below the target, leaves x closer to the solution than the
    /// target alone promises.
    static constexpr double kFinishingForcing = 1e-4;
    double target_ = 0.0;     ///< the (projected) gradient norm at which the solve stops
    bool finishing_ = false;  ///< this step starts at the target: the finishing step
    PatternMatrix hessian_;
    VectorXd hessian_values_;
    const VectorXd no_multipliers_ = VectorXd(0);
    const bool projected_;
    const bool inexact_;  ///< steps solved to the forcing term η: reuse on, or an iterative linear solver
    ActiveBounds bounds_;
    bool resumed_ = false;  ///< started on the factors of a previous solve
    bool step_reused_ = false;  ///< the last step came from CG on kept factors
    StagnationWatch stagnation_;

    VectorXd x_, gradient_, rhs_, step_, trial_, trial_gradient_;
    double f_ = 0.0;
    double diagonal_scale_ = 1.0;
    bool trust_exact_ = false;     ///< the last step's ρ ≥ ½
    double kept_shift_ = 0.0;      ///< the shift of the next exact Hessian (Levenberg-Marquardt)
};

Result ProjectedNewtonRun::run()
{
    x_ = nlp_.starting_point();
    bounds_.project(x_);
    f_ = nlp_.objective(x_);
    recorder_.count_evaluation();
    if (!std::isfinite(f_))
        return finish(Status::numerical_error, "objective not finite at the starting point");
    evaluate_gradient(x_, gradient_);
    const double initial_gradient = bounds_.projected_gradient_norm(x_, gradient_);
    recorder_.record(0, f_, 0.0, initial_gradient, 0.0, 0.0);
    stagnation_.stagnant(f_, initial_gradient);
    target_ = settings_.gradient_target > 0.0 ? settings_.gradient_target : options_.tolerance * initial_gradient;

    for (int iteration = 1;; ++iteration) {
        // With inexact steps (reuse on, or an iterative linear solver), the
        // point that meets the target gets one finishing step solved to
        // η = kFinishingForcing, then the solve ends: an
        // inexact step that just meets the target (η up to ‖∇f‖/‖∇f₀‖) leaves
        // x as far from the solution as the target allows, where an exact
        // Newton step would as a rule have overshot it by orders of magnitude.
        // With finishing_step off the solve ends at the target (time steps).
        const bool at_target = reached();
        const bool no_finishing_step = !inexact_ || !settings_.finishing_step;
        if (at_target && (finishing_ || no_finishing_step || iteration > options_.max_iterations))
            return finish(Status::converged, "gradient reduced by tol");
        finishing_ = at_target;
        if (iteration > options_.max_iterations)
            return finish(Status::max_iterations, "iteration limit reached");
        recorder_.set_iterations(iteration);
        // H: the exact Hessian while its quadratic model predicted the last
        // step well (ρ ≥ ½), shifted by the kept multiple of I, unless that
        // is indefinite (exact_step); the PSD projection the problem offers
        // (seed 000 §5.6) otherwise, and always at the start. Per-element projection
        // alone stiffens H where element terms of opposite sign cancel in the
        // sum, and then converges only linearly; the exact Hessian alone
        // overshoots far from the solution (docs/solvers.md, "Projected Newton").
        bool exact = !projected_ || trust_exact_;
        eta_ = finishing_ ? kFinishingForcing : forcing_.next(bounds_.projected_gradient_norm(x_, gradient_));
        if (!newton_step(exact))
            return finish(Status::numerical_error, factorization_->failure());
        if (std::optional<Result> stop = line_search_and_update(iteration, exact))
            return *stop;
    }
}

bool ProjectedNewtonRun::newton_step(bool& exact)
{
    bounds_.update(x_, gradient_);
    rhs_ = -gradient_;
    for (size_t i = 0; bounds_.any() && i < bounds_.fixed().size(); ++i)
        if (bounds_.fixed()[i])
            rhs_[static_cast<Eigen::Index>(i)] = 0.0;
    if (exact) {
        const ShiftedSolve outcome = exact_step();
        if (outcome == ShiftedSolve::failed)
            return false;
        exact = outcome == ShiftedSolve::solved;
    }
    if (!exact && !projected_step())
        return false;
    if (!(gradient_.dot(step_) < 0.0))
        step_ = rhs_;  // not a descent direction: steepest descent
    // The longest step tried: 1e3 max(1, ‖x‖) (Dennis & Schnabel's maxstep,
    // "Numerical Methods for Unconstrained Optimization", §6.3 and A6.3.1).
    // A nearly singular H's Newton step (HS 3: f linear along a null vector
    // of H, shifted by 1e-8 of its diagonal) can overshoot by 1e12, more than
    // the line search's halvings undo; the cap leaves it a few.
    const double longest = 1e3 * std::max(1.0, x_.norm());
    if (step_.norm() > longest)
        step_ *= longest / step_.norm();
    return true;
}

// The step on the exact H + σI, σ = kept_shift_. A problem with a
// projection tries that σ once: when H + σI is indefinite, σ is raised for
// the next exact iteration (raised_shift) and this one takes the projected
// step, one factorization where raising σ until Cholesky
// accepts it costs one per σ tried (three per exact iteration on the twisted
// 206k cantilever, docs/benchmarks.md). Without a projection, σ is raised
// until H + σI is positive definite.
ShiftedSolve ProjectedNewtonRun::exact_step()
{
    assemble_hessian(Projection::none);
    double shift = kept_shift_;
    if (projected_) {
        const ShiftedSolve outcome = attempt_shifted(shift, step_);
        if (outcome == ShiftedSolve::indefinite)
            kept_shift_ = raised_shift(kept_shift_, diagonal_scale_);
        return outcome;
    }
    if (!solve_shifted(shift, step_, diagonal_scale_))
        return ShiftedSolve::failed;
    kept_shift_ = shift;
    return ShiftedSolve::solved;
}

bool ProjectedNewtonRun::projected_step()
{
    assemble_hessian(Projection::clamp);
    recorder_.add_statistic("projected_iterations", 1.0);
    double shift = 0.0;
    return solve_shifted(shift, step_, diagonal_scale_);
}

std::optional<Result> ProjectedNewtonRun::line_search_and_update(int iteration, bool exact)
{
    const double slope = gradient_.dot(step_);
    auto merit = [&](double alpha) {
        trial_ = x_ + alpha * step_;
        bounds_.project(trial_);
        recorder_.count_evaluation();
        return nlp_.objective(trial_);
    };
    // Near the solution the decrease ½∇fᵀH⁻¹∇f falls below the round-off of
    // f: a step that keeps f within round-off and reduces the (projected)
    // gradient's ∞-norm is accepted.
    auto gradient_reduced = [&](double) {
        nlp_.gradient(trial_, trial_gradient_);
        return bounds_.projected_gradient_norm(trial_, trial_gradient_) <
               bounds_.projected_gradient_norm(x_, gradient_);
    };
    const LineSearchOutcome search =
        backtracking_line_search(merit, f_, slope, settings_.line_search, gradient_reduced);
    if (search.status != LineSearchStatus::accepted) {
        if (finishing_)  // x already met the target; the finishing step found nothing to gain
            return finish(Status::converged, "gradient reduced by tol");
        if (search.status == LineSearchStatus::stalled)
            return finish(Status::stalled, "no measurable decrease of f along the Newton step");
        return finish(Status::line_search_failed,
                      "no sufficient decrease after " + std::to_string(search.backtracks) + " halvings");
    }
    // ρ = actual / predicted decrease of the full step; the model ½dᵀHd + ∇fᵀd
    // with Hd = −∇f predicts −½∇fᵀd. Trust the exact Hessian next when ρ ≥ ½;
    // in exact mode also adapt the shift as a Levenberg-Marquardt parameter:
    // ×10 when ρ < ¼, ÷10 when ρ > ¾. A predicted decrease below round-off of
    // f leaves ρ meaningless; that happens only near a solution, where the
    // exact Hessian is the one to use.
    const double predicted = -0.5 * slope;
    const bool measurable = predicted > 1e-11 * std::max(1.0, std::abs(f_));
    const double rho = !measurable                       ? 1.0
                       : std::isfinite(search.full_step) ? (f_ - search.full_step) / predicted
                                                         : -kInfinity;
    trust_exact_ = rho >= 0.5;
    if (!measurable)
        kept_shift_ = 0.0;  // near the solution: exact Newton, quadratic convergence
    else if (exact && rho < 0.25)
        kept_shift_ = kept_shift_ > 0.0 ? 10.0 * kept_shift_ : 0.0;
    else if (exact && rho > 0.75)
        kept_shift_ = kept_shift_ / 10.0 > 1e-8 * diagonal_scale_ ? kept_shift_ / 10.0 : 0.0;
    if (step_below_roundoff(x_, trial_))
        return finish(finishing_ ? Status::converged : Status::stalled,
                      finishing_ ? "gradient reduced by tol" : "the Newton step is below the round-off of x");
    // An inexact step the line search had to shorten says the kept factors
    // no longer model H well enough at the forcing term's η (up to ½ while
    // the gradient stalls): the next step factorizes afresh. Measured
    // (docs/solvers.md): the 6k cantilever at tol 1e-10 in 20 iterations
    // instead of 24 with the same 4 factorizations; the penalty's and the
    // augmented Lagrangian's subproblems on hs076 in 20 instead of 73 and 45.
    if (step_reused_ && search.alpha < 1.0) {
        reuse_.forget();
        recorder_.add_statistic("cg_shortened_steps", 1.0);
    }
    x_.swap(trial_);
    f_ = search.merit;
    evaluate_gradient(x_, gradient_);
    const double gradient_norm = bounds_.projected_gradient_norm(x_, gradient_);
    recorder_.record(iteration, f_, 0.0, gradient_norm, search.alpha * step_.cwiseAbs().maxCoeff(), search.alpha);
    if (stagnation_.stagnant(f_, gradient_norm) && !reached())
        return finish(Status::stalled, "no progress in " + std::to_string(stagnation_.window()) +
                                           " iterations: f changed within its round-off and the gradient did not "
                                           "halve (a kink or noise in grad f near x)");
    return std::nullopt;
}

class ProjectedNewton final : public Solver {
public:
    std::string name() const override { return "projected-newton"; }
    std::string description() const override
    {
        return "Newton on the exact Hessian near the solution, PSD-projected elsewhere, CHOLMOD, Armijo; "
               "unconstrained and bound-constrained problems";
    }
    std::vector<OptionDeclaration> declared_options() const override
    {
        std::vector<OptionDeclaration> declarations = newton_option_declarations();
        declarations.push_back(real_option("gradient_target", "0",
                                           "stop when the projected gradient's inf-norm is at most this (absolute, "
                                           "for a solve warm-started near its solution); 0: tol times its value at "
                                           "the start",
                                           0.0, 1e300));
        declarations.push_back(choice_option(
            "finishing_step", "on",
            "on: once an inexact step (reused factorization, iterative linear solver) meets the target, one more "
            "step solved to a relative residual of 1e-4 leaves x well inside it; off: stop at the target",
            {"on", "off"}));
        return declarations;
    }

    std::optional<std::string> refusal(const Nlp& nlp) const override
    {
        const NlpCapabilities kind = capabilities_of(nlp);
        if (kind.has_inequalities)
            return "projected-newton takes unconstrained and bound-constrained problems only (this one has " +
                   kind.describe() + "; use interior-point, penalty, augmented-lagrangian or ipopt)";
        if (kind.has_equalities)
            return "projected-newton takes unconstrained and bound-constrained problems only (this one has " +
                   kind.describe() +
                   "; eliminate Dirichlet conditions, or use kkt-newton, interior-point, augmented-lagrangian or ipopt)";
        return std::nullopt;
    }

    void check_options(const SolverOptions& options) const override
    {
        settings_of(options);
    }

    Result run(Nlp& nlp, const SolverOptions& options) const override
    {
        return run_projected_newton(nlp, options, settings_of(options), name());
    }

private:
    NewtonSettings settings_of(const SolverOptions& options) const
    {
        const OptionValues values = read_options(name(), declared_options(), {}, options.backend);
        NewtonSettings settings = newton_settings(values);
        settings.gradient_target = values.real("gradient_target");
        settings.finishing_step = values.text("finishing_step") == "on";
        return settings;
    }
};

} // namespace

std::vector<OptionDeclaration> newton_option_declarations()
{
    return {choice_option("linear_solver", "cholmod", "sparse solver of H d = -grad f", known_linear_solver_names()),
            real_option("armijo", "1e-4", "sufficient-decrease constant c1 of the Armijo test", 0.0, 0.5, true, true),
            integer_option("max_backtracks", "40", "halvings of the step before line_search_failed", 1, 1000),
            choice_option("reuse_factorization", "auto",
                          "on: a step after the first solves H d = -grad f by CG preconditioned with the last "
                          "factorization, to an Eisenstat-Walker forcing term, and H is factorized afresh when CG "
                          "needs more than max_cg_iterations; off: H is factorized every iteration; auto: on with "
                          "a direct linear_solver, off with an iterative one",
                          {"auto", "on", "off"}),
            integer_option("max_cg_iterations", "20",
                           "CG iterations a step on a reused factorization may take before H is factorized afresh",
                           1, 100000)};
}

NewtonSettings newton_settings(const OptionValues& values)
{
    NewtonSettings settings;
    settings.linear_solver = values.text("linear_solver");
    check_linear_solver_usable(settings.linear_solver);
    settings.line_search.armijo = values.real("armijo");
    settings.line_search.max_backtracks = values.integer("max_backtracks");
    const std::string& reuse = values.text("reuse_factorization");
    const bool iterative = is_iterative_linear_solver(settings.linear_solver);
    if (reuse == "on" && iterative)
        throw InputError("reuse_factorization = on needs a direct linear_solver; " + settings.linear_solver +
                         " is iterative (use reuse_factorization = off or auto)");
    settings.reuse.enabled = reuse == "on" || (reuse == "auto" && !iterative);
    settings.reuse.max_cg_iterations = values.integer("max_cg_iterations");
    return settings;
}

// A solve that started on a previous solve's factors takes inexact steps
// from its first iteration. Where the target lies near the round-off of f
// (a time step at tol 1e-10), those steps can creep into the range where f
// no longer measures a decrease, and the line search stalls short of the
// target; a first step on fresh factors jumps past that range. Such a solve
// is run again from its start without the kept factors, the counts and
// time of the first attempt added.
Result run_projected_newton(Nlp& nlp, const SolverOptions& options, const NewtonSettings& settings,
                            const std::string& solver_name)
{
    ProjectedNewtonRun attempt(nlp, options, settings, solver_name);
    const Result result = attempt.run();
    const bool short_of_target = result.status == Status::stalled || result.status == Status::line_search_failed;
    if (!attempt.resumed() || !short_of_target)
        return result;
    attempt.drop_kept_factors();
    Result retry = ProjectedNewtonRun(nlp, options, settings, solver_name).run();
    add_counts(retry, result);
    retry.time_s += result.time_s;
    retry.statistics["restarts_without_kept_factors"] += 1.0;
    return retry;
}

std::unique_ptr<Solver> make_projected_newton_solver() { return std::make_unique<ProjectedNewton>(); }

} // namespace sinew
