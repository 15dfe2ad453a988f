#include "sinew/solvers/constrained/penalty_method.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/solvers/constrained/augmented_lagrangian_function.hpp"
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
/// history (objective f and violation ‖c̃‖∞ written by the outer loop).
class OuterLoop {
public:
    OuterLoop(Nlp& nlp, const SolverOptions& options, const OuterSettings& settings, std::string name)
        : nlp_(nlp), options_(options), settings_(settings), name_(std::move(name)), function_(nlp), bounds_(nlp)
    {
    }

    Result run();

private:
    Result solve_subproblem(double kappa, int outer);
    /// tol × max(1, ‖∇f(x)‖∞): the subproblems' gradient target at x, and the
    /// bound the last one must have met for the solve to count as converged.
    double gradient_target(const VectorXd& x);
    void absorb(const Result& inner, int outer);
    Result finish(Status status, const std::string& message, const VectorXd& x);

    Nlp& nlp_;
    const SolverOptions& options_;
    OuterSettings settings_;
    std::string name_;
    AugmentedLagrangianFunction function_;
    ActiveBounds bounds_;
    VectorXd lambda_;
    Result total_;
    int rows_ = 0;
};

Result OuterLoop::solve_subproblem(double kappa, int outer)
{
    function_.set_parameters(lambda_, kappa);
    NewtonSettings inner = settings_.inner;
    inner.gradient_target = gradient_target(function_.starting_point());
    inner.annotate_row = [this, outer](HistoryRow& row) {
        row.objective = function_.last_objective();
        row.constraint_violation =
            function_.last_residuals().size() > 0 ? function_.last_residuals().cwiseAbs().maxCoeff() : 0.0;
        row.outer_iteration = outer;
    };
    SolverOptions inner_options = options_;
    inner_options.memory = nullptr;  // each subproblem starts afresh (its κ or λ moved)
    inner_options.max_iterations = std::max(1, options_.max_iterations - total_.iterations);
    return run_projected_newton(function_, inner_options, inner, name_);
}

double OuterLoop::gradient_target(const VectorXd& x)
{
    VectorXd g(nlp_.num_variables());
    nlp_.gradient(x, g);
    return options_.tolerance * std::max(1.0, g.cwiseAbs().maxCoeff());
}

void OuterLoop::absorb(const Result& inner, int outer)
{
    for (HistoryRow row : inner.history) {
        if (outer > 0 && row.iteration == 0)
            continue;  // the subproblem's start is the last one's end
        row.iteration = rows_++;
        total_.history.push_back(row);
    }
    total_.iterations += inner.iterations;
    total_.function_evaluations += inner.function_evaluations;
    total_.linear_solves = std::max(0, total_.linear_solves) + std::max(0, inner.linear_solves);
    for (const auto& [key, value] : inner.statistics)
        total_.statistics[key] += value;
}

Result OuterLoop::finish(Status status, const std::string& message, const VectorXd& x)
{
    total_.status = status;
    total_.message = message;
    total_.x = x;
    total_.constraint_multipliers = settings_.multipliers ? lambda_ : VectorXd();
    return total_;
}

Result OuterLoop::run()
{
    const int m = nlp_.num_constraints();
    lambda_ = VectorXd::Zero(m);
    VectorXd x = nlp_.starting_point();
    bounds_.project(x);
    function_.set_starting_point(x);
    double kappa = settings_.kappa;
    double last_violation = kInfinity;
    VectorXd c(m);
    for (int outer = 0;; ++outer) {
        const double target = gradient_target(x);
        const Result inner = solve_subproblem(kappa, outer);
        absorb(inner, outer);
        x = inner.x;
        function_.set_starting_point(x);
        total_.statistics["kappa"] = kappa;
        total_.statistics["outer_iterations"] = outer + 1;
        if (inner.status != Status::converged && inner.status != Status::stalled)
            return finish(inner.status, "subproblem " + std::to_string(outer + 1) + ": " + inner.message, x);
        function_.equality_constraints().residuals(x, c);
        const double violation = m > 0 ? c.cwiseAbs().maxCoeff() : 0.0;
        // The subproblem's target, set from ∇f at its start, must also hold
        // for ∇f at its end; otherwise the next subproblem tightens it.
        const bool stationary = target <= gradient_target(x);
        if (violation <= options_.constraint_tolerance && inner.status == Status::converged && stationary)
            return finish(Status::converged, "violation within constr_tol at kappa = " + format_number(kappa), x);
        // A feasible penalty minimizer whose subproblem stalled at round-off
        // of ∇φ (κJᵀc̃ grows with κ): more stiffness cannot help. It ends
        // here; solve() then measures the KKT residual and keeps "converged"
        // only if that tolerance holds too.
        if (!settings_.multipliers && violation <= options_.constraint_tolerance && inner.status == Status::stalled)
            return finish(Status::converged,
                          "violation within constr_tol at kappa = " + format_number(kappa) +
                              "; the subproblem stalled at round-off: " + inner.message,
                          x);
        if (settings_.multipliers)
            lambda_ += kappa * c;  // λ ← λ + κc̃ (Ipopt's sign: ∇f + Jᵀλ = 0)
        const bool stalled = violation > 0.25 * last_violation;
        last_violation = violation;
        const bool raise = !settings_.multipliers || stalled;
        const bool can_raise = settings_.kappa_growth > 1.0 && kappa * settings_.kappa_growth <= settings_.max_kappa;
        if (raise && !can_raise) {
            // No stiffer subproblem to tighten the gradient target: a feasible
            // point ends here, and solve() keeps "converged" only if the KKT
            // residual holds too.
            if (violation <= options_.constraint_tolerance && inner.status == Status::converged)
                return finish(Status::converged,
                              "violation within constr_tol at the largest kappa = " + format_number(kappa), x);
            if (settings_.multipliers)
                return finish(Status::infeasible, penalty_message(violation, kappa) + ", and it stalls", x);
            return finish(Status::tolerance_not_met, penalty_message(violation, kappa), x);
        }
        if (raise)
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
        return "quadratic penalty E + kappa/2 |c|^2 by projected Newton, kappa continuation; bounds, equalities";
    }
    std::vector<OptionDeclaration> declared_options() const override { return outer_options("1e2", "10"); }
    std::map<std::string, std::vector<OptionDeclaration>> nested_options() const override
    {
        return {{"inner", newton_option_declarations()}};
    }
    std::optional<std::string> refusal(const Nlp& nlp) const override { return refuse_inequalities(name(), nlp); }
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
        return "method of multipliers on f + lambda^T c + kappa/2 |c|^2, projected Newton subproblems; bounds, "
               "equalities";
    }
    std::vector<OptionDeclaration> declared_options() const override { return outer_options("10", "10"); }
    std::map<std::string, std::vector<OptionDeclaration>> nested_options() const override
    {
        return {{"inner", newton_option_declarations()}};
    }
    std::optional<std::string> refusal(const Nlp& nlp) const override { return refuse_inequalities(name(), nlp); }
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
