#include "sinew/mpm/inextensibility/schur_projection.hpp"

namespace sinew {

SchurProjectionReport project_onto_rows(const LinearVelocityRows& rows, const Eigen::VectorXd& masses, Eigen::VectorXd& y,
                                        const SpdSolve& solve)
{
    SchurProjectionReport report;
    report.violation_before = rows.violation(y);
    if (rows.rows() == 0 || report.violation_before == 0.0) {
        report.solve.converged = true;
        report.solve.relative_residual = 0.0;
        return report;
    }
    const Eigen::VectorXd inverse_mass = masses.cwiseInverse();                  // M⁻¹
    const Eigen::VectorXd residual = rows.B * y - rows.rhs;                       // B M⁻¹ b − rhs, b = M y*
    Eigen::VectorXd diagonal = rows.B.cwiseAbs2() * inverse_mass;                 // diag L = Σ_j B_cj² / m_j
    const auto multiply = [&](const Eigen::VectorXd& lambda, Eigen::VectorXd& product) {
        product = rows.B * inverse_mass.cwiseProduct(rows.B.transpose() * lambda);  // L λ = B M⁻¹ Bᵀ λ
    };
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(rows.rows());
    report.solve = solve(multiply, diagonal, residual, lambda);
    y -= inverse_mass.cwiseProduct(rows.B.transpose() * lambda);  // y = M⁻¹ (b − Bᵀ λ)
    report.violation_after = rows.violation(y);
    return report;
}

} // namespace sinew
