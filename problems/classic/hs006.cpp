#include "sinew/problems/classic/hs006.hpp"

namespace sinew {

Hs006::Hs006()
{
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(0, 1);
    // f and c₀ are both nonlinear in x₀ only: ∇²L has the single entry (0,0).
    hessian_pattern_.add(0, 0);
}

void Hs006::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs006::starting_point() const
{
    Vector x(2);
    x << -1.2, 1.0;
    return x;
}

double Hs006::objective(ConstVectorRef x)
{
    const double r = 1.0 - x[0];
    return r * r;  // (1 − x₀)²
}

void Hs006::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << -2.0 * (1.0 - x[0]), 0.0;
}

void Hs006::constraints(ConstVectorRef x, VectorRef c)
{
    c[0] = 10.0 * (x[1] - x[0] * x[0]);  // c₀ = 10 (x₁ − x₀²)
}

void Hs006::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << -20.0 * x[0], 10.0;
}

void Hs006::hessian_values(ConstVectorRef, double sigma, ConstVectorRef lambda, VectorRef values)
{
    values[0] = 2.0 * sigma - 20.0 * lambda[0];  // σ ∂²f/∂x₀² + λ₀ ∂²c₀/∂x₀²
}

} // namespace sinew
