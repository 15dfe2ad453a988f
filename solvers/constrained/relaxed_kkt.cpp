#include "sinew/solvers/constrained/relaxed_kkt.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/solvers/constrained/augmented_lagrangian_function.hpp"
#include "sinew/solvers/constrained/penalty_status.hpp"
#include "sinew/solvers/newton/active_bounds.hpp"
#include "sinew/solvers/newton/kkt_matrix.hpp"
#include "sinew/solvers/newton/line_search.hpp"
#include "sinew/solvers/newton/newton_recorder.hpp"
#include "sinew/solvers/newton/regularized_factorization.hpp"

#include <cmath>

namespace sinew {
namespace {

using Eigen::VectorXd;

struct RelaxedKktSettings {
    double kappa = 1e4;
    bool schur = false;
    std::string ldlt_solver;
    LineSearchSettings line_search;
};

std::vector<OptionDeclaration> relaxed_kkt_options()
{
    return {real_option("kappa", "1e4", "constraint stiffness kappa (the seed's -eta); kappa -> inf is exact KKT", 0.0,
                        1e20, true),
            choice_option("linear_system", "ldlt", "ldlt: the quasi-definite KKT matrix; schur: H + kappa J^T J",
                          {"ldlt", "schur"}),
            choice_option("ldlt_solver", "mumps-ldlt",
                          "the LDL^T of linear_system=ldlt: MUMPS pivots; CHOLMOD's does not, and meets zero "
                          "pivots where H is indefinite",
                          {"mumps-ldlt", "cholmod-ldlt"}),
            real_option("armijo", "1e-4", "sufficient-decrease constant c1 on E + kappa/2 |c|^2", 0.0, 0.5, true,
                        true),
            integer_option("max_backtracks", "40", "halvings of the step before line_search_failed", 1, 1000)};
}

RelaxedKktSettings read_settings(const SolverOptions& options)
{
    const OptionValues values = read_options("relaxed-kkt", relaxed_kkt_options(), {}, options.backend);
    RelaxedKktSettings settings;
    settings.kappa = values.real("kappa");
    settings.schur = values.text("linear_system") == "schur";
    settings.ldlt_solver = values.text("ldlt_solver");
    settings.line_search.armijo = values.real("armijo");
    settings.line_search.max_backtracks = values.integer("max_backtracks");
    return settings;
}

class RelaxedKktRun {
public:
    RelaxedKktRun(Nlp& nlp, const SolverOptions& options, const RelaxedKktSettings& settings)
        : nlp_(nlp), options_(options), settings_(settings), n_(nlp.num_variables()), m_(nlp.num_constraints()),
          penalty_(nlp), bounds_(nlp), kkt_(nlp.hessian_pattern(), nlp.jacobian_pattern(), n_, m_),
          schur_(penalty_.hessian_pattern(), n_),
          factorization_(make_linear_solver(settings.schur ? "cholmod" : settings.ldlt_solver)),
          recorder_(options, "relaxed-kkt", nlp.name()), grad_phi_(n_), g_(n_), jtc_(n_),
          hv_(nlp.hessian_pattern().nonzeros()), sv_(penalty_.hessian_pattern().nonzeros()), rhs_(n_ + m_),
          solution_(n_ + m_), trial_(n_)
    {
        penalty_.set_parameters(VectorXd::Zero(m_), settings.kappa);
    }

    Result run();

private:
    bool compute_step();
    Result finish(Status status, const std::string& message)
    {
        Result result = recorder_.finish(status, message, x_, factorization_);
        result.constraint_multipliers = settings_.kappa * penalty_.last_residuals();  // λ = κc̃, ∇f + Jᵀλ = ∇φ
        bounds_.multipliers(x_, grad_phi_, result.bound_multipliers_lower, result.bound_multipliers_upper);
        result.statistics["kappa"] = settings_.kappa;
        return result;
    }

