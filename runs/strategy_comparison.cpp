#include "sinew/runs/strategy_comparison.hpp"

#include "sinew/solvers/solver.hpp"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sinew {
namespace {

} // namespace

std::string kappa_text(double kappa)
{
    const double p = std::round(std::log10(kappa));
    char text[32];
    if (std::pow(10.0, p) == kappa)
        std::snprintf(text, sizeof text, "1e%.0f", p);
    else
        std::snprintf(text, sizeof text, "%.3g", kappa);
    return text;
}

namespace {

std::string kappa_label(const std::string& solver, double kappa)
{
    return solver + " κ=" + kappa_text(kappa);
}

/// max_i ‖p_i − q_i‖₂ over nodes of `dimension` coordinates.
double max_nodal_distance(const Eigen::VectorXd& p, const Eigen::VectorXd& q, int dimension)
{
    if (p.size() != q.size() || p.size() == 0)
        return std::numeric_limits<double>::quiet_NaN();
    const Eigen::MatrixXd difference =
        Eigen::Map<const Eigen::MatrixXd>(p.data(), dimension, p.size() / dimension) -
        Eigen::Map<const Eigen::MatrixXd>(q.data(), dimension, q.size() / dimension);
    return difference.colwise().norm().maxCoeff();
}

/// The index of the first converged run of `solver`, or −1.
int converged_run(const std::vector<ComparisonRun>& runs, const std::string& solver)
{
    for (size_t k = 0; k < runs.size(); ++k)
        if (runs[k].strategy.solver == solver && runs[k].result.status == Status::converged)
            return static_cast<int>(k);
    return -1;
}

} // namespace

double kappa_scale(Nlp& nlp)
{
    const int n = nlp.num_variables(), m = nlp.num_constraints();
    if (m == 0 || n == 0)
        return 1.0;
    const Eigen::VectorXd x = nlp.starting_point();
    const SparsityPattern& hp = nlp.hessian_pattern();
    Eigen::VectorXd h(hp.nonzeros());
    const Projection projection = nlp.supports(Projection::clamp) ? Projection::clamp : Projection::none;
    nlp.hessian(x, 1.0, Eigen::VectorXd::Zero(m), projection, h);
    Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < hp.nonzeros(); ++k)
        if (hp.rows[static_cast<size_t>(k)] == hp.cols[static_cast<size_t>(k)])
            diagonal[hp.rows[static_cast<size_t>(k)]] += h[k];
    const SparsityPattern& jp = nlp.jacobian_pattern();
    Eigen::VectorXd j(jp.nonzeros());
    nlp.jacobian_values(x, j);
    std::vector<Eigen::Triplet<double>> entries;
    for (int k = 0; k < jp.nonzeros(); ++k)
        entries.emplace_back(jp.rows[static_cast<size_t>(k)], jp.cols[static_cast<size_t>(k)], j[k]);
    Eigen::SparseMatrix<double> jacobian(m, n);
    jacobian.setFromTriplets(entries.begin(), entries.end());
    double jtj = 0.0;  // max_i (JᵀJ)_ii = max_i ‖J e_i‖²
    for (int i = 0; i < n; ++i)
        jtj = std::max(jtj, jacobian.col(i).squaredNorm());
    const double scale = diagonal.maxCoeff() / jtj;
    return std::isfinite(scale) && scale > 0 ? scale : 1.0;
}

std::vector<double> default_kappas(Nlp& nlp)
{
    const double p = std::round(std::log10(kappa_scale(nlp)));
    return {std::pow(10.0, p + 1), std::pow(10.0, p + 3), std::pow(10.0, p + 5)};
}

SolverOptions strategy_options(const ComparedStrategy& strategy, const SolverOptions& base)
{
    SolverOptions options = base;
    for (const auto& [key, value] : strategy.backend)
        options.backend[key] = value;
    if (strategy.kappa)
        for (const auto& [key, value] : find_solver(strategy.solver).fixed_kappa_options(*strategy.kappa))
            options.backend[key] = value;
    return options;
}

