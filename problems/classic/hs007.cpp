#include "sinew/problems/classic/hs007.hpp"

#include <cmath>

namespace sinew {

Hs007::Hs007()
{
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(0, 1);
    // f and c₀ are each a function of x₀ plus one of x₁: ∇²L is diagonal.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 1);
}

void Hs007::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs007::starting_point() const
{
    return Vector::Constant(2, 2.0);
}

double Hs007::objective(ConstVectorRef x)
{
    return std::log(1.0 + x[0] * x[0]) - x[1];  // ln(1 + x₀²) − x₁
}

void Hs007::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << 2.0 * x[0] / (1.0 + x[0] * x[0]), -1.0;
}

void Hs007::constraints(ConstVectorRef x, VectorRef c)
{
    const double a = 1.0 + x[0] * x[0];
    c[0] = a * a + x[1] * x[1] - 4.0;  // (1 + x₀²)² + x₁² − 4
}

void Hs007::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << 4.0 * x[0] * (1.0 + x[0] * x[0]), 2.0 * x[1];
}

void Hs007::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // ∂²f/∂x₀² = 2(1 − x₀²)/(1 + x₀²)², ∇²c₀ = diag(4 + 12x₀², 2); pattern order (0,0), (1,1).
    const double a = 1.0 + x[0] * x[0];
    values << sigma * 2.0 * (1.0 - x[0] * x[0]) / (a * a) + lambda[0] * (4.0 + 12.0 * x[0] * x[0]),
              2.0 * lambda[0];
}

} // namespace sinew
