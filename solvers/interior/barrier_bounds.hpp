#pragma once
#include "sinew/problems/nlp.hpp"

namespace sinew {

/// The bounds w_L ≤ w ≤ w_U of an interior-point method and the logarithmic
/// barrier on them (Wächter & Biegler 2006, "On the implementation of an
/// interior-point filter line-search algorithm", Math. Program. 106, §2–3):
///
///     φ_μ(w) = f(w) − μ Σ ln(w − w_L) − μ Σ ln(w_U − w)
///
/// over the finite bounds only. Each bound is relaxed outward by
/// relax·max(1, |bound|) (Ipopt's bound_relax_factor, 1e-8 by default) so
/// that a variable with w_L = w_U still has an interior; original() projects
/// onto the unrelaxed box.
class BarrierBounds {
public:
    using Vector = Eigen::VectorXd;

    BarrierBounds(const Nlp& nlp, double relax);

    int size() const { return static_cast<int>(lower_.size()); }
    bool has_lower(int i) const { return has_lower_[i] != 0.0; }
    bool has_upper(int i) const { return has_upper_[i] != 0.0; }
    /// 1 where the bound is finite, 0 where it is absent.
    const Vector& lower_mask() const { return has_lower_; }
    const Vector& upper_mask() const { return has_upper_; }

    /// Moves w strictly inside (Ipopt's bound_push κ₁ and bound_frac κ₂, §3.6):
    /// p_L = min(κ₁ max(1, |w_L|), κ₂ (w_U − w_L)), w ← max(w, w_L + p_L), and the mirror at w_U.
    void push_inside(Vector& w, double push = 1e-2, double fraction = 1e-2) const;
    /// w − w_L and w_U − w, 1 where the bound is absent (so that products with z vanish).
    void distances(const Vector& w, Vector& to_lower, Vector& to_upper) const;
    /// −μ Σ ln(w − w_L) − μ Σ ln(w_U − w); +∞ outside the relaxed box.
    double barrier(const Vector& w, double mu) const;
    /// ∇ of barrier(): −μ/(w − w_L) + μ/(w_U − w).
    void barrier_gradient(const Vector& w, double mu, Vector& gradient) const;
    /// Σ = z_L/(w − w_L) + z_U/(w_U − w), the primal-dual barrier Hessian.
    void sigma(const Vector& w, const Vector& z_lower, const Vector& z_upper, Vector& sigma) const;

    /// Fraction to the boundary (§2.2, eq. 15): the largest α ≤ 1 with
    /// w + α dw ≥ (1 − τ)(w − w_L) from w_L and the mirror at w_U.
    double max_step(const Vector& w, const Vector& dw, double tau) const;
    /// The same for multipliers z ≥ 0 on finite bounds: z + α dz ≥ (1 − τ) z.
    double max_dual_step(const Vector& z, const Vector& dz, const Vector& mask, double tau) const;
    /// z kept within [μ/(κ_Σ d), κ_Σ μ/d] (§2.2, eq. 16), κ_Σ = 1e10, so that Σ
    /// stays close to the primal barrier Hessian μ/d².
    void safeguard(const Vector& w, double mu, Vector& z_lower, Vector& z_upper) const;
    /// max over finite bounds of |(w − w_L) z_L − μ| and |(w_U − w) z_U − μ|.
    double complementarity(const Vector& w, const Vector& z_lower, const Vector& z_upper, double mu) const;

    /// The nearest point of the original (unrelaxed) box.
    void original(Vector& w) const;

private:
    Vector lower_, upper_;                  ///< relaxed bounds (finite where present)
    Vector original_lower_, original_upper_;
    Vector has_lower_, has_upper_;          ///< 1 or 0
};

} // namespace sinew
