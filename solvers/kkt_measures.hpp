#pragma once
#include "sinew/problems/nlp.hpp"
#include "sinew/solvers/result.hpp"

namespace sinew {

/// First-order optimality error at x for multipliers (λ, z_L, z_U), in
/// Ipopt's convention: the largest of
///   - stationarity ‖∇f + Jᵀλ − z_L + z_U‖∞,
///   - sign errors: z_L, z_U < 0; λᵢ > 0 on a constraint with no upper bound,
///     λᵢ < 0 on one with no lower bound; a bound multiplier on an absent bound,
///   - complementarity: |λᵢ|·(distance of cᵢ to the bound its sign selects),
///     z_L·(x − x_L), z_U·(x_U − x).
double kkt_residual(Nlp& nlp, Nlp::ConstVectorRef x, Nlp::ConstVectorRef lambda, Nlp::ConstVectorRef z_lower,
                    Nlp::ConstVectorRef z_upper);

/// Multipliers for a backend that reports none: least squares
///   min ‖∇f + Σ_{active} μₐ ∇aₐ‖
/// over the constraints and bounds active at x (within `active_tolerance`,
/// equalities always active, and a violated row too: at a penalty's
/// stationary point the rows beyond their bounds are those that push), by
/// sparse QR. μ is split into λ, z_L, z_U;
/// wrong signs are left as they come so that kkt_residual shows them.
void estimate_multipliers(Nlp& nlp, Nlp::ConstVectorRef x, double active_tolerance, Eigen::VectorXd& lambda,
                          Eigen::VectorXd& z_lower, Eigen::VectorXd& z_upper);

} // namespace sinew
