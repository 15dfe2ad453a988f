#include "sinew/problems/classic/hs035.hpp"

namespace sinew {

Hs035::Hs035()
{
    for (int col = 0; col < 3; ++col)
        jacobian_pattern_.add(0, col);
    // ∇²f has no x₁x₂ term, so (2,1) is structurally zero; c₀ is linear.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 0);
    hessian_pattern_.add(2, 2);
}

void Hs035::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setConstant(kInfinity);
}

void Hs035::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setConstant(kInfinity);
}

Nlp::Vector Hs035::starting_point() const
{
    return Vector::Constant(3, 0.5);
}

double Hs035::objective(ConstVectorRef x)
{
    return 9.0 - 8.0 * x[0] - 6.0 * x[1] - 4.0 * x[2] + 2.0 * x[0] * x[0] + 2.0 * x[1] * x[1] + x[2] * x[2] +
           2.0 * x[0] * x[1] + 2.0 * x[0] * x[2];
}

void Hs035::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << -8.0 + 4.0 * x[0] + 2.0 * x[1] + 2.0 * x[2],
            -6.0 + 4.0 * x[1] + 2.0 * x[0],
            -4.0 + 2.0 * x[2] + 2.0 * x[0];
}

void Hs035::constraints(ConstVectorRef x, VectorRef c)
{
    c[0] = 3.0 - x[0] - x[1] - 2.0 * x[2];
}

void Hs035::jacobian_values(ConstVectorRef, VectorRef values)
{
    values << -1.0, -1.0, -2.0;
}

void Hs035::hessian_values(ConstVectorRef, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∇²f only, in pattern order (0,0), (1,0), (1,1), (2,0), (2,2).
    values << 4.0 * sigma, 2.0 * sigma, 4.0 * sigma, 2.0 * sigma, 2.0 * sigma;
}

} // namespace sinew
