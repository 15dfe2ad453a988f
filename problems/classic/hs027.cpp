#include "sinew/problems/classic/hs027.hpp"

namespace sinew {

Hs027::Hs027()
{
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(0, 2);
    // f involves x₀, x₁ only and c₀ adds x₂²: (2,0) and (2,1) are structurally zero.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 2);
}

void Hs027::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs027::starting_point() const
{
    return Vector::Constant(3, 2.0);
}

double Hs027::objective(ConstVectorRef x)
{
    const double a = x[0] - 1.0;
    const double b = x[1] - x[0] * x[0];
    return 0.01 * a * a + b * b;  // 0.01(x₀ − 1)² + (x₁ − x₀²)²
}

void Hs027::gradient(ConstVectorRef x, VectorRef grad)
{
    const double b = x[1] - x[0] * x[0];
    grad << 0.02 * (x[0] - 1.0) - 4.0 * x[0] * b, 2.0 * b, 0.0;
}

void Hs027::constraints(ConstVectorRef x, VectorRef c)
{
    c[0] = x[0] + x[2] * x[2] + 1.0;
}

void Hs027::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << 1.0, 2.0 * x[2];
}

void Hs027::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // σ ∇²f + λ₀ ∇²c₀ with ∇²c₀ = 2 e₂e₂ᵀ; pattern order (0,0), (1,0), (1,1), (2,2).
    values << sigma * (0.02 + 12.0 * x[0] * x[0] - 4.0 * x[1]),
              sigma * (-4.0 * x[0]),
              sigma * 2.0,
              2.0 * lambda[0];
}

} // namespace sinew
