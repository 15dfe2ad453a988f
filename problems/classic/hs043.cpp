#include "sinew/problems/classic/hs043.hpp"

namespace sinew {

Hs043::Hs043()
{
    // Every constraint has a square of every variable: a dense 3 × 4 Jacobian, row by row.
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 4; ++col)
            jacobian_pattern_.add(row, col);
    // f and the cᵢ are separable: ∇²L is diagonal.
    for (int i = 0; i < 4; ++i)
        hessian_pattern_.add(i, i);
}

void Hs043::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setConstant(kInfinity);
}

Nlp::Vector Hs043::starting_point() const
{
    return Vector::Zero(4);
}

double Hs043::objective(ConstVectorRef x)
{
    return x[0] * x[0] + x[1] * x[1] + 2.0 * x[2] * x[2] + x[3] * x[3] - 5.0 * x[0] - 5.0 * x[1] - 21.0 * x[2] +
           7.0 * x[3];
}

void Hs043::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << 2.0 * x[0] - 5.0, 2.0 * x[1] - 5.0, 4.0 * x[2] - 21.0, 2.0 * x[3] + 7.0;
}

void Hs043::constraints(ConstVectorRef x, VectorRef c)
{
    const double x0s = x[0] * x[0];
    const double x1s = x[1] * x[1];
    const double x2s = x[2] * x[2];
    const double x3s = x[3] * x[3];
    c << 8.0 - x0s - x1s - x2s - x3s - x[0] + x[1] - x[2] + x[3],
         10.0 - x0s - 2.0 * x1s - x2s - 2.0 * x3s + x[0] + x[3],
         5.0 - 2.0 * x0s - x1s - x2s - 2.0 * x[0] + x[1] + x[3];
}

void Hs043::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << -2.0 * x[0] - 1.0, -2.0 * x[1] + 1.0, -2.0 * x[2] - 1.0, -2.0 * x[3] + 1.0,  // ∇c₀
              -2.0 * x[0] + 1.0, -4.0 * x[1], -2.0 * x[2], -4.0 * x[3] + 1.0,              // ∇c₁
              -4.0 * x[0] - 2.0, -2.0 * x[1] + 1.0, -2.0 * x[2], 1.0;                      // ∇c₂
}

void Hs043::hessian_values(ConstVectorRef, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // Diagonal of σ ∇²f + Σ λᵢ ∇²cᵢ: ∇²f = diag(2, 2, 4, 2),
    // ∇²c₀ = diag(−2, −2, −2, −2), ∇²c₁ = diag(−2, −4, −2, −4), ∇²c₂ = diag(−4, −2, −2, 0).
    const double l0 = lambda[0];
    const double l1 = lambda[1];
    const double l2 = lambda[2];
    values << 2.0 * sigma - 2.0 * l0 - 2.0 * l1 - 4.0 * l2,
              2.0 * sigma - 2.0 * l0 - 4.0 * l1 - 2.0 * l2,
              4.0 * sigma - 2.0 * l0 - 2.0 * l1 - 2.0 * l2,
              2.0 * sigma - 2.0 * l0 - 4.0 * l1;
}

} // namespace sinew
