// Ipopt 3.11 through its C++ TNLP interface (Debian's coinor-libipopt-dev).
#include "sinew/solvers/backends/ipopt_solver.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/solvers/progress_log.hpp"

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>

namespace sinew {
namespace {

using Eigen::Map;
using Eigen::VectorXd;
using ConstMap = Map<const VectorXd>;

/// Ipopt treats bounds at or beyond ±1e19 as absent.
double to_ipopt_bound(double b) { return std::max(-1e20, std::min(1e20, b)); }

/// Adapts an Nlp to Ipopt's TNLP: both use the same sign convention for the
/// Lagrangian, σ∇²f + Σλᵢ∇²cᵢ, and lower-triangle Hessians.
class TnlpAdapter : public Ipopt::TNLP {
public:
    TnlpAdapter(Nlp& nlp, const SolverOptions& options, Result& result)
        : nlp_(nlp), log_(options, "ipopt", nlp.name()), result_(result), start_(std::chrono::steady_clock::now())
    {
    }

    /// Set when a callback threw: the reason, reported in Result::message.
    const std::string& callback_error() const { return callback_error_; }

    bool get_nlp_info(Ipopt::Index& n, Ipopt::Index& m, Ipopt::Index& nnz_jac_g, Ipopt::Index& nnz_h_lag,
                      IndexStyleEnum& index_style) override
    {
        n = nlp_.num_variables();
        m = nlp_.num_constraints();
        nnz_jac_g = nlp_.jacobian_pattern().nonzeros();
        nnz_h_lag = nlp_.hessian_pattern().nonzeros();
        index_style = C_STYLE;
        return true;
    }

    bool get_bounds_info(Ipopt::Index n, Ipopt::Number* x_l, Ipopt::Number* x_u, Ipopt::Index m,
                         Ipopt::Number* g_l, Ipopt::Number* g_u) override
    {
        return guarded([&] {
            Map<VectorXd> xl(x_l, n), xu(x_u, n), gl(g_l, m), gu(g_u, m);
            nlp_.variable_bounds(xl, xu);
            nlp_.constraint_bounds(gl, gu);
            xl = xl.unaryExpr(&to_ipopt_bound);
            xu = xu.unaryExpr(&to_ipopt_bound);
            gl = gl.unaryExpr(&to_ipopt_bound);
            gu = gu.unaryExpr(&to_ipopt_bound);
            return true;
        });
    }

    bool get_starting_point(Ipopt::Index n, bool init_x, Ipopt::Number* x, bool init_z, Ipopt::Number*,
                            Ipopt::Number*, Ipopt::Index, bool init_lambda, Ipopt::Number*) override
    {
        if (!init_x || init_z || init_lambda)
            return false;
        return guarded([&] {
            Map<VectorXd>(x, n) = nlp_.starting_point();
            return true;
        });
    }

    bool eval_f(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number& obj_value) override
    {
        return guarded([&] {
            obj_value = nlp_.objective(ConstMap(x, n));
            return std::isfinite(obj_value);  // false: Ipopt cuts the step back
        });
    }

    bool eval_grad_f(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number* grad_f) override
    {
        return guarded([&] {
            Map<VectorXd> g(grad_f, n);
            nlp_.gradient(ConstMap(x, n), g);
            return g.allFinite();
        });
    }

    bool eval_g(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Index m, Ipopt::Number* g) override
    {
        return guarded([&] {
            Map<VectorXd> c(g, m);
            nlp_.constraints(ConstMap(x, n), c);
            return c.allFinite();
        });
    }

    bool eval_jac_g(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Index, Ipopt::Index nele_jac,
                    Ipopt::Index* iRow, Ipopt::Index* jCol, Ipopt::Number* values) override
    {
        return guarded([&] {
            if (values == nullptr) {
                const SparsityPattern& pattern = nlp_.jacobian_pattern();
                std::copy(pattern.rows.begin(), pattern.rows.end(), iRow);
                std::copy(pattern.cols.begin(), pattern.cols.end(), jCol);
                return true;
            }
            Map<VectorXd> v(values, nele_jac);
            nlp_.jacobian_values(ConstMap(x, n), v);
            return v.allFinite();
        });
    }

    bool eval_h(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number obj_factor, Ipopt::Index m,
                const Ipopt::Number* lambda, bool, Ipopt::Index nele_hess, Ipopt::Index* iRow, Ipopt::Index* jCol,
                Ipopt::Number* values) override
    {
        return guarded([&] {
            if (values == nullptr) {
                const SparsityPattern& pattern = nlp_.hessian_pattern();
                std::copy(pattern.rows.begin(), pattern.rows.end(), iRow);
                std::copy(pattern.cols.begin(), pattern.cols.end(), jCol);
                return true;
            }
            Map<VectorXd> v(values, nele_hess);
            if (m > 0 && lambda != nullptr)
                nlp_.hessian(ConstMap(x, n), obj_factor, ConstMap(lambda, m), Projection::none, v);
            else
                nlp_.hessian(ConstMap(x, n), obj_factor, VectorXd::Zero(m), Projection::none, v);
            return v.allFinite();
        });
    }

