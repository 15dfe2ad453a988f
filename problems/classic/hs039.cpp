#include "sinew/problems/classic/hs039.hpp"

namespace sinew {

Hs039::Hs039()
{
    // c₀ involves x₀, x₁, x₂; c₁ involves x₀, x₁, x₃.
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(0, 1);
    jacobian_pattern_.add(0, 2);
    jacobian_pattern_.add(1, 0);
    jacobian_pattern_.add(1, 1);
    jacobian_pattern_.add(1, 3);
    // f is linear and each constraint is separable: ∇²L is diagonal, with
    // (1,1) structurally zero.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(2, 2);
    hessian_pattern_.add(3, 3);
}

void Hs039::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs039::starting_point() const
{
    return Vector::Constant(4, 2.0);
}

double Hs039::objective(ConstVectorRef x)
{
    return -x[0];
}

void Hs039::gradient(ConstVectorRef, VectorRef grad)
{
    grad << -1.0, 0.0, 0.0, 0.0;
}

void Hs039::constraints(ConstVectorRef x, VectorRef c)
{
    c << x[1] - x[0] * x[0] * x[0] - x[2] * x[2],  // c₀ = x₁ − x₀³ − x₂²
         x[0] * x[0] - x[1] - x[3] * x[3];         // c₁ = x₀² − x₁ − x₃²
}

void Hs039::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << -3.0 * x[0] * x[0], 1.0, -2.0 * x[2],  // ∇c₀
              2.0 * x[0], -1.0, -2.0 * x[3];         // ∇c₁
}

void Hs039::hessian_values(ConstVectorRef x, double, ConstVectorRef lambda, VectorRef values)
{
    // λ₀ ∇²c₀ + λ₁ ∇²c₁ (∇²f = 0); pattern order (0,0), (2,2), (3,3).
    values << -6.0 * x[0] * lambda[0] + 2.0 * lambda[1],
              -2.0 * lambda[0],
              -2.0 * lambda[1];
}

} // namespace sinew
