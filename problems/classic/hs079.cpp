#include "sinew/problems/classic/hs079.hpp"

#include <cmath>

namespace sinew {
namespace {

const double kSqrt2 = std::sqrt(2.0);

} // namespace

Hs079::Hs079()
{
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(0, 1);
    jacobian_pattern_.add(0, 2);
    jacobian_pattern_.add(1, 1);
    jacobian_pattern_.add(1, 2);
    jacobian_pattern_.add(1, 3);
    jacobian_pattern_.add(2, 0);
    jacobian_pattern_.add(2, 4);
    // ∇²f is tridiagonal (a chain of differences); c₂ = x₀x₄ − 2 adds (4,0).
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 1);
    hessian_pattern_.add(2, 2);
    hessian_pattern_.add(3, 2);
    hessian_pattern_.add(3, 3);
    hessian_pattern_.add(4, 0);
    hessian_pattern_.add(4, 3);
    hessian_pattern_.add(4, 4);
}

void Hs079::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs079::starting_point() const
{
    return Vector::Constant(5, 2.0);
}

double Hs079::objective(ConstVectorRef x)
{
    const double a = x[0] - 1.0;
    const double b = x[0] - x[1];
    const double c = x[1] - x[2];
    const double d2 = (x[2] - x[3]) * (x[2] - x[3]);
    const double e2 = (x[3] - x[4]) * (x[3] - x[4]);
    return a * a + b * b + c * c + d2 * d2 + e2 * e2;
}

void Hs079::gradient(ConstVectorRef x, VectorRef grad)
{
    const double b = x[0] - x[1];
    const double c = x[1] - x[2];
    const double d = x[2] - x[3];
    const double e = x[3] - x[4];
    const double d3 = 4.0 * d * d * d;  // ∂(x₂ − x₃)⁴/∂x₂
    const double e3 = 4.0 * e * e * e;  // ∂(x₃ − x₄)⁴/∂x₃
    grad << 2.0 * (x[0] - 1.0) + 2.0 * b,
            -2.0 * b + 2.0 * c,
            -2.0 * c + d3,
            -d3 + e3,
            -e3;
}

void Hs079::constraints(ConstVectorRef x, VectorRef c)
{
    c << x[0] + x[1] * x[1] + x[2] * x[2] * x[2] - 2.0 - 3.0 * kSqrt2,  // c₀ = x₀ + x₁² + x₂³ − 2 − 3√2
         x[1] - x[2] * x[2] + x[3] + 2.0 - 2.0 * kSqrt2,                // c₁ = x₁ − x₂² + x₃ + 2 − 2√2
         x[0] * x[4] - 2.0;                                            // c₂ = x₀x₄ − 2
}

void Hs079::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << 1.0, 2.0 * x[1], 3.0 * x[2] * x[2],  // ∇c₀ at columns 0, 1, 2
              1.0, -2.0 * x[2], 1.0,               // ∇c₁ at columns 1, 2, 3
              x[4], x[0];                          // ∇c₂ at columns 0, 4
}

void Hs079::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // Pattern order (0,0), (1,0), (1,1), (2,1), (2,2), (3,2), (3,3), (4,0), (4,3), (4,4).
    // With p = 12(x₂ − x₃)², q = 12(x₃ − x₄)²: ∇²f has diagonal (4, 4, 2 + p, p + q, q)
    // and off-diagonal (1,0) = (2,1) = −2, (3,2) = −p, (4,3) = −q.
    // ∇²c₀ = diag(0, 2, 6x₂, 0, 0), ∇²c₁ = −2 at (2,2), ∇²c₂ = 1 at (4,0).
    const double s = sigma;
    const double p = 12.0 * (x[2] - x[3]) * (x[2] - x[3]);
    const double q = 12.0 * (x[3] - x[4]) * (x[3] - x[4]);
    values << 4.0 * s,
              -2.0 * s,
              4.0 * s + 2.0 * lambda[0],
              -2.0 * s,
              (2.0 + p) * s + 6.0 * x[2] * lambda[0] - 2.0 * lambda[1],
              -p * s,
              (p + q) * s,
              lambda[2],
              -q * s,
              q * s;
}

} // namespace sinew
