#include "sinew/problems/classic/hs042.hpp"

namespace sinew {

Hs042::Hs042()
{
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(1, 2);
    jacobian_pattern_.add(1, 3);
    // f and c₁ are separable: ∇²L is diagonal.
    for (int i = 0; i < 4; ++i)
        hessian_pattern_.add(i, i);
}

void Hs042::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs042::starting_point() const
{
    return Vector::Ones(4);
}

double Hs042::objective(ConstVectorRef x)
{
    double f = 0.0;
    for (int i = 0; i < 4; ++i)
        f += (x[i] - (i + 1)) * (x[i] - (i + 1));  // Σ (xᵢ − (i + 1))²
    return f;
}

void Hs042::gradient(ConstVectorRef x, VectorRef grad)
{
    for (int i = 0; i < 4; ++i)
        grad[i] = 2.0 * (x[i] - (i + 1));
}

void Hs042::constraints(ConstVectorRef x, VectorRef c)
{
    c << x[0] - 2.0,                        // c₀ = x₀ − 2
         x[2] * x[2] + x[3] * x[3] - 2.0;  // c₁ = x₂² + x₃² − 2
}

void Hs042::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << 1.0, 2.0 * x[2], 2.0 * x[3];
}

void Hs042::hessian_values(ConstVectorRef, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // σ 2I + λ₁ diag(0, 0, 2, 2).
    values << 2.0 * sigma, 2.0 * sigma, 2.0 * sigma + 2.0 * lambda[1], 2.0 * sigma + 2.0 * lambda[1];
}

} // namespace sinew
