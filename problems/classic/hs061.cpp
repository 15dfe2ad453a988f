#include "sinew/problems/classic/hs061.hpp"

namespace sinew {

Hs061::Hs061()
{
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(0, 1);
    jacobian_pattern_.add(1, 0);
    jacobian_pattern_.add(1, 2);
    // f and both constraints are separable: ∇²L is diagonal.
    for (int i = 0; i < 3; ++i)
        hessian_pattern_.add(i, i);
}

void Hs061::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs061::starting_point() const
{
    return Vector::Zero(3);
}

double Hs061::objective(ConstVectorRef x)
{
    return 4.0 * x[0] * x[0] + 2.0 * x[1] * x[1] + 2.0 * x[2] * x[2] - 33.0 * x[0] + 16.0 * x[1] - 24.0 * x[2];
}

void Hs061::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << 8.0 * x[0] - 33.0, 4.0 * x[1] + 16.0, 4.0 * x[2] - 24.0;
}

void Hs061::constraints(ConstVectorRef x, VectorRef c)
{
    c << 3.0 * x[0] - 2.0 * x[1] * x[1] - 7.0,  // c₀ = 3x₀ − 2x₁² − 7
         4.0 * x[0] - x[2] * x[2] - 11.0;       // c₁ = 4x₀ − x₂² − 11
}

void Hs061::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << 3.0, -4.0 * x[1], 4.0, -2.0 * x[2];
}

void Hs061::hessian_values(ConstVectorRef, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // σ diag(8, 4, 4) + λ₀ diag(0, −4, 0) + λ₁ diag(0, 0, −2).
    values << 8.0 * sigma, 4.0 * sigma - 4.0 * lambda[0], 4.0 * sigma - 2.0 * lambda[1];
}

} // namespace sinew
