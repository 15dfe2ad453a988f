#include "sinew/energies/models/plane_fixed_corotated.hpp"

#include "sinew/energies/models/plane_derivatives.hpp"

#include <cmath>
#include <limits>

namespace sinew {

PlaneFixedCorotated::PlaneFixedCorotated(const ParameterValues& parameters)
    : mu_(parameters.at("mu")), lambda_(parameters.at("lambda"))
{
}

double PlaneFixedCorotated::energy(const Deformation& F, const Point& point) const
{
    return evaluate(F, point, nullptr, nullptr, Projection::none);
}

double PlaneFixedCorotated::evaluate(const Deformation& F, const Point&, Stress* P, Stiffness* dPdF,
                                     Projection projection) const
{
    constexpr double kInf = std::numeric_limits<double>::infinity();
    // R = [[a, −b], [b, a]]/r maximizes tr(RᵀF) = r = σ₁ + σ₂ over rotations.
    const double a = F(0, 0) + F(1, 1), b = F(1, 0) - F(0, 1);
    const double r = std::hypot(a, b);
    Eigen::Matrix2d R = Eigen::Matrix2d::Identity();
    if (r > 0.0)
        R << a / r, -b / r, b / r, a / r;
    const double J = F.determinant();
    // ψ = μ‖F − R‖² + λ/2 (J − 1)² (‖F − R‖² from F − R, not as ‖F‖² − 2r + 2, which
    // cancels near rest); NaN only from ∞ − ∞, where ψ overflows.
    double psi = mu_ * (F - R).squaredNorm() + 0.5 * lambda_ * (J - 1.0) * (J - 1.0);
    if (!(psi < kInf))
        psi = kInf;
    const Eigen::Matrix2d cof = plane_determinant_gradient(F);
    if (P)
        *P = 2.0 * mu_ * (F - R) + lambda_ * (J - 1.0) * cof;  // P = 2μ(F − R) + λ(J − 1) cof F
    if (dPdF) {
        Eigen::Matrix2d quarter_turn;
        quarter_turn << 0.0, -1.0, 1.0, 0.0;
        const Eigen::Matrix2d twist = quarter_turn * R;
        const Eigen::Map<const Eigen::Vector4d> t(twist.data()), g(cof.data());
        // ∂R/∂F = t tᵀ / (σ₁ + σ₂)
        *dPdF = 2.0 * mu_ * (Stiffness::Identity() - t * t.transpose() / std::max(r, kMinSingularValueSum)) +
                lambda_ * g * g.transpose();
        add_plane_determinant_hessian(lambda_ * (J - 1.0), *dPdF);
        if (projection == Projection::clamp)
            clamp_plane_stiffness(*dPdF);
    }
    return psi;
}

} // namespace sinew
