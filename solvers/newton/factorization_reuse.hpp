#pragma once
#include "sinew/solvers/newton/regularized_factorization.hpp"

namespace sinew {

/// Whether Newton steps may reuse an earlier factorization, and for how long.
struct ReuseSettings {
    bool enabled = false;
    /// Preconditioned CG iterations a step may take before the caller
    /// refactorizes: the step then costs a factorization plus what CG spent.
    int max_cg_iterations = 20;
};

/// The state of the back-off after refusals, carried from solve to solve.
struct ReuseBackoff {
    int refusals_in_row = 0;  ///< refusals for the iteration limit since CG last delivered a step
    int steps_to_skip = 0;
};

/// Inexact Newton on a kept factorization (DESIGN.md, "Solvers: one Newton
/// core"): once a Newton matrix A₀ has been factorized, the step of a later
/// iteration solves (A + σI) d = b by conjugate gradients preconditioned with
/// A₀'s factors, to the relative residual η of the forcing term
/// (ForcingTerm). A step for which CG needs more than max_cg_iterations, or
/// meets a direction of non-positive curvature (A + σI indefinite), is
/// refused, and the caller factorizes A afresh, which becomes the kept one.
/// A solve's first iteration factorizes unless the caller resumes the kept
/// factors (and the back-off) of a previous solve of the same pattern: the
/// time steps of a run (resume()).
///
/// Refusals for the iteration limit in a row back off: after the k-th,
/// k ≥ kRefusalsBeforeBackoff = 3, the next 2^(k−3) − 1 steps (at most
/// kMaxSkippedSteps) skip CG and factorize at once, so a problem whose
/// Hessian changes too fast for a kept factor (a penalty at large κ) pays
/// about one factorization per step, not a factorization plus
/// max_cg_iterations CG iterations. Two refusals in a row are common where
/// the Hessian turns (the straight 206k beam has them) and do not back off. A step CG delivers
/// ends the run of refusals. A refusal for non-positive curvature is cheap
/// and tells the caller something (take the projected step), so it neither
/// counts nor is skipped.
class FactorizationReuse {
public:
    FactorizationReuse(RegularizedFactorization& factorization, ReuseSettings settings);

    /// d ≈ (A + shift·I)⁻¹ b, A symmetric given by its lower triangle, to
    /// ‖b − (A + shift·I) d‖₂ ≤ η‖b‖₂. False when reuse is off, nothing is
    /// kept, or CG did not get there within the limit: then factorize.
    bool solve(const SparseMatrix& lower, double shift, const Eigen::VectorXd& b, double eta, Eigen::VectorXd& d);

    /// The factorization now holds A's factors: later steps may reuse them.
    void keep() { kept_ = settings_.enabled; }
    /// The factorization no longer holds usable factors (a refused attempt).
    void forget() { kept_ = false; }
    /// Whether the factorization holds factors later steps may reuse.
    bool kept() const { return kept_; }
    /// Continue where a previous solve on the same factorization ended.
    void resume(bool factors_kept, ReuseBackoff backoff)
    {
        kept_ = factors_kept && settings_.enabled;
        backoff_ = backoff;
    }
    ReuseBackoff backoff() const { return backoff_; }
    /// The last solve() was refused because CG met non-positive curvature:
    /// A + shift·I is not positive definite, so factorizing it would fail too.
    bool found_indefinite() const { return found_indefinite_; }

    int cg_iterations() const { return cg_iterations_; }
    int reused_steps() const { return reused_steps_; }
    int refused_steps() const { return refused_steps_; }
    /// Steps that factorized without trying CG, backing off after refusals.
    int skipped_steps() const { return skipped_steps_; }
    double cg_seconds() const { return cg_s_; }

    /// Refusals in a row from which on the steps after a refusal are skipped.
    static constexpr int kRefusalsBeforeBackoff = 3;
    /// The most steps one backoff skips.
    static constexpr int kMaxSkippedSteps = 15;

private:
    /// After another refusal for the iteration limit: the steps to skip next.
    void back_off();

    RegularizedFactorization& factorization_;
    ReuseSettings settings_;
    bool kept_ = false;
    bool found_indefinite_ = false;
    int cg_iterations_ = 0;
    int reused_steps_ = 0;
    int refused_steps_ = 0;
    int skipped_steps_ = 0;
    ReuseBackoff backoff_;
    double cg_s_ = 0.0;
};

} // namespace sinew
