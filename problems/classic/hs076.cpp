#include "sinew/problems/classic/hs076.hpp"

namespace sinew {

Hs076::Hs076()
{
    // c₀ and c₁ involve every variable, c₂ only x₁ and x₂.
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 4; ++col)
            jacobian_pattern_.add(row, col);
    jacobian_pattern_.add(2, 1);
    jacobian_pattern_.add(2, 2);
    // ∇²f couples x₀–x₂ and x₂–x₃ only; the constraints are linear.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 0);
    hessian_pattern_.add(2, 2);
    hessian_pattern_.add(3, 2);
    hessian_pattern_.add(3, 3);
}

void Hs076::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setConstant(kInfinity);
}

void Hs076::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setConstant(kInfinity);
}

Nlp::Vector Hs076::starting_point() const
{
    return Vector::Constant(4, 0.5);
}

double Hs076::objective(ConstVectorRef x)
{
    return x[0] * x[0] + 0.5 * x[1] * x[1] + x[2] * x[2] + 0.5 * x[3] * x[3] - x[0] * x[2] + x[2] * x[3] - x[0] -
           3.0 * x[1] + x[2] - x[3];
}

void Hs076::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << 2.0 * x[0] - x[2] - 1.0,
            x[1] - 3.0,
            2.0 * x[2] - x[0] + x[3] + 1.0,
            x[3] + x[2] - 1.0;
}

void Hs076::constraints(ConstVectorRef x, VectorRef c)
{
    c << 5.0 - x[0] - 2.0 * x[1] - x[2] - x[3],
         4.0 - 3.0 * x[0] - x[1] - 2.0 * x[2] + x[3],
         x[1] + 4.0 * x[2] - 1.5;
}

void Hs076::jacobian_values(ConstVectorRef, VectorRef values)
{
    values << -1.0, -2.0, -1.0, -1.0,  // ∇c₀
              -3.0, -1.0, -2.0, 1.0,   // ∇c₁
              1.0, 4.0;                // ∂c₂/∂x₁, ∂c₂/∂x₂
}

void Hs076::hessian_values(ConstVectorRef, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∇²f only, in pattern order (0,0), (1,1), (2,0), (2,2), (3,2), (3,3).
    values << 2.0 * sigma, sigma, -sigma, 2.0 * sigma, sigma, sigma;
}

} // namespace sinew
