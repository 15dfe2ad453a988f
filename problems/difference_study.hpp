#pragma once
// A closer look at derivative entries that central differences at one step
// disagree with (docs/solvers.md, "Derivative checks"): round-off noise in
// the differenced values, a kink (the function is not differentiable there,
// or its derivative jumps between x − h and x + h), or a step too large.
#include <Eigen/Core>

#include <functional>
#include <vector>

namespace sinew {

/// How an entry was settled.
enum class StudyOutcome {
    disagrees,     ///< nothing explains the difference: a wrong derivative
    noise,         ///< the central difference's error is within its round-off noise
    kink,          ///< one one-sided difference agrees at two consecutive steps, the other side does not
    both_sides,    ///< both one-sided differences agree: a jump in curvature at x, or a step too large
};

/// One entry ∂F_row/∂x_j to settle: its analytic value and the central
/// difference that disagreed with it.
struct EntryToStudy {
    int row;
    double analytic;
    double central;
};

struct StudiedEntry {
    StudyOutcome outcome = StudyOutcome::disagrees;
    /// |analytic − estimate| less the estimate's noise allowance, over
    /// max(|estimate|, floor): the best agreement the study found (the
    /// central difference's when nothing agrees).
    double relative_error = 0.0;
    double estimate = 0.0;
};

/// F evaluated at a point: the quantity whose derivative is checked (f as a
/// vector of one entry, the constraints c, or ∇L).
using PointFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

/// Studies entries of column j (the derivative along x_j) whose central
/// difference at step h disagreed with the analytic value by more than
/// `tolerance` (relative, against max(|estimate|, floor)):
///  1. noise: σ_i, the round-off of F_i along x_j, from fourth differences
///     of F at x ± kη e_j, k = 0…5, η = h/100, the smaller of the two sides'
///     (Var Δ⁴ = 70σ² for independent errors; a kink spoils one side at most;
///     at least ε·|F_i|); the central difference's error less 3·(√2/2)σ_i/h;
///  2. one-sided: the second-order one-sided differences
///     (4F(x ± h_k/2) − 3F(x) − F(x ± h_k))/(±h_k), h_k = h·2^-k, k = 0…8,
///     less their noise 3·√26·σ_i/h_k: an entry agreeing on one side at two
///     consecutive steps is settled (a kink when the other side disagrees at
///     that step; both sides when it agrees too: F's curvature jumps at x,
///     which costs the central difference its second order, or h was too
///     large).
/// An allowance above a tenth of `floor` settles nothing (a difference that
/// noisy cannot resolve the entry). A wrong derivative agrees at no step on
/// either side. Costs 6 evaluations
/// of F, and 2 more per halving while some entry is unsettled.
std::vector<StudiedEntry> study_column(const PointFunction& F, const Eigen::VectorXd& x, int j, double h,
                                       const Eigen::VectorXd& F_at_x, const std::vector<EntryToStudy>& entries,
                                       double floor, double tolerance);

} // namespace sinew
