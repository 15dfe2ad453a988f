#include "sinew/solvers/constrained/penalty_method.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/solvers/constrained/augmented_lagrangian_function.hpp"
#include "sinew/solvers/constrained/constraint_residuals.hpp"
#include "sinew/solvers/constrained/equality_constraints.hpp"
#include "sinew/solvers/constrained/penalty_status.hpp"
#include "sinew/solvers/newton/active_bounds.hpp"
#include "sinew/solvers/newton/projected_newton.hpp"

#include <chrono>
#include <cmath>

namespace sinew {
namespace {

using Eigen::VectorXd;

/// The outer loop's settings; the subproblem's are NewtonSettings.
struct OuterSettings {
    double kappa = 0.0;       ///< first κ
    double kappa_growth = 10.0;
    double max_kappa = 1e12;
    int max_outer = 50;
    bool multipliers = false;  ///< augmented Lagrangian (true) or penalty
    NewtonSettings inner;
};

std::vector<OptionDeclaration> outer_options(const char* first_kappa, const char* growth)
{
    return {real_option("kappa", first_kappa, "first constraint stiffness kappa", 0.0, 1e20, true),
            real_option("kappa_growth", growth, "kappa <- kappa_growth * kappa when more stiffness is needed "
                                                "(1: a single solve at fixed kappa)", 1.0, 1e6),
            real_option("max_kappa", "1e12", "largest kappa", 0.0, 1e30, true),
            integer_option("max_outer_iterations", "50", "subproblems solved at most", 1, 10000)};
}

OuterSettings read_settings(const std::string& solver, const std::vector<OptionDeclaration>& declared,
                            const SolverOptions& options, bool multipliers)
{
    const OptionValues values = read_options(solver, declared, {"inner"}, options.backend);
    OuterSettings settings;
    settings.kappa = values.real("kappa");
    settings.kappa_growth = values.real("kappa_growth");
    settings.max_kappa = values.real("max_kappa");
    settings.max_outer = values.integer("max_outer_iterations");
    settings.multipliers = multipliers;
    settings.inner = newton_settings(read_options(solver + " inner", newton_option_declarations(), {},
                                                  values.nested("inner")));
    return settings;
}

/// The outer loop of penalty continuation and of the method of multipliers;
/// every subproblem is solved by projected Newton, whose rows go into one
/// history (objective f and violation ‖c − P(c)‖∞ written by the outer loop).
class OuterLoop {
public:
    OuterLoop(Nlp& nlp, const SolverOptions& options, const OuterSettings& settings, std::string name)
        : nlp_(nlp), options_(options), settings_(settings), name_(std::move(name)), function_(nlp), bounds_(nlp),
          rows_(function_.constraint_residuals()), m_(nlp.num_constraints()), n_(nlp.num_variables()), c_(m_),
          r_(m_), active_(m_), jacobian_(nlp.jacobian_pattern().nonzeros()), g_(n_), grad_phi_(n_), v_(m_)
    {
        x_lower_.resize(n_);
        x_upper_.resize(n_);
        nlp.variable_bounds(x_lower_, x_upper_);
    }

    Result run();

private:
    Result solve_subproblem(double kappa, int outer);
    /// tol × max(1, ‖∇f(x)‖∞): the subproblems' gradient target at x, and the
    /// bound the last one must have met for the solve to count as converged.
    double gradient_target(const VectorXd& x);
    /// At the end x of a subproblem solved with λ, κ: c, the violation
    /// ‖c − P(c)‖∞, the shifted residuals r = c − P(c + λ/κ), the multipliers
    /// μ (the next λ; κ(c − P(c)) for the penalty) and the bound multipliers
    /// from ∇f + Jᵀμ, which the result reports.
    void measure_rows(const VectorXd& x, double kappa);
    /// Puts on its bound every variable of x within ‖x − P(x − ∇φ)‖∞ of it
    /// that ∇φ (from measure_rows()) pushes outward, as a projected-gradient
    /// step would; whether any moved.
    bool place_held_variables(VectorXd& x);
    /// |μᵀv| ≤ kkt_tol · max(1, |f(x)|), from measure_rows(): to first order
    /// f(x*) − f(x) = μᵀ(c − P(c)) near a KKT point, so this bounds the
    /// distance in energy to the constrained optimum that a feasibility test
    /// alone leaves open (a violation of 1e-6 with large multipliers).
    bool energy_gap_small(const VectorXd& x);
    /// z_L, z_U ≥ 0 at x from g = ∇f + Jᵀμ.
    void bound_multipliers(const VectorXd& x, const VectorXd& g);
    void absorb(const Result& inner, int outer);
    Result finish(Status status, const std::string& message, const VectorXd& x);

