#include "sinew/runs/jacobi_cg.hpp"

#include "sinew/solvers/newton/preconditioned_cg.hpp"

namespace sinew {

SpdSolve jacobi_cg(double tolerance, int max_iterations)
{
    return [tolerance, max_iterations](const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>& multiply,
                                       const Eigen::VectorXd& diagonal, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
        const auto jacobi = [&diagonal](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
            z = r.cwiseQuotient(diagonal);  // z = D⁻¹ r
            return true;
        };
        const CgOutcome outcome = preconditioned_cg(multiply, jacobi, b, tolerance, max_iterations, x);
        return SpdSolveOutcome{outcome.status == CgStatus::converged, outcome.iterations, outcome.relative_residual};
    };
}

} // namespace sinew
