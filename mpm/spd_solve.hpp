#pragma once
// The linear solves mpm/ poses and does not carry out: a symmetric positive
// (semi)definite system given by its product, solved by whatever the layer
// above binds (runs/ and the tests: solvers/'s preconditioned_cg), so that
// mpm/ knows nothing of solvers/. The implicit damage (seed 004 Alg. 9) and
// the inextensibility's Schur complement (seed 004 Alg. 11) use it.
#include <Eigen/Core>

#include <functional>

namespace sinew {

struct SpdSolveOutcome {
    bool converged = false;
    int iterations = 0;
    double relative_residual = 1.0;  ///< ‖b − S x‖ / ‖b‖
};

/// A solver of S x = b, S symmetric positive definite (or semidefinite with
/// b in its range) given by its product `multiply(v, S v)`, with the Jacobi
/// preconditioner of `diagonal`.
using SpdSolve = std::function<SpdSolveOutcome(const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>& multiply,
                                               const Eigen::VectorXd& diagonal, const Eigen::VectorXd& b, Eigen::VectorXd& x)>;

} // namespace sinew
