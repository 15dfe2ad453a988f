#include "sinew/problems/taylor_test.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/problems/derivative_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <random>
#include <sstream>
#include <utility>

namespace sinew {
namespace {

using Eigen::VectorXd;

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// Halvings of h0 (or of a point's perturbation) tried while f is not finite.
constexpr int kMaxShrinks = 40;

/// f, ∇f, c and J at one point; only f when f is not finite.
struct FirstOrder {
    double f = kNaN;
    VectorXd grad, c, jac;  // jac: values in jacobian_pattern() order
};

/// Everything one series from a point needs about that point.
struct Base {
    VectorXd x;
    FirstOrder at;
    VectorXd lagrangian_grad;  ///< σ∇f + Jᵀλ
    VectorXd hessian;          ///< ∇²L values in hessian_pattern() order
    double grad_x = 0.0;       ///< |∇f|ᵀ|x|, ‖|J||x|‖ and ‖|∇²L||x|‖, for round-off estimates
    double jac_x = 0.0;
    double hess_x = 0.0;
};

/// A direction d and the first-order models' slopes along it.
struct Directional {
    VectorXd d;
    double grad_d;  ///< ∇fᵀd
    VectorXd jac_d;   ///< J d
    VectorXd hess_d;  ///< ∇²L d
};

/// What every series of one run shares.
struct Context {
    Nlp& nlp;
    const TaylorOptions& options;
    VectorXd lambda;
    std::mt19937 rng;
};

VectorXd uniform_vector(std::mt19937& rng, Eigen::Index size)
{
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    VectorXd v(size);
    for (Eigen::Index i = 0; i < size; ++i)
        v[i] = uniform(rng);
    return v;
}

/// max(1, |x_i|): the scale of a step in x_i.
VectorXd step_scale(const VectorXd& x) { return x.cwiseAbs().cwiseMax(1.0); }

/// y = M v for M given by a triplet pattern (repeated entries add up); with
/// `symmetric` the pattern is a lower triangle standing for the whole matrix.
/// With `absolute`, |M| |v| instead (for round-off estimates).
VectorXd multiply(const SparsityPattern& pattern, const VectorXd& values, const VectorXd& v, int rows, bool symmetric,
                  bool absolute = false)
{
    VectorXd y = VectorXd::Zero(rows);
    for (int k = 0; k < pattern.nonzeros(); ++k) {
        const int r = pattern.rows[k], c = pattern.cols[k];
        const double a = absolute ? std::abs(values[k]) : values[k];
        y[r] += a * (absolute ? std::abs(v[c]) : v[c]);
        if (symmetric && r != c)
            y[c] += a * (absolute ? std::abs(v[r]) : v[r]);
    }
    return y;
}

/// f at x and, when it is finite, ∇f, c and J (the Nlp contract makes no
/// other call where f is not finite).
FirstOrder evaluate(Nlp& nlp, const VectorXd& x)
{
    FirstOrder at;
    at.f = nlp.objective(x);
    if (!std::isfinite(at.f))
        return at;
    at.grad.resize(x.size());
    nlp.gradient(x, at.grad);
    at.c.resize(nlp.num_constraints());
    at.jac.resize(nlp.jacobian_pattern().nonzeros());
    if (nlp.num_constraints() > 0) {
        nlp.constraints(x, at.c);
        nlp.jacobian_values(x, at.jac);
    }
    return at;
}

/// ∇L = σ∇f + Jᵀλ.
VectorXd lagrangian_gradient(const Context& context, const FirstOrder& at)
{
    VectorXd g = context.options.sigma * at.grad;
    const SparsityPattern& pattern = context.nlp.jacobian_pattern();
    for (int k = 0; k < pattern.nonzeros(); ++k)
        g[pattern.cols[k]] += at.jac[k] * context.lambda[pattern.rows[k]];
    return g;
}

/// Point `index` of the run: x itself for index 0, else x + ρ·u∘max(1, |x|)
/// with ρ = options.perturbation halved until f is finite there. Empty x
/// when f is not finite at any of them.
Base make_base(Context& context, const VectorXd& x, int index)
{
    Base base;
    const VectorXd offset = uniform_vector(context.rng, x.size()).cwiseProduct(step_scale(x));
    double rho = index == 0 ? 0.0 : context.options.perturbation;
    for (int shrink = 0; shrink <= kMaxShrinks; ++shrink, rho /= 2) {
        base.x = x + rho * offset;
        base.at = evaluate(context.nlp, base.x);
        if (std::isfinite(base.at.f) || rho == 0.0)
            break;
    }
    if (!std::isfinite(base.at.f)) {
        base.x.resize(0);
        return base;
    }
    base.lagrangian_grad = lagrangian_gradient(context, base.at);
    base.hessian.resize(context.nlp.hessian_pattern().nonzeros());
    context.nlp.hessian(base.x, context.options.sigma, context.lambda, Projection::none, base.hessian);
    const Nlp& nlp = context.nlp;
    base.grad_x = base.at.grad.cwiseAbs().dot(base.x.cwiseAbs());
    base.jac_x = multiply(nlp.jacobian_pattern(), base.at.jac, base.x, nlp.num_constraints(), false, true).norm();
    base.hess_x = multiply(nlp.hessian_pattern(), base.hessian, base.x, nlp.num_variables(), true, true).norm();
    return base;
}

/// d = u∘max(1, |x|), u uniform in [-1, 1]^n scaled to ‖u‖∞ = 1.
VectorXd make_direction(Context& context, const VectorXd& x)
{
    VectorXd u = uniform_vector(context.rng, x.size());
    const double largest = u.size() > 0 ? u.cwiseAbs().maxCoeff() : 0.0;
    if (largest > 0.0)
        u /= largest;
    return u.cwiseProduct(step_scale(x));
}

/// options.initial_step halved until f(x + h0 d) is finite; 0 when it never is.
double first_step(Context& context, const Base& base, const VectorXd& d)
{
    double h = context.options.initial_step;
    for (int shrink = 0; shrink <= kMaxShrinks; ++shrink, h /= 2)
        if (std::isfinite(context.nlp.objective(base.x + h * d)))
            return h;
    return 0.0;
}

void append(TaylorSeries& series, double h, double remainder, double roundoff)
{
    series.steps.push_back(h);
    series.remainders.push_back(std::isfinite(remainder) ? remainder : kNaN);
    series.roundoff.push_back(kTaylorRoundoffFactor * kEpsilon * roundoff);
}

bool measured(const TaylorSeries& s, int k)
{
    return std::isfinite(s.remainders[k]) && s.remainders[k] > s.roundoff[k];
}

/// log2(r(h_{k-1}) / r(h_k)): the slope between step k − 1 and step k.
double local_slope(const TaylorSeries& s, int k) { return std::log2(s.remainders[k - 1] / s.remainders[k]); }

/// The fit window: the smallest kTaylorFitSteps steps of the last unbroken
/// run of measured steps; {-1, -1} when no step is measured.
std::pair<int, int> fit_window(const TaylorSeries& s)
{
    int last = static_cast<int>(s.steps.size()) - 1;
    while (last >= 0 && !measured(s, last))
        --last;
    int first = last;
    while (first > 0 && measured(s, first - 1) && last - first + 1 < kTaylorFitSteps)
        --first;
    return {first, last};
}

/// Whether one more halving would help: the smallest step is still measured
/// and the window is too short or not yet asymptotic (its local slopes spread
/// by more than kTaylorSlopeSpread).
bool wants_smaller_step(const TaylorSeries& s)
{
    const auto [first, last] = fit_window(s);
    if (last < 0 || last + 1 != static_cast<int>(s.steps.size()))
        return false;
    if (last - first + 1 < kTaylorMinFitSteps)
        return true;
    double low = HUGE_VAL, high = -HUGE_VAL;
    for (int k = first + 1; k <= last; ++k) {
        low = std::min(low, local_slope(s, k));
        high = std::max(high, local_slope(s, k));
    }
    return high - low > kTaylorSlopeSpread;
}

/// Appends step h to the three series (gradient, Jacobian, Hessian). The
/// round-off estimate of a remainder a(x+hd) − a(x) − h·a'(x)d is
/// ε(|a(x)| + |a(x+hd)| + h|a'(x)d| + |a'(x)||x|); the last term is the effect
/// of rounding x + hd to doubles.
void add_step(Context& context, const Base& base, const Directional& along, double h, TaylorSeries series[3])
{
    const FirstOrder at = h > 0.0 ? evaluate(context.nlp, base.x + h * along.d) : FirstOrder{};
    if (!std::isfinite(at.f)) {
        for (int s = 0; s < 3; ++s)
            append(series[s], h, kNaN, 0.0);
        return;
    }
    append(series[0], h, std::abs(at.f - base.at.f - h * along.grad_d),
           std::abs(base.at.f) + std::abs(at.f) + h * std::abs(along.grad_d) + base.grad_x);
    append(series[1], h, (at.c - base.at.c - h * along.jac_d).norm(),
           base.at.c.norm() + at.c.norm() + h * along.jac_d.norm() + base.jac_x);
    const VectorXd lagrangian_grad = lagrangian_gradient(context, at);
    append(series[2], h, (lagrangian_grad - base.lagrangian_grad - h * along.hess_d).norm(),
           base.lagrangian_grad.norm() + lagrangian_grad.norm() + h * along.hess_d.norm() + base.hess_x);
}

/// What series s differences at `at`: f (s = 0), c (1) or ∇L (2).
VectorXd differenced(const Context& context, const FirstOrder& at, int s)
{
    if (s == 0)
        return VectorXd::Constant(1, at.f);
    return s == 1 ? at.c : lagrangian_gradient(context, at);
}

/// ‖q(x + hd) − 2q(x) + q(x − hd)‖ / h for the quantity of series s: h‖q''‖
/// where q is smooth along d, the jump of its directional derivative where
/// it has a kink at x. NaN where f is not finite.
double second_difference(Context& context, const Base& base, const VectorXd& d, double h, int s)
{
    const FirstOrder ahead = evaluate(context.nlp, base.x + h * d), behind = evaluate(context.nlp, base.x - h * d);
    if (!std::isfinite(ahead.f) || !std::isfinite(behind.f))
        return kNaN;
    const VectorXd q = differenced(context, base.at, s);
    return (differenced(context, ahead, s) - 2.0 * q + differenced(context, behind, s)).norm() / h;
}

/// A failed series at a kink of its quantity at the point: at the two
/// smallest fitted steps the second difference keeps at least ¾ of its size
/// as h halves (it would halve where q is smooth) and lies above the
/// remainder's round-off. Such a point has no derivative to judge.
void mark_kink(Context& context, const Base& base, const VectorXd& d, TaylorSeries& series, int s)
{
    if (series.verdict != TaylorVerdict::failed || series.fit_last < 1)
        return;
    const double h = series.steps[series.fit_last];
    const double small = second_difference(context, base, d, h, s);
    const double large = second_difference(context, base, d, 2.0 * h, s);
    if (small >= 0.75 * large && small * h > series.roundoff[series.fit_last]) {
        series.verdict = TaylorVerdict::kink;
        std::ostringstream note;
        note << std::setprecision(3) << "the derivative jumps at the point along d: " << small << " at h, " << large
             << " at 2h";
        series.note = note.str();
    }
}

/// The three series along d from `base`: options.steps halvings, and up to
/// options.extra_steps more while a series wants_smaller_step().
void run_series(Context& context, const Base& base, const VectorXd& d, TaylorSeries series[3])
{
    Nlp& nlp = context.nlp;
    const Directional along{d, base.at.grad.dot(d),
                            multiply(nlp.jacobian_pattern(), base.at.jac, d, nlp.num_constraints(), false),
                            multiply(nlp.hessian_pattern(), base.hessian, d, nlp.num_variables(), true)};
    const double h0 = first_step(context, base, d);
    const int most = context.options.steps + context.options.extra_steps;
    for (int k = 0; k < most; ++k) {
        if (k >= context.options.steps && (h0 == 0.0 || std::none_of(series, series + 3, wants_smaller_step)))
            break;
        add_step(context, base, along, h0 * std::ldexp(1.0, -k), series);
    }
    if (h0 == 0.0)
        for (int s = 0; s < 3; ++s)
            series[s].note = "f is not finite at x + h0 d for h0 down to " +
                             format_number(std::ldexp(context.options.initial_step, -kMaxShrinks));
}

/// Least-squares slope of log r against log h over steps first..last.
double fitted_slope(const TaylorSeries& s, int first, int last)
{
    double mean_x = 0.0, mean_y = 0.0;
    const int count = last - first + 1;
    for (int k = first; k <= last; ++k) {
        mean_x += std::log(s.steps[k]) / count;
        mean_y += std::log(s.remainders[k]) / count;
    }
    double sxy = 0.0, sxx = 0.0;
    for (int k = first; k <= last; ++k) {
        const double dx = std::log(s.steps[k]) - mean_x;
        sxy += dx * (std::log(s.remainders[k]) - mean_y);
        sxx += dx * dx;
    }
    return sxy / sxx;
}

/// The verdict (rule in docs/solvers.md): the slope fitted over the
/// fit_window(), which needs kTaylorMinFitSteps steps; exact when no finite
/// remainder (of at least kTaylorMinFitSteps) is above round-off.
void judge(TaylorSeries& s, double min_slope)
{
    const auto [first, last] = fit_window(s);
    const int count = static_cast<int>(s.steps.size());
    const auto finite =
        std::count_if(s.remainders.begin(), s.remainders.end(), [](double r) { return std::isfinite(r); });
    if (last < 0 && finite >= kTaylorMinFitSteps) {
        s.verdict = TaylorVerdict::exact;
        return;
    }
    if (last < 0 || last - first + 1 < kTaylorMinFitSteps) {
        s.verdict = TaylorVerdict::not_measurable;
        if (s.note.empty())
            s.note = std::to_string(last < 0 ? 0 : last - first + 1) + " consecutive steps above round-off, " +
                     std::to_string(finite) + " of " + std::to_string(count) + " finite";
        return;
    }
    s.fit_first = first;
    s.fit_last = last;
    s.slope = fitted_slope(s, first, last);
    s.verdict = s.slope >= min_slope ? TaylorVerdict::passed : TaylorVerdict::failed;
    if (wants_smaller_step(s))
        s.note = "not yet asymptotic at the smallest step";
}

/// Whether `a` is worse than `b`: a lower verdict, or the same with a lower slope.
bool worse(const TaylorSeries& a, const TaylorSeries& b)
{
    return a.verdict != b.verdict ? a.verdict < b.verdict : a.slope < b.slope;
}

void keep_worst(TaylorResult& result, TaylorSeries&& series, int point, int direction)
{
    if (result.point >= 0 && !worse(series, result.worst))
        return;
    result.worst = std::move(series);
    result.point = point;
    result.direction = direction;
}

/// Every direction from one point, folded into the report.
void test_point(Context& context, const VectorXd& x, int index, TaylorReport& report)
{
    const Base base = make_base(context, x, index);
    TaylorResult* results[3] = {&report.gradient, &report.jacobian, &report.hessian};
    bool all_passed[3] = {true, true, true};
    for (int direction = 0; direction < context.options.directions; ++direction) {
        TaylorSeries series[3];
        const VectorXd d = make_direction(context, x);
        if (base.x.size() == 0 && x.size() > 0) {
            for (auto& s : series)
                s.note = index == 0 ? "f is not finite at x"
                                    : "f is not finite at x + perturbation, halved " +
                                          std::to_string(kMaxShrinks) + " times";
        } else {
            run_series(context, base, d, series);
        }
        for (int s = 0; s < 3; ++s) {
            judge(series[s], context.options.min_slope);
            if (base.x.size() > 0)
                mark_kink(context, base, d, series[s], s);
            all_passed[s] = all_passed[s] && series[s].verdict >= TaylorVerdict::passed;
            if (results[s]->tested)
                keep_worst(*results[s], std::move(series[s]), index, direction);
        }
    }
    for (int s = 0; s < 3; ++s)
        results[s]->points_passed += all_passed[s];
}

void validate(const Nlp& nlp, const VectorXd& x, const TaylorOptions& o)
{
    auto require = [](bool ok, const std::string& what) {
        if (!ok)
            throw InputError("Taylor test: " + what);
    };
    require(o.points >= 1, "points = " + std::to_string(o.points) + " is invalid; it must be at least 1");
    require(o.directions >= 1, "directions = " + std::to_string(o.directions) + " is invalid; it must be at least 1");
    require(o.steps >= kTaylorMinFitSteps, "steps = " + std::to_string(o.steps) + " is invalid; it must be at least " +
                                               std::to_string(kTaylorMinFitSteps));
    require(o.extra_steps >= 0, "extra steps = " + std::to_string(o.extra_steps) + " is invalid; it must be >= 0");
    require(o.initial_step > 0.0 && std::isfinite(o.initial_step),
            "initial step = " + format_number(o.initial_step) + " is invalid; it must be a positive finite number");
    require(o.perturbation >= 0.0 && std::isfinite(o.perturbation),
            "perturbation = " + format_number(o.perturbation) + " is invalid; it must be a finite number >= 0");
    require(o.min_slope > 0.0 && std::isfinite(o.min_slope),
            "min slope = " + format_number(o.min_slope) + " is invalid; it must be a positive finite number");
    require(std::isfinite(o.sigma), "sigma = " + format_number(o.sigma) + " is not finite");
    require(x.size() == nlp.num_variables(), "x has " + std::to_string(x.size()) + " entries for " +
                                                 std::to_string(nlp.num_variables()) + " variables of " + nlp.name());
    require(x.allFinite(), "the point x of " + nlp.name() + " is not finite");
}

std::string format_short(double value, int precision = 3)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", precision, value);
    return text;
}

std::string slope_text(double slope)
{
    if (!std::isfinite(slope))
        return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", slope);
    return text;
}

} // namespace