std::vector<ComparedStrategy> comparison_strategies(const Nlp& nlp, const std::vector<std::string>& solvers,
                                                    const std::vector<double>& kappas,
                                                    std::vector<std::string>& refusals)
{
    std::vector<ComparedStrategy> strategies;
    for (const auto& solver : all_solvers()) {
        const std::string name = solver->name();
        if (!solvers.empty() && std::find(solvers.begin(), solvers.end(), name) == solvers.end())
            continue;
        if (const auto why = solver->refusal(nlp)) {
            refusals.push_back(name + ": " + *why);
            continue;
        }
        if (!takes_kappa(*solver)) {
            strategies.push_back({name, name, std::nullopt, {}, {}});
            continue;
        }
        for (double kappa : kappas)
            strategies.push_back({kappa_label(name, kappa), name, kappa, {}, {}});
    }
    return strategies;
}

Comparison run_comparison(const ComparisonSubject& subject, const std::vector<ComparedStrategy>& strategies,
                          const SolverOptions& options, const ComparisonProgress& progress)
{
    Comparison comparison;
    comparison.subject = subject.name;
    comparison.size = subject.size;
    comparison.kappa_scale = kappa_scale(*subject.make_nlp());
    const int count = static_cast<int>(strategies.size());
    for (int k = 0; k < count; ++k) {
        const ComparedStrategy& strategy = strategies[static_cast<size_t>(k)];
        if (progress.started)
            progress.started(k, count, strategy);
        SolverOptions run_options = strategy_options(strategy, options);
        if (progress.iteration)
            run_options.on_iteration = [&](const HistoryRow& row) { progress.iteration(k, count, strategy, row); };
        ComparisonSubject::Outcome outcome = subject.run(strategy, run_options);
        if (progress.finished)
            progress.finished(k, count, strategy, outcome);
        if (k == 0)
            comparison.constraint_ranks = outcome.constraint_ranks;
        ComparisonRun run;
        run.strategy = strategy;
        run.result = std::move(outcome.result);
        run.positions = std::move(outcome.positions);
        run.contact = outcome.contact;
        comparison.runs.push_back(std::move(run));
    }
    int reference = converged_run(comparison.runs, "kkt-newton");
    if (reference < 0)
        reference = converged_run(comparison.runs, "ipopt");
    if (reference >= 0) {
        const ComparisonRun& ref = comparison.runs[static_cast<size_t>(reference)];
        comparison.reference = ref.strategy.label;
        for (ComparisonRun& run : comparison.runs)
            run.reference_distance = max_nodal_distance(run.positions, ref.positions, subject.dimension);
    }
    return comparison;
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y)
{
    std::vector<std::pair<double, double>> points;
    for (size_t i = 0; i < std::min(x.size(), y.size()); ++i)
        if (std::isfinite(x[i]) && std::isfinite(y[i]) && x[i] > 0 && y[i] > 0)
            points.emplace_back(std::log(x[i]), std::log(y[i]));
    if (points.size() < 2)
        return std::numeric_limits<double>::quiet_NaN();
    double mean_x = 0, mean_y = 0;
    for (const auto& [u, v] : points) {
        mean_x += u / static_cast<double>(points.size());
        mean_y += v / static_cast<double>(points.size());
    }
    double sxy = 0, sxx = 0;
    for (const auto& [u, v] : points) {
        sxy += (u - mean_x) * (v - mean_y);
        sxx += (u - mean_x) * (u - mean_x);
    }
    return sxx > 0 ? sxy / sxx : std::numeric_limits<double>::quiet_NaN();
}

std::vector<const ComparisonRun*> kappa_sweep(const Comparison& comparison, const std::string& solver)
{
    std::vector<const ComparisonRun*> sweep;
    for (const ComparisonRun& run : comparison.runs)
        if (run.strategy.solver == solver && run.strategy.kappa)
            sweep.push_back(&run);
    std::sort(sweep.begin(), sweep.end(),
              [](const ComparisonRun* a, const ComparisonRun* b) { return *a->strategy.kappa < *b->strategy.kappa; });
    return sweep;
}

} // namespace sinew
