#include "sinew/solvers/newton/preconditioned_cg.hpp"

#include <cmath>

namespace sinew {

using Eigen::VectorXd;

CgOutcome preconditioned_cg(const std::function<void(const VectorXd&, VectorXd&)>& multiply,
                            const std::function<bool(const VectorXd&, VectorXd&)>& precondition,
                            const VectorXd& b, double eta, int max_iterations, VectorXd& d)
{
    CgOutcome outcome;
    d.setZero(b.size());
    const double b_norm = b.norm();
    if (b_norm == 0.0) {
        outcome.status = CgStatus::converged;
        outcome.relative_residual = 0.0;
        return outcome;
    }
    VectorXd r = b;  // r = b − A d with d = 0
    VectorXd z(b.size()), p(b.size()), q(b.size());
    if (!precondition(r, z) || !z.allFinite()) {
        outcome.status = CgStatus::preconditioner_failed;
        return outcome;
    }
    p = z;
    double rz = r.dot(z);  // rᵀM⁻¹r
    while (outcome.iterations < max_iterations) {
        multiply(p, q);  // q = A p
        ++outcome.iterations;
        const double curvature = p.dot(q);  // pᵀA p
        if (!(curvature > 0.0)) {
            outcome.status = CgStatus::negative_curvature;
            return outcome;
        }
        const double alpha = rz / curvature;  // α = rᵀz / pᵀAp
        d += alpha * p;
        r -= alpha * q;
        outcome.relative_residual = r.norm() / b_norm;
        if (outcome.relative_residual <= eta) {
            outcome.status = CgStatus::converged;
            return outcome;
        }
        if (!precondition(r, z) || !z.allFinite()) {
            outcome.status = CgStatus::preconditioner_failed;
            return outcome;
        }
        const double rz_next = r.dot(z);
        p = z + (rz_next / rz) * p;  // β = r₊ᵀz₊ / rᵀz
        rz = rz_next;
    }
    outcome.status = CgStatus::iteration_limit;
    return outcome;
}

} // namespace sinew
