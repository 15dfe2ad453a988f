#include "sinew/problems/classic/hs063.hpp"

namespace sinew {

Hs063::Hs063()
{
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 3; ++col)
            jacobian_pattern_.add(row, col);
    // f has no x₁x₂ term and ∇²c₁ = 2I: (2,1) is structurally zero.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 0);
    hessian_pattern_.add(2, 2);
}

void Hs063::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setConstant(kInfinity);
}

void Hs063::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs063::starting_point() const
{
    return Vector::Constant(3, 2.0);
}

double Hs063::objective(ConstVectorRef x)
{
    return 1000.0 - x[0] * x[0] - 2.0 * x[1] * x[1] - x[2] * x[2] - x[0] * x[1] - x[0] * x[2];
}

void Hs063::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << -2.0 * x[0] - x[1] - x[2], -4.0 * x[1] - x[0], -2.0 * x[2] - x[0];
}

void Hs063::constraints(ConstVectorRef x, VectorRef c)
{
    c << 8.0 * x[0] + 14.0 * x[1] + 7.0 * x[2] - 56.0,  // c₀ = 8x₀ + 14x₁ + 7x₂ − 56
         x.squaredNorm() - 25.0;                        // c₁ = Σ xᵢ² − 25
}

void Hs063::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << 8.0, 14.0, 7.0,                       // ∇c₀
              2.0 * x[0], 2.0 * x[1], 2.0 * x[2];  // ∇c₁ = 2x
}

void Hs063::hessian_values(ConstVectorRef, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // σ ∇²f + λ₁ 2I, in pattern order (0,0), (1,0), (1,1), (2,0), (2,2).
    const double l1 = lambda[1];
    values << -2.0 * sigma + 2.0 * l1, -sigma, -4.0 * sigma + 2.0 * l1, -sigma, -2.0 * sigma + 2.0 * l1;
}

} // namespace sinew