const char* to_string(TaylorVerdict verdict)
{
    switch (verdict) {
    case TaylorVerdict::failed: return "FAILED";
    case TaylorVerdict::not_measurable: return "not measurable";
    case TaylorVerdict::kink: return "kink at the point";
    case TaylorVerdict::passed: return "passed";
    case TaylorVerdict::exact: return "exact (round-off)";
    }
    return "?";
}

bool TaylorResult::passed() const
{
    return !tested || worst.verdict >= TaylorVerdict::passed ||
           (worst.verdict == TaylorVerdict::kink && points_passed > 0);
}

bool TaylorReport::passed() const
{
    return pattern_problem.empty() && gradient.passed() && jacobian.passed() && hessian.passed();
}

TaylorReport taylor_test(Nlp& nlp, Nlp::ConstVectorRef x_in, const TaylorOptions& options)
{
    const VectorXd x = x_in;
    validate(nlp, x, options);
    TaylorReport report;
    report.points = options.points;
    report.directions = options.directions;
    report.min_slope = options.min_slope;
    report.pattern_problem = find_pattern_problem(nlp);
    if (!report.pattern_problem.empty())
        return report;
    report.gradient.tested = report.hessian.tested = true;
    report.jacobian.tested = nlp.num_constraints() > 0;
    Context context{nlp, options, VectorXd(), std::mt19937(options.seed)};
    context.lambda = uniform_vector(context.rng, nlp.num_constraints());
    for (int point = 0; point < options.points; ++point)
        test_point(context, x, point, report);
    return report;
}

