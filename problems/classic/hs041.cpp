#include "sinew/problems/classic/hs041.hpp"

namespace sinew {

Hs041::Hs041()
{
    for (int col = 0; col < 4; ++col)
        jacobian_pattern_.add(0, col);
    // ∇²f couples x₀, x₁, x₂ off the diagonal; c₀ is linear.
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(2, 0);
    hessian_pattern_.add(2, 1);
}

void Hs041::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper << 1.0, 1.0, 1.0, 2.0;
}

void Hs041::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs041::starting_point() const
{
    return Vector::Constant(4, 2.0);
}

double Hs041::objective(ConstVectorRef x)
{
    return 2.0 - x[0] * x[1] * x[2];
}

void Hs041::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << -x[1] * x[2], -x[0] * x[2], -x[0] * x[1], 0.0;
}

void Hs041::constraints(ConstVectorRef x, VectorRef c)
{
    c[0] = x[0] + 2.0 * x[1] + 2.0 * x[2] - x[3];
}

void Hs041::jacobian_values(ConstVectorRef, VectorRef values)
{
    values << 1.0, 2.0, 2.0, -1.0;
}

void Hs041::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∇²f only, in pattern order (1,0), (2,0), (2,1).
    values << -sigma * x[2], -sigma * x[1], -sigma * x[0];
}

} // namespace sinew
