#include "sinew/problems/classic/hs065.hpp"

namespace sinew {

Hs065::Hs065()
{
    for (int col = 0; col < 3; ++col)
        jacobian_pattern_.add(0, col);
    // x₂ is decoupled from x₀, x₁ in f and in c₀: (2,0) and (2,1) are structurally zero.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 2);
}

void Hs065::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower << -4.5, -4.5, -5.0;
    upper << 4.5, 4.5, 5.0;
}

void Hs065::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setConstant(kInfinity);
}

Nlp::Vector Hs065::starting_point() const
{
    Vector x(3);
    x << -5.0, 5.0, 0.0;
    return x;
}

double Hs065::objective(ConstVectorRef x)
{
    const double d = x[0] - x[1];         // x₀ − x₁
    const double s = x[0] + x[1] - 10.0;  // x₀ + x₁ − 10
    const double t = x[2] - 5.0;          // x₂ − 5
    return d * d + s * s / 9.0 + t * t;
}

void Hs065::gradient(ConstVectorRef x, VectorRef grad)
{
    const double d = x[0] - x[1];
    const double s = x[0] + x[1] - 10.0;
    grad << 2.0 * d + 2.0 * s / 9.0, -2.0 * d + 2.0 * s / 9.0, 2.0 * (x[2] - 5.0);
}

void Hs065::constraints(ConstVectorRef x, VectorRef c)
{
    c[0] = 48.0 - x.squaredNorm();  // 48 − x₀² − x₁² − x₂²
}

void Hs065::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values = -2.0 * x;
}

void Hs065::hessian_values(ConstVectorRef, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // σ ∇²f + λ₀ ∇²c₀ with ∇²c₀ = −2I, in pattern order (0,0), (1,0), (1,1), (2,2).
    const double l0 = lambda[0];
    values << sigma * (2.0 + 2.0 / 9.0) - 2.0 * l0,
              sigma * (-2.0 + 2.0 / 9.0),
              sigma * (2.0 + 2.0 / 9.0) - 2.0 * l0,
              sigma * 2.0 - 2.0 * l0;
}

} // namespace sinew