std::string TaylorReport::to_text() const
{
    std::ostringstream out;
    if (!pattern_problem.empty())
        return pattern_problem + "\n";
    out << "Taylor test, " << points << " point(s) x " << directions
        << " direction(s); pass: slope >= " << format_short(min_slope) << " or remainder at round-off\n";
    char line[200];
    std::snprintf(line, sizeof line, "  %-10s %7s  %-18s %-12s %s\n", "derivative", "slope", "verdict", "worst at",
                  "fitted steps h");
    out << line;
    const std::pair<const char*, const TaylorResult*> rows[] = {
        {"gradient", &gradient}, {"jacobian", &jacobian}, {"hessian", &hessian}};
    for (const auto& [name, result] : rows) {
        if (!result->tested) {
            std::snprintf(line, sizeof line, "  %-10s %7s  %s\n", name, "-", "not tested (no constraints)");
            out << line;
            continue;
        }
        const TaylorSeries& s = result->worst;
        const std::string where = "p" + std::to_string(result->point) + " d" + std::to_string(result->direction);
        const std::string fitted = s.fit_first >= 0 ? format_short(s.steps[s.fit_first]) + " .. " +
                                                          format_short(s.steps[s.fit_last])
                                   : s.verdict == TaylorVerdict::exact ? "none above round-off"
                                                                       : s.note;
        const std::string remark = s.fit_first >= 0 && !s.note.empty() ? " (" + s.note + ")" : "";
        std::snprintf(line, sizeof line, "  %-10s %7s  %-18s %-12s %s\n", name,
                      slope_text(s.slope).c_str(), sinew::to_string(s.verdict),
                      where.c_str(), (fitted + remark).c_str());
        out << line;
    }
    return out.str();
}

