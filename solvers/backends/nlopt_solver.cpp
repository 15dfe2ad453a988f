// NLopt 2.7 gradient-based algorithms through its C++ interface.
#include "sinew/solvers/backends/nlopt_solver.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/core/parse_number.hpp"
#include "sinew/solvers/progress_log.hpp"

#include <nlopt.hpp>

#include <chrono>
#include <cmath>
#include <exception>
#include <limits>

namespace sinew {
namespace {

using Eigen::Map;
using Eigen::VectorXd;

/// What an NLopt algorithm accepts.
struct Capabilities {
    bool bounds;
    bool equalities;
    bool inequalities;
    /// Largest n accepted; 0 for no limit. SLSQP keeps a dense n×n
    /// quasi-Newton matrix and solves a dense QP per iteration (O(n³)).
    int max_variables = 0;
    /// Refuse problems without inequality constraints. NLopt's MMA and CCSAQ
    /// converge linearly on them: 3000 evaluations leave Rosenbrock at
    /// f = 3.5e-6 (n = 2) and 5.6e-3 (n = 1000); nlopt-lbfgs takes 56.
    bool needs_inequalities = false;
    /// Refuse problems without constraints: AUGLAG then runs its inner
    /// LD_LBFGS once, the same run as nlopt-lbfgs.
    bool needs_constraints = false;
};

/// The constraints of an Nlp in NLopt's form: h(x) = 0 and q(x) <= 0.
/// Equalities cᵢ − g_Lᵢ; inequalities cᵢ − g_Uᵢ and g_Lᵢ − cᵢ for each finite side.
struct ConstraintRows {
    struct Row {
        int index;    ///< constraint i of the Nlp
        double sign;  ///< +1: cᵢ − bound, −1: bound − cᵢ
        double bound;
    };
    std::vector<Row> equalities;
    std::vector<Row> inequalities;
};

ConstraintRows split_constraints(const Nlp& nlp)
{
    const int m = nlp.num_constraints();
    VectorXd gl(m), gu(m);
    nlp.constraint_bounds(gl, gu);
    ConstraintRows rows;
    for (int i = 0; i < m; ++i) {
        if (gl[i] == gu[i]) {
            rows.equalities.push_back({i, 1.0, gl[i]});
            continue;
        }
        if (is_finite_bound(gu[i]))
            rows.inequalities.push_back({i, 1.0, gu[i]});
        if (is_finite_bound(gl[i]))
            rows.inequalities.push_back({i, -1.0, gl[i]});
    }
    return rows;
}

/// Everything the C callbacks need; exceptions never cross into NLopt's C
/// code: the reason is recorded and the optimization is forced to stop.
class NloptBridge {
public:
    NloptBridge(Nlp& nlp, const SolverOptions& options, const std::string& solver, Result& result)
        : nlp_(nlp), log_(options, solver, nlp.name()), result_(result), rows_(split_constraints(nlp)),
          start_(std::chrono::steady_clock::now()), n_(nlp.num_variables()), m_(nlp.num_constraints()),
          c_(m_), jacobian_(nlp.jacobian_pattern().nonzeros()), gradient_(n_), x_lower_(n_), x_upper_(n_)
    {
        nlp.variable_bounds(x_lower_, x_upper_);
    }

    const ConstraintRows& rows() const { return rows_; }
    const std::string& error() const { return error_; }
    int gradient_evaluations() const { return gradient_evaluations_; }
    /// The last point where f and ∇f were evaluated: the final iterate of
    /// these gradient methods (their line searches and inner loops end on
    /// the point they accept).
    const VectorXd& last_iterate() const { return previous_x_; }

    /// f(x) and ∇f; one history row per evaluation with a gradient.
    double objective(const std::vector<double>& x, std::vector<double>& grad)
    {
        return guarded(0.0, [&] {
            const Map<const VectorXd> xv(x.data(), n_);
            const double f = nlp_.objective(xv);
            if (!grad.empty()) {
                Map<VectorXd> g(grad.data(), n_);
                nlp_.gradient(xv, g);
                record(xv, f, g);
            }
            return f;
        });
    }