    Nlp& nlp_;
    const SolverOptions& options_;
    OuterSettings settings_;
    std::string name_;
    AugmentedLagrangianFunction function_;
    ActiveBounds bounds_;
    ConstraintResiduals& rows_;
    const int m_, n_;
    VectorXd lambda_, multipliers_, z_lower_, z_upper_, x_lower_, x_upper_;
    VectorXd c_, r_, active_, jacobian_, g_, grad_phi_, v_;  ///< scratch
    double violation_ = 0.0;
    Result total_;
    int history_rows_ = 0;
};

Result OuterLoop::solve_subproblem(double kappa, int outer)
{
    function_.set_parameters(lambda_, kappa);
    NewtonSettings inner = settings_.inner;
    inner.gradient_target = gradient_target(function_.starting_point());
    inner.annotate_row = [this, outer](HistoryRow& row) {
        row.objective = function_.last_objective();
        row.constraint_violation = function_.last_violation();
        row.outer_iteration = outer;
    };
    SolverOptions inner_options = options_;
    inner_options.memory = nullptr;  // each subproblem starts afresh (its κ or λ moved)
    inner_options.max_iterations = std::max(1, options_.max_iterations - total_.iterations);
    return run_projected_newton(function_, inner_options, inner, name_);
}

double OuterLoop::gradient_target(const VectorXd& x)
{
    nlp_.gradient(x, g_);
    return options_.tolerance * std::max(1.0, g_.cwiseAbs().maxCoeff());
}

bool OuterLoop::energy_gap_small(const VectorXd& x)
{
    if (m_ == 0)
        return true;
    rows_.violations(c_, v_);
    return std::abs(multipliers_.dot(v_)) <= options_.kkt_tolerance * std::max(1.0, std::abs(nlp_.objective(x)));
}

void OuterLoop::measure_rows(const VectorXd& x, double kappa)
{
    rows_.values(x, c_);
    violation_ = rows_.max_violation(c_);
    rows_.shifted(c_, lambda_, kappa, r_, multipliers_, active_);
    nlp_.gradient(x, grad_phi_);
    if (m_ > 0) {
        rows_.jacobian(x, jacobian_);
        VectorXd& jt_mu = g_;  // scratch; gradient_target() refills g_
        rows_.transpose_times(jacobian_, multipliers_, jt_mu);
        grad_phi_ += jt_mu;  // ∇φ = ∇f + Jᵀμ
    }
    bound_multipliers(x, grad_phi_);
}

bool OuterLoop::place_held_variables(VectorXd& x)
{
    if (!bounds_.any())
        return false;
    const double reach = bounds_.projected_gradient_norm(x, grad_phi_);
    bool moved = false;
    for (int i = 0; i < n_; ++i) {
        if (grad_phi_[i] > 0.0 && x[i] > x_lower_[i] && x[i] - x_lower_[i] <= reach) {
            x[i] = x_lower_[i];
            moved = true;
        } else if (grad_phi_[i] < 0.0 && x[i] < x_upper_[i] && x_upper_[i] - x[i] <= reach) {
            x[i] = x_upper_[i];
            moved = true;
        }
    }
    return moved;
}

void OuterLoop::bound_multipliers(const VectorXd& x, const VectorXd& g)
{
    // z from g = ∇φ where a bound holds a variable that g pushes outward
    // (g = z_L − z_U there). "Holds": within ‖x − P(x − g)‖∞ of the bound, the
    // projected gradient the subproblem drove to its target: a variable the
    // subproblem kept ε-active may end a round-off away from its bound.
    z_lower_ = VectorXd::Zero(n_);
    z_upper_ = VectorXd::Zero(n_);
    if (!bounds_.any())
        return;
    const double reach = bounds_.projected_gradient_norm(x, g);
    for (int i = 0; i < n_; ++i) {
        if (g[i] > 0.0 && x[i] - x_lower_[i] <= reach)
            z_lower_[i] = g[i];
        else if (g[i] < 0.0 && x_upper_[i] - x[i] <= reach)
            z_upper_[i] = -g[i];
    }
}

void OuterLoop::absorb(const Result& inner, int outer)
{
    for (HistoryRow row : inner.history) {
        if (outer > 0 && row.iteration == 0)
            continue;  // the subproblem's start is the last one's end
        row.iteration = history_rows_++;
        total_.history.push_back(row);
    }
    add_counts(total_, inner);
}

Result OuterLoop::finish(Status status, const std::string& message, const VectorXd& x)
{
    total_.status = status;
    total_.message = message;
    total_.x = x;
    // The method of multipliers reports μ and z of the last subproblem's end
    // (Ipopt's signs: ∇f + Jᵀμ − z_L + z_U is ∇φ there, μ ≥ 0 only on an upper
    // side, ≤ 0 only on a lower one), and solve() measures the KKT residual
    // with them. The penalty reports none: its μ = κ(c − P(c)) carries the
    // round-off of c − P(c) times κ (2e-4 in the KKT residual of hs100 at
    // κ = 1e9), and solve() estimates them by least squares on the active set.
    if (settings_.multipliers) {
        total_.constraint_multipliers = multipliers_;
        total_.bound_multipliers_lower = z_lower_;
        total_.bound_multipliers_upper = z_upper_;
    }
    return total_;
}

Result OuterLoop::run()
{
    lambda_ = VectorXd::Zero(m_);
    multipliers_ = VectorXd::Zero(m_);
    VectorXd x = nlp_.starting_point();
    bounds_.project(x);
    function_.set_starting_point(x);
    double kappa = settings_.kappa;
    double last_measure = kInfinity;
    for (int outer = 0;; ++outer) {
        const double target = gradient_target(x);
        const Result inner = solve_subproblem(kappa, outer);
        absorb(inner, outer);
        x = inner.x;
        function_.set_starting_point(x);
        total_.statistics["kappa"] = kappa;
        total_.statistics["outer_iterations"] = outer + 1;
        measure_rows(x, kappa);
        if (inner.status != Status::converged && inner.status != Status::stalled)
            return finish(inner.status, "subproblem " + std::to_string(outer + 1) + ": " + inner.message, x);
        // A subproblem that stalled with a variable held off its bound (its
        // ε-active set keeps a variable where it is) is solved again, with the
        // same λ and κ, from the point with those variables on their bounds.
        if (inner.status == Status::stalled && outer + 1 < settings_.max_outer && place_held_variables(x)) {
            function_.set_starting_point(x);
            measure_rows(x, kappa);
            if (total_.iterations < options_.max_iterations)
                continue;
        }
        const double violation = violation_;
        // The method of multipliers also needs the multipliers to have
        // settled: ‖r‖∞ = ‖μ − λ‖∞/κ, which is the violation on equality and
        // active rows and |λ|/κ on a row that left its side (complementarity).
        // With λ = 0 (penalty) r is the violation c − P(c) itself.
        const double measure = m_ > 0 ? std::max(violation, r_.cwiseAbs().maxCoeff()) : violation;
        // The subproblem's target, set from ∇f at its start, must also hold
        // for ∇f at its end; otherwise the next subproblem tightens it.
        const bool stationary = target <= gradient_target(x);
        if (measure <= options_.constraint_tolerance && inner.status == Status::converged && stationary &&
            energy_gap_small(x))
            return finish(Status::converged, "violation within constr_tol at kappa = " + format_number(kappa), x);
        // A feasible point (multipliers settled too) whose subproblem stalled
        // at round-off of ∇φ (κJᵀc̃ grows with κ) or at a kink of it (a node
        // the rows let a hair into a faceted body, where φ is not smooth):
        // more stiffness or another multiplier update cannot help. It ends
        // here; solve() then measures the KKT residual and keeps "converged"
        // only if that tolerance holds too.
        if (measure <= options_.constraint_tolerance && inner.status == Status::stalled && energy_gap_small(x))
            return finish(Status::converged,
                          "violation within constr_tol at kappa = " + format_number(kappa) +
                              "; the subproblem stalled at round-off: " + inner.message,
                          x);
        if (settings_.multipliers)
            lambda_ = multipliers_;  // λ ← μ: λ + κ(c − side) on active rows, 0 elsewhere (Ipopt's sign)
        const bool stalled = measure > 0.25 * last_measure;
        // At the largest κ the method of multipliers still converges, only
        // linearly (Bertsekas 1982, §2.2): while the measure keeps falling by
        // a tenth a subproblem, λ is updated again rather than the solve
        // ended (hertz-sphere at max_kappa 1e5 falls by about a quarter).
        const bool still_falling = settings_.multipliers && measure < 0.9 * last_measure;
        last_measure = measure;
        // Once the measure is within constr_tol only the energy gap is left,
        // and it shrinks with the violation as λ is updated: a stiffer
        // subproblem would only be harder to solve (hertz-sphere's at
        // κ = 1e7 stagnated at ‖∇φ‖ = 3e-5).
        const bool raise = !settings_.multipliers || (stalled && measure > options_.constraint_tolerance);
        const bool can_raise = settings_.kappa_growth > 1.0 && kappa * settings_.kappa_growth <= settings_.max_kappa;
        if (raise && !can_raise && !still_falling) {
            // No stiffer subproblem to tighten the gradient target: a feasible
            // point ends here, and solve() keeps "converged" only if the KKT
            // residual holds too.
            if (measure <= options_.constraint_tolerance && inner.status == Status::converged)
                return energy_gap_small(x)
                           ? finish(Status::converged,
                                    "violation within constr_tol at the largest kappa = " + format_number(kappa), x)
                           : finish(Status::tolerance_not_met,
                                    "violation within constr_tol at the largest kappa = " + format_number(kappa) +
                                        ", but the energy gap |mu^T (c - P(c))| exceeds kkt_tol max(1, |f|)",
                                    x);
            if (settings_.multipliers)
                return finish(multiplier_method_status(violation, options_.constraint_tolerance),
                              multiplier_method_message(violation, measure, kappa), x);
            return finish(Status::tolerance_not_met, penalty_message(violation, kappa), x);
        }
        if (raise && can_raise)
            kappa *= settings_.kappa_growth;
        if (outer + 1 >= settings_.max_outer || total_.iterations >= options_.max_iterations)
            return finish(Status::max_iterations, penalty_message(violation, kappa), x);
    }
}

class PenaltyMethod final : public Solver {
public:
    std::string name() const override { return "penalty"; }
    std::string description() const override
    {
        return "quadratic penalty E + kappa/2 |c - P(c)|^2 by projected Newton, kappa continuation; bounds, "
               "equalities, inequalities";
    }
    std::vector<OptionDeclaration> declared_options() const override { return outer_options("1e2", "10"); }
    std::map<std::string, std::vector<OptionDeclaration>> nested_options() const override
    {
        return {{"inner", newton_option_declarations()}};
    }
    std::optional<std::string> refusal(const Nlp& nlp) const override { return refuse_unconstrained(name(), nlp); }
    void check_options(const SolverOptions& options) const override
    {
        read_settings(name(), declared_options(), options, false);
    }
    Result run(Nlp& nlp, const SolverOptions& options) const override
    {
        return OuterLoop(nlp, options, read_settings(name(), declared_options(), options, false), name()).run();
    }
    /// κ held fixed: no continuation (kappa_growth 1).
    std::map<std::string, std::string> fixed_kappa_options(double kappa) const override
    {
        return {{"kappa", option_text(kappa)}, {"kappa_growth", "1"}};
    }
};

class AugmentedLagrangian final : public Solver {
public:
    std::string name() const override { return "augmented-lagrangian"; }
    std::string description() const override
    {
        return "method of multipliers (Powell-Hestenes-Rockafellar) on f + sum (mu^2 - lambda^2)/(2 kappa), "
               "projected Newton subproblems; bounds, equalities, inequalities";
    }
    std::vector<OptionDeclaration> declared_options() const override { return outer_options("10", "10"); }
    std::map<std::string, std::vector<OptionDeclaration>> nested_options() const override
    {
        return {{"inner", newton_option_declarations()}};
    }
    std::optional<std::string> refusal(const Nlp& nlp) const override { return refuse_unconstrained(name(), nlp); }
    void check_options(const SolverOptions& options) const override
    {
        read_settings(name(), declared_options(), options, true);
    }
    Result run(Nlp& nlp, const SolverOptions& options) const override
    {
        return OuterLoop(nlp, options, read_settings(name(), declared_options(), options, true), name()).run();
    }
};

} // namespace

std::unique_ptr<Solver> make_penalty_solver() { return std::make_unique<PenaltyMethod>(); }
std::unique_ptr<Solver> make_augmented_lagrangian_solver() { return std::make_unique<AugmentedLagrangian>(); }

} // namespace sinew
