#pragma once
#include "sinew/problems/nlp.hpp"
#include "sinew/runs/contact_summary.hpp"
#include "sinew/solvers/result.hpp"
#include "sinew/solvers/solver_options.hpp"

#include <Eigen/Core>

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sinew {

/// One column of a comparison: a solver, and for the strategies whose answer
/// depends on a constraint stiffness (relaxed-kkt, penalty) the κ it runs at.
struct ComparedStrategy {
    std::string label;              ///< "kkt-newton", "relaxed-kkt κ=1e4", …
    std::string solver;
    std::optional<double> kappa;    ///< penalty: one solve at this κ (no continuation)
    /// Empty: the subject's NLP. Otherwise another formulation the subject
    /// offers (ComparisonSubject::variants), by its name.
    std::string form;
    /// Backend options of this strategy, over the comparison's own.
    std::map<std::string, std::string> backend;
};

/// What is compared: a scene or an NLP, run afresh for every strategy.
struct ComparisonSubject {
    std::string name;
    double size = 1.0;   ///< the scene's bounding-box diagonal (1 for a plain NLP)
    int dimension = 1;   ///< coordinates per node of `positions` (1 for a plain NLP)
    /// A fresh NLP, for the solvers' refusals.
    std::function<std::unique_ptr<Nlp>()> make_nlp;
    /// One solve: the Result and the positions it reached, node-major (the
    /// scene's every node, prescribed ones included; x for a plain NLP).
    struct Outcome {
        Result result;
        Eigen::VectorXd positions;
        std::vector<std::string> notes;  ///< settings the run overrode or dropped
        std::vector<std::string> constraint_ranks;  ///< each constraint set's rank at the start (scenes)
        ContactSummary contact;  ///< contact with the scene's bodies at the end (present: the scene has some)
    };
    std::function<Outcome(const ComparedStrategy& strategy, const SolverOptions& options)> run;
    /// Strategies on formulations other than make_nlp()'s that the subject
    /// runs too (the rig: the seed's penalty form, rotation vectors).
    std::vector<ComparedStrategy> variants;
};

/// The strategies a comparison runs: each of `solvers` (empty: every solver)
/// that accepts the NLP, relaxed-kkt and penalty once per κ of `kappas`.
/// `refusals` receives "solver: reason" for each solver left out.
std::vector<ComparedStrategy> comparison_strategies(const Nlp& nlp, const std::vector<std::string>& solvers,
                                                    const std::vector<double>& kappas,
                                                    std::vector<std::string>& refusals);

/// The stiffness at which κ‖c‖² starts to weigh like the energy, at the
/// starting point x₀: max_i (∇²f)_ii / max_i (JᵀJ)_ii (the exact Hessian,
/// or its PSD projection where the NLP offers one). 1 when either is zero
/// or not finite (no constraints, a linear objective).
double kappa_scale(Nlp& nlp);

/// The default κ of a comparison: 10^(p+1), 10^(p+3), 10^(p+5) with
/// p = round(log10 kappa_scale), where the violation of the relaxed
/// strategies is past the pre-asymptotic regime and falls as 1/κ.
std::vector<double> default_kappas(Nlp& nlp);

/// κ as a label shows it: "1e4" for a power of ten, else "2.5e+06".
std::string kappa_text(double kappa);

/// The options a strategy runs with: `base` with the strategy's backend
/// options, plus κ for relaxed-kkt and for penalty a single solve at that κ
/// (kappa_growth = 1, no continuation).
SolverOptions strategy_options(const ComparedStrategy& strategy, const SolverOptions& base);

/// One strategy's run and how far it ended from the reference solution.
struct ComparisonRun {
    ComparedStrategy strategy;
    Result result;
    Eigen::VectorXd positions;
    /// max over nodes of ‖p_i − p_ref_i‖₂ (m for scenes); NaN without a reference.
    double reference_distance = std::numeric_limits<double>::quiet_NaN();
    ContactSummary contact;  ///< as the subject's Outcome reported it
};

struct Comparison {
    std::string subject;
    double size = 1.0;
    std::vector<ComparisonRun> runs;
    /// The run the distances are measured to: kkt-newton's when it
    /// converged, else Ipopt's when it converged; empty when neither did.
    std::string reference;
    double kappa_scale = 1.0;  ///< kappa_scale() of the subject's NLP
    std::vector<std::string> constraint_ranks;  ///< as the first run reported them
};

/// Called as the runs proceed: before a strategy (row null), on each of its
/// history rows, and after it (result set). `index` counts from 0.
struct ComparisonProgress {
    std::function<void(int index, int count, const ComparedStrategy&)> started;
    std::function<void(int index, int count, const ComparedStrategy&, const HistoryRow&)> iteration;
    std::function<void(int index, int count, const ComparedStrategy&, const ComparisonSubject::Outcome&)> finished;
};

/// Runs every strategy on the subject with the same base options (κ and the
/// strategy's own settings added), picks the reference and measures every
/// run's distance to it.
Comparison run_comparison(const ComparisonSubject& subject, const std::vector<ComparedStrategy>& strategies,
                          const SolverOptions& options, const ComparisonProgress& progress = {});

/// Least-squares slope of log y against log x over the points with finite
/// positive x and y: d log(violation) / d log(κ) is −1 when the violation
/// falls as 1/κ. NaN with fewer than two such points.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

/// The runs of one solver that carry a κ, in increasing κ.
std::vector<const ComparisonRun*> kappa_sweep(const Comparison& comparison, const std::string& solver);

} // namespace sinew