    /// result[r] = sign·(c_i − bound) for the rows; grad is rows × n, row-major.
    void constraints(const std::vector<ConstraintRows::Row>& rows, unsigned count, double* out, unsigned n,
                     const double* x, double* grad)
    {
        guarded(0.0, [&] {
            const Map<const VectorXd> xv(x, n);
            nlp_.constraints(xv, c_);
            for (unsigned r = 0; r < count; ++r)
                out[r] = rows[r].sign * (c_[rows[r].index] - rows[r].bound);
            if (grad) {
                std::fill(grad, grad + static_cast<size_t>(count) * n, 0.0);
                row_of_constraint_.assign(static_cast<size_t>(m_), {});
                for (unsigned r = 0; r < count; ++r)
                    row_of_constraint_[static_cast<size_t>(rows[r].index)].push_back(r);
                nlp_.jacobian_values(xv, jacobian_);
                const SparsityPattern& pattern = nlp_.jacobian_pattern();
                for (int k = 0; k < pattern.nonzeros(); ++k)
                    for (unsigned r : row_of_constraint_[static_cast<size_t>(pattern.rows[k])])
                        grad[static_cast<size_t>(r) * n + static_cast<size_t>(pattern.cols[k])] +=
                            rows[r].sign * jacobian_[k];
            }
            return 0.0;
        });
    }

private:
    template <typename Body>
    double guarded(double fallback, Body&& body)
    {
        try {
            return body();
        } catch (const std::exception& e) {
            if (error_.empty())
                error_ = e.what();
            throw nlopt::forced_stop();
        }
        return fallback;
    }

    void record(const Map<const VectorXd>& x, double f, const Map<VectorXd>& g)
    {
        HistoryRow row;
        row.iteration = gradient_evaluations_++;
        row.objective = f;
        row.constraint_violation = max_constraint_violation(nlp_, x);
        // Without general constraints the projected gradient is NLopt's
        // stationarity measure; with them NLopt exposes no multipliers.
        row.dual_residual = std::numeric_limits<double>::quiet_NaN();
        if (m_ == 0) {
            double worst = 0.0;
            for (int j = 0; j < n_; ++j) {
                const bool blocked_down = g[j] > 0.0 && x[j] <= x_lower_[j];
                const bool blocked_up = g[j] < 0.0 && x[j] >= x_upper_[j];
                if (!blocked_down && !blocked_up)
                    worst = std::max(worst, std::abs(g[j]));
            }
            row.dual_residual = worst;
        }
        if (has_previous_) {
            row.step_norm = (x - previous_x_).cwiseAbs().maxCoeff();
            row.step_length = std::numeric_limits<double>::quiet_NaN();
        }
        previous_x_ = x;
        has_previous_ = true;
        row.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        result_.history.push_back(row);
        log_.row(row);
    }

