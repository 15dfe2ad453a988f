#pragma once
#include "sinew/problems/nlp.hpp"
#include "sinew/solvers/declared_options.hpp"
#include "sinew/solvers/result.hpp"
#include "sinew/solvers/solver_options.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sinew {

/// A strategy that solves an Nlp. Implementations know nothing of physics.
class Solver {
public:
    virtual ~Solver() = default;
    virtual std::string name() const = 0;
    virtual std::string description() const = 0;
    /// The backend options this solver declares (DESIGN.md, "Options"); empty
    /// for backends that take their own options by name (Ipopt, NLopt).
    virtual std::vector<OptionDeclaration> declared_options() const { return {}; }
    /// The options of nested solvers by prefix ("inner" → the subproblem
    /// solver's declarations, given as inner.name=value).
    virtual std::map<std::string, std::vector<OptionDeclaration>> nested_options() const { return {}; }
    /// Why this solver cannot handle `nlp` (e.g. "LBFGS does not take
    /// constraints"), or nothing when it can.
    virtual std::optional<std::string> refusal(const Nlp& nlp) const = 0;
    /// Throws InputError naming the first invalid backend option (its name
    /// and value) without solving anything; run() accepts what this accepts.
    virtual void check_options(const SolverOptions& options) const = 0;
    /// Runs the solve. Does not throw for a solve that fails to converge: the
    /// status says so. Throws InputError for invalid options.
    virtual Result run(Nlp& nlp, const SolverOptions& options) const = 0;
    /// A strategy whose answer is a function of a stiffness κ (relaxed KKT,
    /// penalty) gives the backend options that solve at that one κ;
    /// comparisons run it once per κ. Empty for every other solver.
    virtual std::map<std::string, std::string> fixed_kappa_options(double kappa) const
    {
        static_cast<void>(kappa);
        return {};
    }
};

/// The backend options text of a number, every digit kept.
std::string option_text(double value);
/// Whether `solver` declares fixed_kappa_options (any κ > 0 gives some).
bool takes_kappa(const Solver& solver);

/// Every solver sinew has, in a fixed order.
const std::vector<std::unique_ptr<Solver>>& all_solvers();

/// The solver called `name`; InputError listing the valid names otherwise.
const Solver& find_solver(const std::string& name);

/// Everything solve() checks before it starts, for callers that must refuse
/// bad input before they write anything: the common options, the solver's
/// name, its backend options, and whether it accepts `nlp`. InputError when
/// one fails.
void check_solve(const Nlp& nlp, const std::string& solver, const SolverOptions& options);

/// Solves `nlp` with the named solver: refuses (InputError) a problem of a kind
/// the solver cannot handle, then measures the result uniformly — objective,
/// constraint violation, KKT residual (estimating multipliers when the backend
/// gives none) — and reports converged only when every tolerance holds.
Result solve(Nlp& nlp, const std::string& solver, const SolverOptions& options);

} // namespace sinew
