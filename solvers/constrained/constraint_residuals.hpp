#pragma once
#include "sinew/problems/nlp.hpp"

namespace sinew {

/// The rows g_L ≤ c(x) ≤ g_U of an NLP, equalities (g_L = g_U) and
/// inequalities (g_L < g_U, either side possibly infinite) alike, for the
/// strategies that fold constraints into the objective (penalty, augmented
/// Lagrangian, relaxed KKT) or that take equalities only (kkt-newton). Every
/// row is read through the projection P onto its interval [g_L, g_U]:
///
///   - the violation v = c − P(c): c − g_L on an equality row; on an
///     inequality row c − g_U above the interval, c − g_L below it, 0 inside.
///     |vᵢ| is the distance of cᵢ to [g_L,ᵢ, g_U,ᵢ], the quantity solve()
///     measures; κ/2‖v‖² is the quadratic penalty.
///   - for multipliers λ (Ipopt's sign: ∇f + Jᵀλ = 0, λᵢ ≤ 0 on an active
///     lower side, ≥ 0 on an active upper side) and κ > 0, the shifted
///     residual r = c − P(c + λ/κ) and the clipped multiplier μ = λ + κr of
///     the Powell–Hestenes–Rockafellar augmented Lagrangian (Rockafellar
///     1973; Nocedal & Wright §17.4). A row is active when its shifted value
///     s = c + λ/κ is not inside the open interval (g_L, g_U): every equality
///     row; an inequality row whose s crosses a side, where r = c − (that
///     side) and μ has that side's sign. Elsewhere r = −λ/κ and μ = 0. The
///     row's term of the augmented Lagrangian is
///         λr + κ/2 r² = (μ² − λ²)/(2κ)
///     (λ(c − g_L) + κ/2(c − g_L)² on an equality row), C¹ in x with gradient
///     μ∇c, and μ is the multiplier update of the method of multipliers.
///     λ = 0 gives r = v and μ = κv: the penalty.
///
/// Evaluation does not allocate.
class ConstraintResiduals {
public:
    explicit ConstraintResiduals(Nlp& nlp);

    int size() const { return static_cast<int>(lower_.size()); }
    const SparsityPattern& pattern() const { return nlp_.jacobian_pattern(); }
    const Eigen::VectorXd& lower() const { return lower_; }
    const Eigen::VectorXd& upper() const { return upper_; }
    bool is_equality(int i) const { return lower_[i] == upper_[i]; }

    /// c(x).
    void values(const Eigen::VectorXd& x, Eigen::VectorXd& c);
    /// The violation v = c(x) − P(c(x)) (c − g_L when every row is an equality).
    void residuals(const Eigen::VectorXd& x, Eigen::VectorXd& v);
    /// v = c − P(c) from the values c.
    void violations(const Eigen::VectorXd& c, Eigen::VectorXd& v) const;
    /// ‖c − P(c)‖∞: the largest distance of a row to its interval (0 when m = 0).
    double max_violation(const Eigen::VectorXd& c) const;
    /// From the values c, for λ and κ > 0: r = c − P(c + λ/κ), μ = λ + κr on
    /// active rows and exactly 0 on the others, and active = 1 or 0 per row
    /// (the weight of the row's κJᵢᵀJᵢ in the Hessian).
    void shifted(const Eigen::VectorXd& c, const Eigen::VectorXd& lambda, double kappa, Eigen::VectorXd& r,
                 Eigen::VectorXd& multipliers, Eigen::VectorXd& active) const;

    /// J's values in pattern order.
    void jacobian(const Eigen::VectorXd& x, Eigen::VectorXd& values);
    /// out = Jᵀ v for J given by its pattern values.
    void transpose_times(const Eigen::VectorXd& values, const Eigen::VectorXd& v, Eigen::VectorXd& out) const;
    /// scaled[k] = values[k] · row_weight[row of k]: the Jacobian with each row scaled.
    void scale_rows(const Eigen::VectorXd& values, const Eigen::VectorXd& row_weight, Eigen::VectorXd& scaled) const;

private:
    Nlp& nlp_;
    Eigen::VectorXd lower_, upper_;  ///< g_L, g_U; absent sides (is_finite_bound false) as ∓infinity
};

} // namespace sinew
