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

/// Inexact Newton on a kept factorization (DESIGN.md, "Solvers: one Newton
/// core"): once a Newton matrix A₀ has been factorized, the step of a later
/// iteration solves (A + σI) d = b by conjugate gradients preconditioned with
/// A₀'s factors, to the relative residual η of the forcing term
/// (ForcingTerm). A step for which CG needs more than max_cg_iterations, or
/// meets a direction of non-positive curvature (A + σI indefinite), is
/// refused, and the caller factorizes A afresh, which becomes the kept one.
/// The first iteration has nothing kept and always factorizes.
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
    /// The last solve() was refused because CG met non-positive curvature:
    /// A + shift·I is not positive definite, so factorizing it would fail too.
    bool found_indefinite() const { return found_indefinite_; }

    int cg_iterations() const { return cg_iterations_; }
    int reused_steps() const { return reused_steps_; }
    int refused_steps() const { return refused_steps_; }
    double cg_seconds() const { return cg_s_; }

private:
    RegularizedFactorization& factorization_;
    ReuseSettings settings_;
    bool kept_ = false;
    bool found_indefinite_ = false;
    int cg_iterations_ = 0;
    int reused_steps_ = 0;
    int refused_steps_ = 0;
    double cg_s_ = 0.0;
};

} // namespace sinew