    Nlp& nlp_;
    const SolverOptions& options_;
    RelaxedKktSettings settings_;
    const int n_, m_;
    AugmentedLagrangianFunction penalty_;  ///< φ = E + κ/2‖c̃‖² (λ = 0)
    ActiveBounds bounds_;
    KktMatrix kkt_;
    PatternMatrix schur_;
    RegularizedFactorization factorization_;
    InertiaCorrection schedule_;
    NewtonRecorder recorder_;
    VectorXd x_, grad_phi_, g_, jtc_, hv_, sv_, rhs_, solution_, trial_, step_;
    double phi_ = 0.0;
};

/// The Newton step of φ from the relaxed KKT matrix or its Schur complement.
bool RelaxedKktRun::compute_step()
{
    bounds_.update(x_, grad_phi_);
    const std::vector<char> fixed = bounds_.any() ? bounds_.fixed() : std::vector<char>{};
    const double kappa = settings_.kappa;
    recorder_.begin_assembly();
    if (settings_.schur)
        penalty_.hessian(x_, 1.0, VectorXd(), Projection::none, sv_);  // H + κJᵀJ
    else
        nlp_.hessian(x_, 1.0, kappa * penalty_.last_residuals(), Projection::none, hv_);
    recorder_.end_assembly();
    auto assemble_schur = [&](double delta_w, double) -> const SparseMatrix& {
        schur_.fill(sv_);
        schur_.shift_diagonal(delta_w);
        if (!fixed.empty())
            schur_.fix_variables(fixed);
        return schur_.matrix();
    };
    auto assemble_kkt = [&](double delta_w, double delta_c) -> const SparseMatrix& {
        return kkt_.fill(hv_, penalty_.last_jacobian(), -1.0, delta_w, 1.0 / kappa + delta_c, fixed);
    };
    const bool factorized =
        settings_.schur ? factorization_.factorize_with_inertia(assemble_schur, n_, 0, schedule_)
                        : factorization_.factorize_with_inertia(assemble_kkt, n_, m_, schedule_);
    if (!factorized)
        return false;
    if (settings_.schur) {
        rhs_.head(n_) = -grad_phi_;  // −(∇E + κJᵀc̃)
    } else {
        rhs_.head(n_) = -g_;  // −∇E
        rhs_.tail(m_) = penalty_.last_residuals();
    }
    for (size_t i = 0; i < fixed.size(); ++i)
        if (fixed[i])
            rhs_[static_cast<Eigen::Index>(i)] = 0.0;
    VectorXd rhs = settings_.schur ? VectorXd(rhs_.head(n_)) : rhs_;
    if (!factorization_.solve(rhs, solution_))
        return false;
    step_ = solution_.head(n_);
    return true;
}

Result RelaxedKktRun::run()
{
    x_ = nlp_.starting_point();
    bounds_.project(x_);
    phi_ = penalty_.objective(x_);
    recorder_.count_evaluation();
    if (!std::isfinite(phi_))
        return finish(Status::numerical_error, "objective not finite at the starting point");
    double step_norm = 0.0, alpha = 0.0;
    for (int iteration = 0;; ++iteration) {
        recorder_.begin_assembly();
        penalty_.gradient(x_, grad_phi_);
        recorder_.end_assembly();
        g_ = penalty_.last_objective_gradient();
        const double dual = bounds_.projected_gradient_norm(x_, grad_phi_);
        const double violation = m_ > 0 ? penalty_.last_residuals().cwiseAbs().maxCoeff() : 0.0;
        recorder_.record(iteration, penalty_.last_objective(), violation, dual, step_norm, alpha);
        if (dual <= options_.tolerance * std::max(1.0, g_.cwiseAbs().maxCoeff()))
            return finish(penalty_status(violation, options_.constraint_tolerance),
                          penalty_message(violation, settings_.kappa));
        if (iteration >= options_.max_iterations)
            return finish(Status::max_iterations, "iteration limit reached");
        recorder_.set_iterations(iteration + 1);
        if (!compute_step())
            return finish(Status::numerical_error, factorization_.failure());
        const double slope = grad_phi_.dot(step_);
        if (!(slope < 0.0))
            return finish(Status::stalled, "the Newton step is not a descent direction (round-off)");
        auto merit = [&](double a) {
            trial_ = x_ + a * step_;
            bounds_.project(trial_);
            recorder_.count_evaluation();
            return penalty_.objective(trial_);
        };
        const LineSearchOutcome search =
            backtracking_line_search(merit, phi_, slope, settings_.line_search, {});
        if (search.status == LineSearchStatus::stalled)
            return finish(Status::stalled, "no measurable decrease of E + kappa/2 |c|^2 along the step");
        if (search.status == LineSearchStatus::failed)
            return finish(Status::line_search_failed,
                          "no sufficient decrease after " + std::to_string(search.backtracks) + " halvings");
        if (step_below_roundoff(x_, trial_))
            return finish(Status::stalled, "the step is below the round-off of x");
        alpha = search.alpha;
        step_norm = (trial_ - x_).cwiseAbs().maxCoeff();
        x_ = trial_;
        phi_ = search.merit;
    }
}

class RelaxedKkt final : public Solver {
public:
    std::string name() const override { return "relaxed-kkt"; }
    std::string description() const override
    {
        return "Newton on E + kappa/2 |c|^2 through the relaxed KKT system (seed 004 4.3), LDL^T or Schur "
               "complement by CHOLMOD; bounds, equalities";
    }
    std::vector<OptionDeclaration> declared_options() const override { return relaxed_kkt_options(); }
    std::optional<std::string> refusal(const Nlp& nlp) const override { return refuse_inequalities(name(), nlp); }
    void check_options(const SolverOptions& options) const override { read_settings(options); }
    std::map<std::string, std::string> fixed_kappa_options(double kappa) const override
    {
        return {{"kappa", option_text(kappa)}};
    }
    Result run(Nlp& nlp, const SolverOptions& options) const override
    {
        return RelaxedKktRun(nlp, options, read_settings(options)).run();
    }
};

} // namespace

std::unique_ptr<Solver> make_relaxed_kkt_solver() { return std::make_unique<RelaxedKkt>(); }

} // namespace sinew