    void finalize_solution(Ipopt::SolverReturn, Ipopt::Index n, const Ipopt::Number* x, const Ipopt::Number* z_L,
                           const Ipopt::Number* z_U, Ipopt::Index m, const Ipopt::Number*, const Ipopt::Number* lambda,
                           Ipopt::Number, const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override
    {
        result_.x = ConstMap(x, n);
        result_.bound_multipliers_lower = ConstMap(z_L, n);
        result_.bound_multipliers_upper = ConstMap(z_U, n);
        result_.constraint_multipliers = m > 0 ? VectorXd(ConstMap(lambda, m)) : VectorXd();
    }

    bool intermediate_callback(Ipopt::AlgorithmMode, Ipopt::Index iter, Ipopt::Number obj_value,
                               Ipopt::Number inf_pr, Ipopt::Number inf_du, Ipopt::Number, Ipopt::Number d_norm,
                               Ipopt::Number, Ipopt::Number, Ipopt::Number alpha_pr, Ipopt::Index,
                               const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override
    {
        HistoryRow row;
        row.iteration = iter;
        row.objective = obj_value;
        row.constraint_violation = inf_pr;
        row.dual_residual = inf_du;
        row.step_norm = iter == 0 ? 0.0 : d_norm;
        row.step_length = iter == 0 ? 0.0 : alpha_pr;
        row.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        result_.history.push_back(row);
        log_.row(row);
        return true;
    }

private:
    /// Runs a callback body; an exception becomes `false` (Ipopt then stops
    /// or backs off) with its reason kept for the result's message.
    template <typename Body>
    bool guarded(Body&& body)
    {
        try {
            return body();
        } catch (const std::exception& e) {
            if (callback_error_.empty())
                callback_error_ = e.what();
            return false;
        }
    }

    Nlp& nlp_;
    ProgressLog log_;
    Result& result_;
    std::chrono::steady_clock::time_point start_;
    std::string callback_error_;
};

/// Sets one Ipopt option from text: integer, then number, then string —
/// Ipopt's typed setters reject a wrong type or an unknown name.
void set_ipopt_option(Ipopt::OptionsList& list, const std::string& key, const std::string& value)
{
    if (key == "linear_solver" && value != "mumps")
        throw InputError("ipopt option linear_solver=" + value +
                         ": only mumps is available in Debian's Ipopt 3.11 (the HSL solvers fail or abort)");
    char* end = nullptr;
    const long as_long = std::strtol(value.c_str(), &end, 10);
    const bool is_int = !value.empty() && *end == '\0' && as_long >= std::numeric_limits<int>::min() &&
                        as_long <= std::numeric_limits<int>::max();
    if (is_int && list.SetIntegerValue(key, static_cast<int>(as_long)))
        return;
    const double as_double = std::strtod(value.c_str(), &end);
    const bool is_number = !value.empty() && *end == '\0';
    if (is_number && std::isfinite(as_double) && list.SetNumericValue(key, as_double))
        return;
    if (!is_number && list.SetStringValue(key, value))
        return;
    throw InputError("ipopt option '" + key + "=" + value +
                     "' was rejected by Ipopt: unknown option name or invalid value for it");
}

Status to_status(Ipopt::ApplicationReturnStatus s)
{
    switch (s) {
    case Ipopt::Solve_Succeeded:
    case Ipopt::Solved_To_Acceptable_Level:
    case Ipopt::Feasible_Point_Found:
        return Status::converged;
    case Ipopt::Maximum_Iterations_Exceeded: return Status::max_iterations;
    case Ipopt::Search_Direction_Becomes_Too_Small: return Status::stalled;
    case Ipopt::Infeasible_Problem_Detected: return Status::infeasible;
    case Ipopt::Restoration_Failed: return Status::line_search_failed;
    case Ipopt::Error_In_Step_Computation:
    case Ipopt::Invalid_Number_Detected:
        return Status::numerical_error;
    case Ipopt::Maximum_CpuTime_Exceeded:
    case Ipopt::User_Requested_Stop:
        return Status::user_stop;
    default: return Status::failed;
    }
}

std::string describe(Ipopt::ApplicationReturnStatus s)
{
    switch (s) {
    case Ipopt::Solve_Succeeded: return "Ipopt: optimal solution found";
    case Ipopt::Solved_To_Acceptable_Level: return "Ipopt: solved to acceptable level";
    case Ipopt::Feasible_Point_Found: return "Ipopt: feasible point found";
    case Ipopt::Infeasible_Problem_Detected: return "Ipopt: converged to a point of local infeasibility";
    case Ipopt::Search_Direction_Becomes_Too_Small: return "Ipopt: search direction becomes too small";
    case Ipopt::Diverging_Iterates: return "Ipopt: iterates diverging";
    case Ipopt::User_Requested_Stop: return "Ipopt: stopped by user request";
    case Ipopt::Maximum_Iterations_Exceeded: return "Ipopt: maximum number of iterations exceeded";
    case Ipopt::Restoration_Failed: return "Ipopt: restoration phase failed";
    case Ipopt::Error_In_Step_Computation: return "Ipopt: error in step computation";
    case Ipopt::Maximum_CpuTime_Exceeded: return "Ipopt: maximum CPU time exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom: return "Ipopt: problem has too few degrees of freedom";
    case Ipopt::Invalid_Problem_Definition: return "Ipopt: invalid problem definition";
    case Ipopt::Invalid_Option: return "Ipopt: invalid option";
    case Ipopt::Invalid_Number_Detected: return "Ipopt: invalid number (NaN or Inf) in an evaluation";
    case Ipopt::Insufficient_Memory: return "Ipopt: insufficient memory";
    default: return "Ipopt: failed with return status " + std::to_string(static_cast<int>(s));
    }
}

/// An Ipopt application with sinew's settings and the backend options set
/// and checked; InputError naming an option Ipopt rejects. A problem whose
/// Hessian is not exact (Nlp::exact_hessian) gets Ipopt's limited-memory
/// quasi-Newton mode unless the options choose otherwise.
Ipopt::SmartPtr<Ipopt::IpoptApplication> configured_application(const SolverOptions& options, bool exact_hessian)
{
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
    // Ipopt prints its own complaint about a rejected option on standard
    // output; the InputError below says it in one line. Its console comes
    // back, for verbosity 2, once every option is accepted.
    app->Jnlst()->DeleteAllJournals();
    Ipopt::OptionsList& list = *app->Options();
    // Silence needs both print_level 0 and sb (the banner); the table
    // comes from intermediate_callback through ProgressLog instead.
    list.SetIntegerValue("print_level", options.verbosity >= 2 ? 5 : 0);
    list.SetStringValue("sb", "yes");
    list.SetNumericValue("tol", options.tolerance);
    list.SetNumericValue("constr_viol_tol", options.constraint_tolerance);
    list.SetIntegerValue("max_iter", options.max_iterations);
    list.SetStringValue("hessian_approximation", exact_hessian ? "exact" : "limited-memory");
    for (const auto& [key, value] : options.backend)
        set_ipopt_option(list, key, value);
    if (options.verbosity >= 2)
        app->Jnlst()->AddFileJournal("console", "stdout", Ipopt::J_ITERSUMMARY);
    // Initialize("") skips ./ipopt.opt, which would override the options above.
    if (app->Initialize("") != Ipopt::Solve_Succeeded)
        throw InputError("ipopt: initialization failed (check the options passed to it)");
    return app;
}

class IpoptSolver : public Solver {
public:
    std::string name() const override { return "ipopt"; }
    std::string description() const override
    {
        return "Ipopt 3.11 interior point, MUMPS, exact Hessian; bounds, equalities, inequalities";
    }
    std::optional<std::string> refusal(const Nlp&) const override { return std::nullopt; }

    void check_options(const SolverOptions& options) const override { configured_application(options, true); }

    Result run(Nlp& nlp, const SolverOptions& options) const override
    {
        Result result;
        Ipopt::SmartPtr<Ipopt::IpoptApplication> app = configured_application(options, nlp.exact_hessian());
        Ipopt::SmartPtr<TnlpAdapter> adapter = new TnlpAdapter(nlp, options, result);
        const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(adapter));
        result.status = to_status(status);
        result.message = describe(status);
        if (!adapter->callback_error().empty()) {
            result.status = Status::numerical_error;
            result.message += "; evaluation failed: " + adapter->callback_error();
        }
        if (Ipopt::IsValid(app->Statistics())) {
            result.iterations = app->Statistics()->IterationCount();
            Ipopt::Index f = 0, grad = 0, c = 0, jac = 0, h = 0;
            app->Statistics()->NumberOfEvaluations(f, grad, c, jac, h);
            result.function_evaluations = f;
        } else {
            result.iterations = result.history.empty() ? 0 : static_cast<int>(result.history.size()) - 1;
        }
        if (result.x.size() != nlp.num_variables()) {
            // Ipopt stopped before finalize_solution (invalid problem, say).
            result.x = nlp.starting_point();
            result.constraint_multipliers.resize(0);
        }
        return result;
    }
};

} // namespace

std::unique_ptr<Solver> make_ipopt_solver() { return std::make_unique<IpoptSolver>(); }

} // namespace sinew
