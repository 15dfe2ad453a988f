#include "sinew/problems/classic/hs071.hpp"

namespace sinew {

Hs071::Hs071()
{
    // Both constraints depend on every variable: a dense 2 × 4 Jacobian, row by row.
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 4; ++col)
            jacobian_pattern_.add(row, col);
    // ∇²L is dense: the whole lower triangle, row by row.
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col <= row; ++col)
            hessian_pattern_.add(row, col);
}

void Hs071::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setConstant(1.0);
    upper.setConstant(5.0);
}

void Hs071::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower << 25.0, 40.0;
    upper << kInfinity, 40.0;
}

Nlp::Vector Hs071::starting_point() const
{
    Vector x(4);
    x << 1.0, 5.0, 5.0, 1.0;
    return x;
}

double Hs071::objective(ConstVectorRef x)
{
    return x[0] * x[3] * (x[0] + x[1] + x[2]) + x[2];  // x₀ x₃ (x₀ + x₁ + x₂) + x₂
}

void Hs071::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << x[3] * (2.0 * x[0] + x[1] + x[2]),
            x[0] * x[3],
            x[0] * x[3] + 1.0,
            x[0] * (x[0] + x[1] + x[2]);
}

void Hs071::constraints(ConstVectorRef x, VectorRef c)
{
    c << x[0] * x[1] * x[2] * x[3],  // c₀ = x₀ x₁ x₂ x₃
         x.squaredNorm();            // c₁ = Σ xᵢ²
}

void Hs071::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << x[1] * x[2] * x[3], x[0] * x[2] * x[3], x[0] * x[1] * x[3], x[0] * x[1] * x[2],  // ∇c₀
              2.0 * x[0], 2.0 * x[1], 2.0 * x[2], 2.0 * x[3];                                  // ∇c₁ = 2x
}

void Hs071::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // σ ∇²f + λ₀ ∇²c₀ + λ₁ ∇²c₁, with ∇²c₁ = 2I; entries in the order of
    // the pattern: (0,0), (1,0), (1,1), (2,0), (2,1), (2,2), (3,0), (3,1), (3,2), (3,3).
    const double s = sigma;
    const double l0 = lambda[0];
    const double l1 = lambda[1];
    values << s * 2.0 * x[3] + 2.0 * l1,
              s * x[3] + l0 * x[2] * x[3],
              2.0 * l1,
              s * x[3] + l0 * x[1] * x[3],
              l0 * x[0] * x[3],
              2.0 * l1,
              s * (2.0 * x[0] + x[1] + x[2]) + l0 * x[1] * x[2],
              s * x[0] + l0 * x[0] * x[2],
              s * x[0] + l0 * x[0] * x[1],
              2.0 * l1;
}

} // namespace sinew
