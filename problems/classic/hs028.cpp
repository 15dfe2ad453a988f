#include "sinew/problems/classic/hs028.hpp"

namespace sinew {

Hs028::Hs028()
{
    for (int col = 0; col < 3; ++col)
        jacobian_pattern_.add(0, col);
    // ∇²f is tridiagonal ((2,0) is structurally zero); c₀ is linear.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 1);
    hessian_pattern_.add(2, 2);
}

void Hs028::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs028::starting_point() const
{
    Vector x(3);
    x << -4.0, 1.0, 1.0;
    return x;
}

double Hs028::objective(ConstVectorRef x)
{
    const double a = x[0] + x[1];
    const double b = x[1] + x[2];
    return a * a + b * b;  // (x₀ + x₁)² + (x₁ + x₂)²
}

void Hs028::gradient(ConstVectorRef x, VectorRef grad)
{
    const double a = x[0] + x[1];
    const double b = x[1] + x[2];
    grad << 2.0 * a, 2.0 * a + 2.0 * b, 2.0 * b;
}

void Hs028::constraints(ConstVectorRef x, VectorRef c)
{
    c[0] = x[0] + 2.0 * x[1] + 3.0 * x[2] - 1.0;
}

void Hs028::jacobian_values(ConstVectorRef, VectorRef values)
{
    values << 1.0, 2.0, 3.0;
}

void Hs028::hessian_values(ConstVectorRef, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∇²f only, in pattern order (0,0), (1,0), (1,1), (2,1), (2,2).
    values << 2.0 * sigma, 2.0 * sigma, 4.0 * sigma, 2.0 * sigma, 2.0 * sigma;
}

} // namespace sinew
