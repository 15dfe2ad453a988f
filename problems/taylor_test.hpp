#pragma once
#include "sinew/problems/nlp.hpp"

#include <limits>
#include <string>
#include <vector>

namespace sinew {

/// A remainder counts as measured when it exceeds this multiple of its
/// round-off estimate (docs/solvers.md, "The Taylor test").
inline constexpr double kTaylorRoundoffFactor = 1e3;
/// The slope is fitted over at most this many of the smallest measured steps...
inline constexpr int kTaylorFitSteps = 4;
/// ... and needs at least this many.
inline constexpr int kTaylorMinFitSteps = 3;
/// Local slopes in the fitted steps spreading by more than this mean the
/// steps are not yet asymptotic: the test halves h further (extra_steps).
inline constexpr double kTaylorSlopeSpread = 0.1;

/// How one remainder series ended, worst first.
enum class TaylorVerdict {
    failed,          ///< measured slope below the threshold: a wrong derivative
    not_measurable,  ///< too few steps above round-off, or f not finite along d; not a pass
    /// slope below the threshold, but the differenced quantity has a kink at
    /// the point along d (its second difference does not shrink with h: no
    /// derivative exists there to judge); a pass only where the same
    /// derivative passes at another point
    kink,
    passed,          ///< measured slope at or above the threshold
    exact,           ///< remainder at round-off at every step (f quadratic, ∇L or c linear along d); a pass
};
const char* to_string(TaylorVerdict verdict);

/// The remainder of one derivative's first-order Taylor model along one
/// direction d from one point x, at steps h_k = h0·2^-k.
struct TaylorSeries {
    std::vector<double> steps;       ///< h_k (h0 halved until f(x + h0 d) is finite)
    std::vector<double> remainders;  ///< r(h_k); NaN where f(x + h_k d) or a derivative is not finite
    std::vector<double> roundoff;    ///< kTaylorRoundoffFactor · round-off estimate of r(h_k)
    int fit_first = -1;              ///< the slope is fitted over steps fit_first..fit_last
    int fit_last = -1;               ///< (-1: not fitted)
    double slope = std::numeric_limits<double>::quiet_NaN();  ///< d log r / d log h, least squares
    TaylorVerdict verdict = TaylorVerdict::not_measurable;
    std::string note;  ///< why the series is not measurable
};

/// One derivative's worst series over every point and direction tried.
struct TaylorResult {
    bool tested = false;  ///< false for the Jacobian of a problem without constraints
    TaylorSeries worst;   ///< lowest verdict, then lowest slope
    int point = -1;       ///< where the worst series is (point 0 is the x given)
    int direction = -1;
    int points_passed = 0;  ///< points where every direction passed (or was exact)
    /// Every series passed, or the worst is a kink and the derivative passed
    /// along every direction at another point.
    bool passed() const;
};

struct TaylorReport {
    TaylorResult gradient;  ///< r(h) = |f(x+hd) − f(x) − h ∇f(x)ᵀd|
    TaylorResult jacobian;  ///< r(h) = ‖c(x+hd) − c(x) − h J(x)d‖₂
    TaylorResult hessian;   ///< r(h) = ‖∇L(x+hd) − ∇L(x) − h ∇²L(x)d‖₂, ∇L = σ∇f + Jᵀλ
    /// A pattern entry outside its matrix (find_pattern_problem()); when set
    /// nothing was tested.
    std::string pattern_problem;
    int points = 0;           ///< points and directions per point tried
    int directions = 0;
    double min_slope = 0.0;   ///< the threshold used
    bool passed() const;      ///< no pattern problem and every tested derivative passed
    std::string to_text() const;      ///< a short table, one row per derivative
    std::string series_text() const;  ///< each derivative's worst series, step by step
};

struct TaylorOptions {
    int points = 3;              ///< the given x and points − 1 random perturbations of it
    int directions = 2;          ///< random directions per point
    int steps = 10;              ///< h_k = initial_step · 2^-k, k = 0 … steps − 1 ...
    int extra_steps = 10;        ///< ... and up to this many more while the smallest steps are not yet asymptotic
    double initial_step = 1e-2;  ///< h0 (d is scaled by max(1, |x_i|), see taylor_test())
    double perturbation = 1e-3;  ///< point p ≥ 1 is x + perturbation · u_i · max(1, |x_i|), u uniform in [-1, 1]
    double min_slope = 1.8;      ///< pass threshold; a wrong derivative gives ≈ 1
    double sigma = 1.0;          ///< objective factor in ∇L and ∇²L
    unsigned seed = 7;           ///< for λ (uniform in [-1, 1]^m), the points and the directions
};

/// Matrix-free Taylor test of ∇f, J and ∇²L at `points` points around x,
/// along `directions` random directions d each, d_i = u_i · max(1, |x_i|)
/// with u uniform in [-1, 1]^n scaled to ‖u‖∞ = 1. A correct derivative's
/// remainder falls as h²; a wrong one as h. Costs per point one ∇²L, and per
/// direction and step one f, ∇f, c and J; memory O(n + nonzeros). A
/// non-finite f at a perturbed point or at x + h0 d halves the perturbation or
/// h0 (up to 40 times). InputError for invalid options or a non-finite x.
TaylorReport taylor_test(Nlp& nlp, Nlp::ConstVectorRef x, const TaylorOptions& options = {});

} // namespace sinew
