#pragma once
// The seed's solve of the grid inextensibility (seed 004 Alg. 11).
#include "sinew/mpm/linear_velocity_rows.hpp"
#include "sinew/mpm/spd_solve.hpp"

#include <Eigen/Core>

namespace sinew {

struct SchurProjectionReport {
    SpdSolveOutcome solve;         ///< the CG on the Schur complement (converged and no iterations when y* satisfied the rows)
    double violation_before = 0.0;  ///< ‖B y* − rhs‖∞
    double violation_after = 0.0;   ///< ‖B y − rhs‖∞
};

/// The velocities nearest y* in the kinetic metric that satisfy the rows:
///
///     minimize ½ (y − y*)ᵀ M (y − y*)  subject to  B y = rhs,
///
/// M = diag(masses). Its KKT system, solved on its Schur complement as the
/// seed writes it: L λ = B M⁻¹ b − rhs with L = B M⁻¹ Bᵀ and b = M y*, by
/// `solve` with L's diagonal Σ_j B_cj²/m_j as the Jacobi preconditioner,
/// then y = M⁻¹ (b − Bᵀ λ). (The seed's b = M v*/Δt makes its λ ours
/// divided by Δt: an impulse per unit time.) L is only semidefinite when
/// rows depend on each other, but B M⁻¹ b − rhs lies in its range when the
/// rows are consistent, so CG converges there too. y holds y* on entry.
SchurProjectionReport project_onto_rows(const LinearVelocityRows& rows, const Eigen::VectorXd& masses, Eigen::VectorXd& y,
                                        const SpdSolve& solve);

} // namespace sinew
