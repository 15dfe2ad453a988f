#include "sinew/problems/classic/hs060.hpp"

#include <cmath>

namespace sinew {
namespace {

const double kRightHandSide = 4.0 + 3.0 * std::sqrt(2.0);  // 4 + 3√2

} // namespace

Hs060::Hs060()
{
    for (int col = 0; col < 3; ++col)
        jacobian_pattern_.add(0, col);
    // f and c₀ couple (x₀, x₁) and (x₁, x₂) but not (x₀, x₂): tridiagonal.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 1);
    hessian_pattern_.add(2, 2);
}

void Hs060::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setConstant(-10.0);
    upper.setConstant(10.0);
}

void Hs060::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs060::starting_point() const
{
    return Vector::Constant(3, 2.0);
}

double Hs060::objective(ConstVectorRef x)
{
    const double a = x[0] - 1.0;
    const double b = x[0] - x[1];
    const double d2 = (x[1] - x[2]) * (x[1] - x[2]);
    return a * a + b * b + d2 * d2;  // (x₀ − 1)² + (x₀ − x₁)² + (x₁ − x₂)⁴
}

void Hs060::gradient(ConstVectorRef x, VectorRef grad)
{
    const double b = x[0] - x[1];
    const double d = x[1] - x[2];
    const double d3 = 4.0 * d * d * d;
    grad << 2.0 * (x[0] - 1.0) + 2.0 * b, -2.0 * b + d3, -d3;
}

void Hs060::constraints(ConstVectorRef x, VectorRef c)
{
    const double x2_squared = x[2] * x[2];
    c[0] = x[0] * (1.0 + x[1] * x[1]) + x2_squared * x2_squared - kRightHandSide;
}

void Hs060::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << 1.0 + x[1] * x[1], 2.0 * x[0] * x[1], 4.0 * x[2] * x[2] * x[2];
}

void Hs060::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // Pattern order (0,0), (1,0), (1,1), (2,1), (2,2). With p = 12(x₁ − x₂)²:
    // ∇²f = [4 −2 0; −2 2 + p −p; 0 −p p], ∇²c₀ = [0 2x₁ 0; 2x₁ 2x₀ 0; 0 0 12x₂²].
    const double s = sigma;
    const double l = lambda[0];
    const double p = 12.0 * (x[1] - x[2]) * (x[1] - x[2]);
    values << 4.0 * s,
              -2.0 * s + 2.0 * x[1] * l,
              (2.0 + p) * s + 2.0 * x[0] * l,
              -p * s,
              p * s + 12.0 * x[2] * x[2] * l;
}

} // namespace sinew