    Nlp& nlp_;
    ProgressLog log_;
    Result& result_;
    ConstraintRows rows_;
    std::chrono::steady_clock::time_point start_;
    int n_, m_;
    VectorXd c_, jacobian_, gradient_, x_lower_, x_upper_, previous_x_;
    bool has_previous_ = false;
    std::vector<std::vector<unsigned>> row_of_constraint_;
    int gradient_evaluations_ = 0;
    std::string error_;
};

double objective_callback(const std::vector<double>& x, std::vector<double>& grad, void* data)
{
    return static_cast<NloptBridge*>(data)->objective(x, grad);
}

void equality_callback(unsigned m, double* result, unsigned n, const double* x, double* grad, void* data)
{
    auto* bridge = static_cast<NloptBridge*>(data);
    bridge->constraints(bridge->rows().equalities, m, result, n, x, grad);
}

void inequality_callback(unsigned m, double* result, unsigned n, const double* x, double* grad, void* data)
{
    auto* bridge = static_cast<NloptBridge*>(data);
    bridge->constraints(bridge->rows().inequalities, m, result, n, x, grad);
}

Status to_status(nlopt::result r)
{
    switch (r) {
    case nlopt::SUCCESS:
    case nlopt::STOPVAL_REACHED:
    case nlopt::FTOL_REACHED:
    case nlopt::XTOL_REACHED:
    case nlopt::ROUNDOFF_LIMITED:  // in practice after convergence: the tolerance check decides
        return Status::converged;
    case nlopt::MAXEVAL_REACHED: return Status::max_iterations;
    case nlopt::MAXTIME_REACHED: return Status::user_stop;
    case nlopt::FORCED_STOP: return Status::numerical_error;
    default: return Status::failed;
    }
}

std::string describe(nlopt::result r)
{
    switch (r) {
    case nlopt::SUCCESS: return "NLopt: success";
    case nlopt::STOPVAL_REACHED: return "NLopt: stopval reached";
    case nlopt::FTOL_REACHED: return "NLopt: ftol reached";
    case nlopt::XTOL_REACHED: return "NLopt: xtol reached";
    case nlopt::MAXEVAL_REACHED: return "NLopt: maximum evaluations reached";
    case nlopt::MAXTIME_REACHED: return "NLopt: maximum time reached";
    case nlopt::ROUNDOFF_LIMITED: return "NLopt: roundoff limited";
    case nlopt::FORCED_STOP: return "NLopt: forced stop";
    case nlopt::OUT_OF_MEMORY: return "NLopt: out of memory";
    case nlopt::INVALID_ARGS: return "NLopt: invalid arguments";
    default: return "NLopt: failure";
    }
}

/// Backend options sinew understands for NLopt, by name.
struct NloptSettings {
    double ftol_rel, ftol_abs = 0.0, xtol_rel, xtol_abs = 0.0, maxtime = 0.0;
    int vector_storage = 0;
};

NloptSettings read_settings(const std::string& solver, const SolverOptions& options)
{
    NloptSettings s;
    s.ftol_rel = options.tolerance;
    s.xtol_rel = options.tolerance;
    for (const auto& [key, value] : options.backend) {
        const std::string what = solver + " option " + key;
        // Every setting is a tolerance, a time or a count: 0 turns it off,
        // a negative value is a mistake (NLopt itself would take it silently).
        const std::string& text = value;  // a structured binding; lambdas capture it by name from C++20 on
        const auto non_negative = [&](double number) {
            if (number < 0.0)
                throw InputError(what + " = " + text + " is invalid; it must be at least 0 (0: off)");
            return number;
        };
        if (key == "ftol_rel")
            s.ftol_rel = non_negative(parse_finite_double(value, what));
        else if (key == "ftol_abs")
            s.ftol_abs = non_negative(parse_finite_double(value, what));
        else if (key == "xtol_rel")
            s.xtol_rel = non_negative(parse_finite_double(value, what));
        else if (key == "xtol_abs")
            s.xtol_abs = non_negative(parse_finite_double(value, what));
        else if (key == "maxtime")
            s.maxtime = non_negative(parse_finite_double(value, what));
        else if (key == "vector_storage")
            s.vector_storage = static_cast<int>(non_negative(parse_int(value, what)));
        else
            throw InputError("unknown " + solver +
                             " option '" + key + "'; valid options: ftol_rel, ftol_abs, xtol_rel, xtol_abs, "
                             "maxtime, vector_storage");
    }
    return s;
}

void apply(nlopt::opt& opt, const NloptSettings& s, int max_evaluations)
{
    opt.set_ftol_rel(s.ftol_rel);
    opt.set_ftol_abs(s.ftol_abs);
    opt.set_xtol_rel(s.xtol_rel);
    opt.set_xtol_abs(s.xtol_abs);
    opt.set_maxeval(max_evaluations);
    if (s.maxtime > 0.0)
        opt.set_maxtime(s.maxtime);
    if (s.vector_storage > 0)
        opt.set_vector_storage(static_cast<unsigned>(s.vector_storage));
}

class NloptSolver : public Solver {
public:
    NloptSolver(std::string name, nlopt::algorithm algorithm, Capabilities can, std::string description)
        : name_(std::move(name)), algorithm_(algorithm), can_(can), description_(std::move(description))
    {
    }

    std::string name() const override { return name_; }
    std::string description() const override { return description_; }

    std::optional<std::string> refusal(const Nlp& nlp) const override
    {
        const NlpCapabilities kind = capabilities_of(nlp);
        if (kind.has_equalities && !can_.equalities)
            return name_ + " takes no equality constraints";
        // NLopt throws std::invalid_argument ("too many equality constraints") otherwise.
        if (kind.num_equalities > nlp.num_variables())
            return name_ + " takes at most as many equality constraints as variables (this problem has " +
                   std::to_string(kind.num_equalities) + " on " + std::to_string(nlp.num_variables()) + ")";
        if (kind.has_inequalities && !can_.inequalities)
            return name_ + " takes no inequality constraints";
        if (kind.has_bounds && !can_.bounds)
            return name_ + " takes no bounds";
        if (can_.needs_constraints && !kind.has_equalities && !kind.has_inequalities)
            return name_ + " without constraints is its inner LD_LBFGS alone; use nlopt-lbfgs";
        if (can_.needs_inequalities && !kind.has_inequalities)
            return name_ + " is meant for inequality-constrained problems and converges only linearly without "
                           "them; use nlopt-lbfgs or ipopt";
        if (can_.max_variables > 0 && nlp.num_variables() > can_.max_variables)
            return name_ + " is a dense method and takes at most " + std::to_string(can_.max_variables) +
                   " variables (this problem has " + std::to_string(nlp.num_variables()) + ")";
        return std::nullopt;
    }

    void check_options(const SolverOptions& options) const override { read_settings(name_, options); }

