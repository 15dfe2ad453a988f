#include "sinew/problems/classic/hs053.hpp"

namespace sinew {

Hs053::Hs053()
{
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(0, 1);
    jacobian_pattern_.add(1, 2);
    jacobian_pattern_.add(1, 3);
    jacobian_pattern_.add(1, 4);
    jacobian_pattern_.add(2, 1);
    jacobian_pattern_.add(2, 4);
    // ∇²f is constant: a tridiagonal block on (x₀, x₁, x₂), then 2 on x₃, x₄.
    // The constraints are linear.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 1);
    hessian_pattern_.add(2, 2);
    hessian_pattern_.add(3, 3);
    hessian_pattern_.add(4, 4);
}

void Hs053::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setConstant(-10.0);
    upper.setConstant(10.0);
}

void Hs053::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs053::starting_point() const
{
    return Vector::Constant(5, 2.0);
}

double Hs053::objective(ConstVectorRef x)
{
    const double a = x[0] - x[1];
    const double b = x[1] + x[2] - 2.0;
    const double c = x[3] - 1.0;
    const double d = x[4] - 1.0;
    return a * a + b * b + c * c + d * d;
}

void Hs053::gradient(ConstVectorRef x, VectorRef grad)
{
    const double a = x[0] - x[1];
    const double b = x[1] + x[2] - 2.0;
    grad << 2.0 * a, -2.0 * a + 2.0 * b, 2.0 * b, 2.0 * (x[3] - 1.0), 2.0 * (x[4] - 1.0);
}

void Hs053::constraints(ConstVectorRef x, VectorRef c)
{
    c << x[0] + 3.0 * x[1],         // c₀ = x₀ + 3x₁
         x[2] + x[3] - 2.0 * x[4],  // c₁ = x₂ + x₃ − 2x₄
         x[1] - x[4];               // c₂ = x₁ − x₄
}

void Hs053::jacobian_values(ConstVectorRef, VectorRef values)
{
    values << 1.0, 3.0, 1.0, 1.0, -2.0, 1.0, -1.0;
}

void Hs053::hessian_values(ConstVectorRef, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∇²f only, in pattern order (0,0), (1,0), (1,1), (2,1), (2,2), (3,3), (4,4).
    values << 2.0 * sigma, -2.0 * sigma, 4.0 * sigma, 2.0 * sigma, 2.0 * sigma, 2.0 * sigma, 2.0 * sigma;
}

} // namespace sinew