std::string TaylorReport::series_text() const
{
    std::ostringstream out;
    const std::pair<const char*, const TaylorResult*> rows[] = {
        {"gradient", &gradient}, {"jacobian", &jacobian}, {"hessian", &hessian}};
    char line[160];
    for (const auto& [name, result] : rows) {
        if (!result->tested)
            continue;
        const TaylorSeries& s = result->worst;
        out << name << " at point " << result->point << ", direction " << result->direction << " ("
            << sinew::to_string(s.verdict) << "; * = fitted)\n";
        std::snprintf(line, sizeof line, "  %12s %12s %12s %8s\n", "h", "r(h)", "round-off", "slope");
        out << line;
        for (std::size_t k = 0; k < s.steps.size(); ++k) {
            const bool has_previous = k > 0 && std::isfinite(s.remainders[k]) && std::isfinite(s.remainders[k - 1]);
            const double local = has_previous ? std::log2(s.remainders[k - 1] / s.remainders[k]) : kNaN;
            const bool fitted = static_cast<int>(k) >= s.fit_first && static_cast<int>(k) <= s.fit_last;
            std::snprintf(line, sizeof line, "%s %12.4g %12.4g %12.4g %8.3g\n", fitted ? " *" : "  ", s.steps[k],
                          s.remainders[k], s.roundoff[k], local);
            out << line;
        }
    }
    return out.str();
}

} // namespace sinew
