#include "sinew/problems/classic/hs077.hpp"

#include <cmath>

namespace sinew {
namespace {

const double kSqrt2 = std::sqrt(2.0);

} // namespace

Hs077::Hs077()
{
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(0, 3);
    jacobian_pattern_.add(0, 4);
    jacobian_pattern_.add(1, 1);
    jacobian_pattern_.add(1, 2);
    jacobian_pattern_.add(1, 3);
    // ∇²f couples only x₀ and x₁; c₀ couples x₀–x₃ and x₃–x₄, c₁ couples x₂–x₃.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 2);
    hessian_pattern_.add(3, 0);
    hessian_pattern_.add(3, 2);
    hessian_pattern_.add(3, 3);
    hessian_pattern_.add(4, 3);
    hessian_pattern_.add(4, 4);
}

void Hs077::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs077::starting_point() const
{
    return Vector::Constant(5, 2.0);
}

double Hs077::objective(ConstVectorRef x)
{
    const double a = x[0] - 1.0;
    const double b = x[0] - x[1];
    const double c = x[2] - 1.0;
    const double d2 = (x[3] - 1.0) * (x[3] - 1.0);
    const double e2 = (x[4] - 1.0) * (x[4] - 1.0);
    return a * a + b * b + c * c + d2 * d2 + e2 * e2 * e2;
}

void Hs077::gradient(ConstVectorRef x, VectorRef grad)
{
    const double d = x[3] - 1.0;
    const double e = x[4] - 1.0;
    const double e2 = e * e;
    grad << 2.0 * (x[0] - 1.0) + 2.0 * (x[0] - x[1]),
            -2.0 * (x[0] - x[1]),
            2.0 * (x[2] - 1.0),
            4.0 * d * d * d,
            6.0 * e2 * e2 * e;
}

void Hs077::constraints(ConstVectorRef x, VectorRef c)
{
    const double x2_squared = x[2] * x[2];
    c << x[0] * x[0] * x[3] + std::sin(x[3] - x[4]) - 2.0 * kSqrt2,  // c₀ = x₀²x₃ + sin(x₃ − x₄) − 2√2
         x[1] + x2_squared * x2_squared * x[3] * x[3] - 8.0 - kSqrt2;   // c₁ = x₁ + x₂⁴x₃² − 8 − √2
}

void Hs077::jacobian_values(ConstVectorRef x, VectorRef values)
{
    const double cs = std::cos(x[3] - x[4]);
    const double x2_cubed = x[2] * x[2] * x[2];
    values << 2.0 * x[0] * x[3], x[0] * x[0] + cs, -cs,                        // ∇c₀ at (0,0), (0,3), (0,4)
              1.0, 4.0 * x2_cubed * x[3] * x[3], 2.0 * x2_cubed * x[2] * x[3];  // ∇c₁ at (1,1), (1,2), (1,3)
}

void Hs077::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // Pattern order (0,0), (1,0), (1,1), (2,2), (3,0), (3,2), (3,3), (4,3), (4,4).
    // ∇²f = [4 −2; −2 2] on (x₀, x₁), 2 at (2,2), 12(x₃ − 1)², 30(x₄ − 1)⁴;
    // ∇²c₀: (0,0) 2x₃, (3,0) 2x₀, and −sin(x₃ − x₄) [1 −1; −1 1] on (x₃, x₄);
    // ∇²c₁: (2,2) 12x₂²x₃², (3,2) 8x₂³x₃, (3,3) 2x₂⁴.
    const double s = sigma;
    const double l0 = lambda[0];
    const double l1 = lambda[1];
    const double sn = std::sin(x[3] - x[4]);
    const double d = x[3] - 1.0;
    const double e2 = (x[4] - 1.0) * (x[4] - 1.0);
    const double x2_squared = x[2] * x[2];
    values << 4.0 * s + 2.0 * x[3] * l0,
              -2.0 * s,
              2.0 * s,
              2.0 * s + 12.0 * x2_squared * x[3] * x[3] * l1,
              2.0 * x[0] * l0,
              8.0 * x2_squared * x[2] * x[3] * l1,
              12.0 * d * d * s - sn * l0 + 2.0 * x2_squared * x2_squared * l1,
              sn * l0,
              30.0 * e2 * e2 * s - sn * l0;
}

} // namespace sinew