    Result run(Nlp& nlp, const SolverOptions& options) const override
    {
        const NloptSettings settings = read_settings(name_, options);
        const unsigned n = static_cast<unsigned>(nlp.num_variables());
        Result result;
        NloptBridge bridge(nlp, options, name_, result);

        nlopt::opt opt(algorithm_, n);
        apply(opt, settings, options.max_iterations);
        if (algorithm_ == nlopt::AUGLAG) {
            // The local optimizer is copied by set_local_optimizer: set its
            // tolerances first.
            nlopt::opt local(nlopt::LD_LBFGS, n);
            apply(local, settings, options.max_iterations);
            opt.set_local_optimizer(local);
        }

        VectorXd lower(n), upper(n);
        nlp.variable_bounds(lower, upper);
        opt.set_lower_bounds(std::vector<double>(lower.data(), lower.data() + n));
        opt.set_upper_bounds(std::vector<double>(upper.data(), upper.data() + n));
        opt.set_min_objective(objective_callback, &bridge);
        const auto& rows = bridge.rows();
        if (!rows.equalities.empty())
            opt.add_equality_mconstraint(equality_callback, &bridge,
                                         std::vector<double>(rows.equalities.size(), options.constraint_tolerance));
        if (!rows.inequalities.empty())
            opt.add_inequality_mconstraint(
                inequality_callback, &bridge,
                std::vector<double>(rows.inequalities.size(), options.constraint_tolerance));

        // NLopt rejects a starting point outside the bounds; Ipopt moves it
        // inside itself. Project it onto the box so both start alike.
        const VectorXd x0 = nlp.starting_point().cwiseMax(lower).cwiseMin(upper);
        std::vector<double> x(x0.data(), x0.data() + n);
        double f = 0.0;
        nlopt::result code = nlopt::FAILURE;
        try {
            code = opt.optimize(x, f);
        } catch (const nlopt::roundoff_limited&) {
            code = nlopt::ROUNDOFF_LIMITED;  // x and f hold the best point found
        } catch (const nlopt::forced_stop&) {
            code = nlopt::FORCED_STOP;
        } catch (const std::runtime_error&) {
            code = opt.last_optimize_result();
        }
        result.status = to_status(code);
        result.message = describe(code);
        if (!bridge.error().empty())
            result.message += "; evaluation failed: " + bridge.error();
        // NLopt returns the lowest f among the points within its constraint
        // tolerance, which after convergence is often a slightly infeasible
        // early point below f* (measured in docs/solvers.md, "NLopt"). On a
        // successful stop the answer is the final iterate; otherwise NLopt's
        // best point.
        if (result.status == Status::converged && bridge.last_iterate().size() == n)
            result.x = bridge.last_iterate();
        else
            result.x = Map<const VectorXd>(x.data(), n);
        result.iterations = bridge.gradient_evaluations();
        result.function_evaluations = opt.get_numevals();
        return result;
    }

private:
    std::string name_;
    nlopt::algorithm algorithm_;
    Capabilities can_;
    std::string description_;
};

} // namespace

std::vector<std::unique_ptr<Solver>> make_nlopt_solvers()
{
    std::vector<std::unique_ptr<Solver>> solvers;
    solvers.push_back(std::make_unique<NloptSolver>(
        "nlopt-slsqp", nlopt::LD_SLSQP, Capabilities{true, true, true, 200},
        "NLopt LD_SLSQP sequential quadratic programming (dense BFGS, n <= 200); bounds, equalities, inequalities"));
    solvers.push_back(std::make_unique<NloptSolver>(
        "nlopt-mma", nlopt::LD_MMA, Capabilities{true, false, true, 0, true},
        "NLopt LD_MMA method of moving asymptotes; bounds, inequalities (at least one)"));
    solvers.push_back(std::make_unique<NloptSolver>(
        "nlopt-ccsaq", nlopt::LD_CCSAQ, Capabilities{true, false, true, 0, true},
        "NLopt LD_CCSAQ conservative convex separable quadratic approximations; bounds, inequalities (at least one)"));
    solvers.push_back(std::make_unique<NloptSolver>(
        "nlopt-lbfgs", nlopt::LD_LBFGS, Capabilities{true, false, false},
        "NLopt LD_LBFGS limited-memory BFGS; bounds only"));
    solvers.push_back(std::make_unique<NloptSolver>(
        "nlopt-auglag", nlopt::AUGLAG, Capabilities{true, true, true, 0, false, true},
        "NLopt AUGLAG augmented Lagrangian around LD_LBFGS; bounds, equalities, inequalities"));
    return solvers;
}

} // namespace sinew
