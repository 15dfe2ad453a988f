#include "sinew/solvers/newton/projected_newton.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/core/parse_number.hpp"
#include "sinew/solvers/linear/linear_solver.hpp"
#include "sinew/solvers/newton/pattern_matrix.hpp"
#include "sinew/solvers/progress_log.hpp"

#include <chrono>
#include <cmath>

namespace sinew {
namespace {

using Clock = std::chrono::steady_clock;
using Eigen::VectorXd;

double seconds_since(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

struct NewtonSettings {
    std::string linear_solver = "cholmod";
    double armijo = 1e-4;
    int max_backtracks = 40;
};

NewtonSettings read_settings(const SolverOptions& options)
{
    NewtonSettings s;
    for (const auto& [key, value] : options.backend) {
        const std::string what = "projected-newton option " + key;
        if (key == "linear_solver")
            s.linear_solver = value;
        else if (key == "armijo")
            s.armijo = parse_finite_double(value, what);
        else if (key == "max_backtracks")
            s.max_backtracks = parse_int(value, what);
        else
            throw InputError("unknown projected-newton option '" + key +
                             "'; valid options: linear_solver, armijo, max_backtracks");
    }
    if (!(s.armijo > 0.0 && s.armijo < 0.5))
        throw InputError("projected-newton option armijo = " + format_number(s.armijo) + " must lie in (0, 0.5)");
    if (s.max_backtracks < 1)
        throw InputError("projected-newton option max_backtracks = " + std::to_string(s.max_backtracks) +
                         " must be at least 1");
    make_linear_solver(s.linear_solver);  // InputError naming the valid solvers
    return s;
}

class ProjectedNewton final : public Solver {
public:
    std::string name() const override { return "projected-newton"; }
    std::string description() const override
    {
        return "Newton on the exact Hessian near the solution, PSD-projected elsewhere, CHOLMOD, Armijo; "
               "unconstrained problems";
    }

    std::optional<std::string> refusal(const Nlp& nlp) const override
    {
        const NlpKind kind = classify(nlp);
        if (!kind.unconstrained())
            return "projected-newton takes unconstrained problems only (this one has " + kind.describe() +
                   "; eliminate Dirichlet conditions, or use ipopt)";
        return std::nullopt;
    }

    void check_options(const SolverOptions& options) const override { read_settings(options); }

    Result run(Nlp& nlp, const SolverOptions& options) const override
    {
        const NewtonSettings settings = read_settings(options);
        const auto start = Clock::now();
        const int n = nlp.num_variables();
        ProgressLog log(options, name(), nlp.name());
        Result result;
        auto linear = make_linear_solver(settings.linear_solver);
        PatternMatrix hessian(nlp.hessian_pattern(), n);
        VectorXd hessian_values(nlp.hessian_pattern().nonzeros());
        const VectorXd no_multipliers(0);
        const bool projected = nlp.has_projected_hessian();
        double assembly_s = 0.0, factorization_s = 0.0, linear_solve_s = 0.0;

        VectorXd x = nlp.starting_point(), gradient(n), step(n), alternative(n), trial(n), trial_gradient(n);
        bool trust_exact = false;    ///< the last step's ρ ≥ ½
        bool near_solution = false;  ///< the last step's predicted decrease was below round-off of f
        double kept_shift = 0.0;     ///< the shift the exact Hessian needed last time
        int projected_iterations = 0, factorizations = 0;
        double f = nlp.objective(x);
        result.function_evaluations = 1;
        auto finish = [&](Status status, const std::string& message) {
            result.status = status;
            result.message = message;
            result.x = x;
            result.linear_solves = linear->stats().solves;
            result.statistics = {{"assembly_s", assembly_s},
                              {"factorization_s", factorization_s},
                              {"linear_solve_s", linear_solve_s},
                              {"symbolic_analyses", linear->stats().symbolic_analyses},
                              {"projected_iterations", projected_iterations},
                              {"factorizations", factorizations}};
            return result;
        };
        if (!std::isfinite(f))
            return finish(Status::numerical_error, "objective not finite at the starting point");
        auto timed = Clock::now();
        nlp.gradient(x, gradient);
        assembly_s += seconds_since(timed);
        const double initial_gradient = gradient.cwiseAbs().maxCoeff();
        auto record = [&](int iteration, double step_norm, double alpha) {
            HistoryRow row;
            row.iteration = iteration;
            row.objective = f;
            row.dual_residual = gradient.cwiseAbs().maxCoeff();
            row.step_norm = step_norm;
            row.step_length = alpha;
            row.time_s = seconds_since(start);
            result.history.push_back(row);
            log.row(row);
        };
        record(0, 0.0, 0.0);

        for (int iteration = 1;; ++iteration) {
            const double gradient_norm = gradient.cwiseAbs().maxCoeff();
            if (gradient_norm <= options.tolerance * initial_gradient)
                return finish(Status::converged, "gradient reduced by tol");
            if (iteration > options.max_iterations)
                return finish(Status::max_iterations, "iteration limit reached");
            result.iterations = iteration;

            // H: the exact Hessian while its quadratic model predicted the
            // last step well (ρ ≥ ½, below), shifted by the multiple of I that
            // made it positive definite last time; the PSD projection the
            // problem offers (seed 000 §5.6) otherwise, and always at the
            // start. Per-element projection alone stiffens H where element
            // terms of opposite sign cancel in the sum, and then converges
            // only linearly; the exact Hessian alone overshoots far from the
            // solution (measurements in docs/solvers.md, "Projected Newton").
            const bool exact = !projected || trust_exact;
            timed = Clock::now();
            if (exact)
                nlp.hessian_values(x, 1.0, no_multipliers, hessian_values);
            else
                nlp.projected_hessian_values(x, hessian_values);
            hessian.fill(hessian_values);
            assembly_s += seconds_since(timed);
            const double diagonal_scale = std::max(1.0, hessian.matrix().diagonal().cwiseAbs().maxCoeff());
            if (!exact)
                ++projected_iterations;
            // Factorizes the H in `hessian` plus shift·I and solves H d = −∇f; an
            // H Cholesky rejects (indefinite, or a projection singular by
            // round-off) is shifted by a growing multiple of I. The shift used
            // goes back in `shift`; false with `failure` set when no shift works.
            std::string failure;
            auto solve_shifted = [&](double& shift, VectorXd& direction) {
                if (shift > 0.0)
                    hessian.shift_diagonal(shift);
                auto timed_here = Clock::now();
                LinearStatus factorized = linear->factorize(hessian.matrix());
                factorization_s += seconds_since(timed_here);
                ++factorizations;
                while (factorized == LinearStatus::not_positive_definite || factorized == LinearStatus::singular) {
                    const double next = shift == 0.0 ? 1e-8 * diagonal_scale : 10.0 * shift;
                    if (!std::isfinite(next) || next > 1e20)
                        break;
                    hessian.shift_diagonal(next - shift);
                    shift = next;
                    timed_here = Clock::now();
                    factorized = linear->factorize(hessian.matrix());
                    factorization_s += seconds_since(timed_here);
                    ++factorizations;
                }
                if (factorized != LinearStatus::ok) {
                    failure = "factorization failed: " + linear->last_message();
                    return false;
                }
                timed_here = Clock::now();
                const LinearStatus solved = linear->solve(-gradient, direction);
                linear_solve_s += seconds_since(timed_here);
                if (solved != LinearStatus::ok || !direction.allFinite()) {
                    failure = "linear solve failed: " + linear->last_message();
                    return false;
                }
                return true;
            };
            double shift = exact ? kept_shift : 0.0;
            if (!solve_shifted(shift, step))
                return finish(Status::numerical_error, failure);
            if (exact)
                kept_shift = shift;
            // The value at the full step, when already known (below).
            double f_full_step = kInfinity;
            bool full_step_known = false;
            // Near the solution (the last predicted decrease below round-off of f)
            // an exact H that needs a shift is indefinite at what should be a
            // minimum: e.g. a membrane in compression at an in-plane equilibrium,
            // whose out-of-plane stiffness is negative while ∇f has no
            // out-of-plane part. The shifted step then converges only linearly,
            // at the rate shift/(λ + shift) of H's small positive eigenvalues λ
            // (the codim sheet, docs/solvers.md). The projected H's step does not
            // see the negative directions; of the two full steps, the one with
            // the lower f is taken.
            if (exact && projected && shift > 0.0 && near_solution) {
                timed = Clock::now();
                nlp.projected_hessian_values(x, hessian_values);
                hessian.fill(hessian_values);
                assembly_s += seconds_since(timed);
                double projected_shift = 0.0;
                if (solve_shifted(projected_shift, alternative)) {
                    const double f_exact = nlp.objective(x + step);
                    const double f_projected = nlp.objective(x + alternative);
                    result.function_evaluations += 2;
                    full_step_known = true;
                    f_full_step = f_exact;
                    if (std::isfinite(f_projected) && !(f_exact <= f_projected)) {
                        step.swap(alternative);
                        f_full_step = f_projected;
                    }
                }
            }
            double slope = gradient.dot(step);
            if (!(slope < 0.0)) {
                step = -gradient;  // not a descent direction: steepest descent
                slope = -gradient.squaredNorm();
            }

            // Armijo backtracking: f(x + α d) ≤ f(x) + c₁ α ∇fᵀd, f finite.
            double alpha = 1.0;
            double f_trial = kInfinity;
            int backtracks = 0;
            for (;; ++backtracks) {
                trial = x + alpha * step;
                if (backtracks == 0 && full_step_known) {
                    f_trial = f_full_step;
                } else {
                    f_trial = nlp.objective(trial);
                    ++result.function_evaluations;
                }
                if (backtracks == 0)
                    f_full_step = f_trial;
                if (std::isfinite(f_trial) && f_trial <= f + settings.armijo * alpha * slope)
                    break;
                // Near the solution the decrease ½ ∇fᵀH⁻¹∇f falls below the
                // round-off of f: accept a step that keeps f within round-off
                // and reduces ‖∇f‖∞.
                if (std::isfinite(f_trial) && f_trial <= f + 1e-12 * std::abs(f)) {
                    nlp.gradient(trial, trial_gradient);
                    if (trial_gradient.cwiseAbs().maxCoeff() < gradient.cwiseAbs().maxCoeff())
                        break;
                }
                if (backtracks == settings.max_backtracks) {
                    // At round-off level f cannot decrease measurably: stop there.
                    if (std::isfinite(f_trial) && std::abs(f_trial - f) <= 1e-14 * std::max(1.0, std::abs(f)))
                        return finish(Status::stalled, "no measurable decrease of f along the Newton step");
                    return finish(Status::line_search_failed, "no sufficient decrease after " +
                                                                  std::to_string(backtracks) + " halvings");
                }
                alpha *= 0.5;
            }
            // ρ = actual / predicted decrease of the full step; the model
            // ½dᵀHd + ∇fᵀd with Hd = −∇f predicts −½∇fᵀd. Trust the exact
            // Hessian next when ρ ≥ ½; in exact mode also adapt the shift as a
            // Levenberg-Marquardt parameter: ×10 when ρ < ¼, ÷10 when ρ > ¾.
            // A predicted decrease below round-off of f leaves ρ meaningless;
            // that happens only near a solution, where the exact Hessian is
            // the one to use.
            const double predicted = -0.5 * slope;
            const bool measurable = predicted > 1e-11 * std::max(1.0, std::abs(f));
            const double rho = !measurable               ? 1.0
                               : std::isfinite(f_full_step) ? (f - f_full_step) / predicted
                                                            : -kInfinity;
            trust_exact = rho >= 0.5;
            near_solution = !measurable;
            if (!measurable)
                kept_shift = 0.0;  // near the solution: exact Newton, quadratic convergence
            else if (exact && rho < 0.25)
                kept_shift = kept_shift > 0.0 ? 10.0 * kept_shift : 0.0;
            else if (exact && rho > 0.75)
                kept_shift = kept_shift / 10.0 > 1e-8 * diagonal_scale ? kept_shift / 10.0 : 0.0;
            x.swap(trial);
            f = f_trial;
            timed = Clock::now();
            nlp.gradient(x, gradient);
            assembly_s += seconds_since(timed);
            record(iteration, alpha * step.cwiseAbs().maxCoeff(), alpha);
        }
    }
};

} // namespace

std::unique_ptr<Solver> make_projected_newton_solver() { return std::make_unique<ProjectedNewton>(); }

} // namespace sinew
