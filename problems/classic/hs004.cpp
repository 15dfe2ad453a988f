#include "sinew/problems/classic/hs004.hpp"

namespace sinew {

Hs004::Hs004()
{
    // f is linear in x₁: only (0,0) is nonzero.
    hessian_pattern_.add(0, 0);
}

void Hs004::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower << 1.0, 0.0;
    upper.setConstant(kInfinity);
}

Nlp::Vector Hs004::starting_point() const
{
    Vector x(2);
    x << 1.125, 0.125;
    return x;
}

double Hs004::objective(ConstVectorRef x)
{
    const double a = x[0] + 1.0;
    return a * a * a / 3.0 + x[1];  // (x₀ + 1)³ / 3 + x₁
}

void Hs004::gradient(ConstVectorRef x, VectorRef grad)
{
    const double a = x[0] + 1.0;
    grad << a * a, 1.0;
}

void Hs004::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∂²f/∂x₀² = 2σ(x₀ + 1).
    values[0] = 2.0 * sigma * (x[0] + 1.0);
}

} // namespace sinew
