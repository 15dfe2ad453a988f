#pragma once
#include <Eigen/Core>

#include <functional>

namespace sinew {

/// How preconditioned conjugate gradients ended.
enum class CgStatus {
    converged,             ///< ‖b − A d‖₂ ≤ η‖b‖₂
    iteration_limit,       ///< max_iterations reached first
    negative_curvature,    ///< pᵀA p ≤ 0 along a search direction: A is not positive definite
    preconditioner_failed  ///< the preconditioner's solve failed or gave a non-finite vector
};

struct CgOutcome {
    CgStatus status = CgStatus::iteration_limit;
    int iterations = 0;              ///< products with A
    double relative_residual = 1.0;  ///< ‖b − A d‖₂ / ‖b‖₂ at the returned d
};

/// Preconditioned conjugate gradients on A d = b from d = 0, A symmetric
/// positive definite and given by its product `multiply(v, A v)`, the
/// preconditioner by `precondition(r, M⁻¹ r)` (false: it failed). Stops when
/// ‖b − A d‖₂ ≤ η‖b‖₂ (Hestenes–Stiefel recurrences, the residual updated
/// as r ← r − α A p; Saad, "Iterative methods for sparse linear systems",
/// Alg. 9.1). Every iterate satisfies dᵀ(A d − b) = 0, so for b = −∇f the
/// model decrease of d is −½ ∇fᵀd as for an exact Newton step.
CgOutcome preconditioned_cg(const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>& multiply,
                            const std::function<bool(const Eigen::VectorXd&, Eigen::VectorXd&)>& precondition,
                            const Eigen::VectorXd& b, double eta, int max_iterations, Eigen::VectorXd& d);

} // namespace sinew
