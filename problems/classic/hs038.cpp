#include "sinew/problems/classic/hs038.hpp"

namespace sinew {

Hs038::Hs038()
{
    // Two Rosenbrock-like pairs (x₀, x₁) and (x₂, x₃), coupled only through
    // the 19.8(x₁ − 1)(x₃ − 1) term: (2,0), (2,1) and (3,0) are structurally zero.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 2);
    hessian_pattern_.add(3, 1);
    hessian_pattern_.add(3, 2);
    hessian_pattern_.add(3, 3);
}

void Hs038::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setConstant(-10.0);
    upper.setConstant(10.0);
}

Nlp::Vector Hs038::starting_point() const
{
    Vector x(4);
    x << -3.0, -1.0, -3.0, -1.0;
    return x;
}

double Hs038::objective(ConstVectorRef x)
{
    const double a = x[1] - x[0] * x[0];  // x₁ − x₀²
    const double b = x[3] - x[2] * x[2];  // x₃ − x₂²
    const double p = x[1] - 1.0;
    const double q = x[3] - 1.0;
    return 100.0 * a * a + (1.0 - x[0]) * (1.0 - x[0]) + 90.0 * b * b + (1.0 - x[2]) * (1.0 - x[2]) +
           10.1 * (p * p + q * q) + 19.8 * p * q;
}

void Hs038::gradient(ConstVectorRef x, VectorRef grad)
{
    const double a = x[1] - x[0] * x[0];
    const double b = x[3] - x[2] * x[2];
    const double p = x[1] - 1.0;
    const double q = x[3] - 1.0;
    grad << -400.0 * x[0] * a - 2.0 * (1.0 - x[0]),
            200.0 * a + 20.2 * p + 19.8 * q,
            -360.0 * x[2] * b - 2.0 * (1.0 - x[2]),
            180.0 * b + 20.2 * q + 19.8 * p;
}

void Hs038::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∇²f in pattern order (0,0), (1,0), (1,1), (2,2), (3,1), (3,2), (3,3).
    values << sigma * (1200.0 * x[0] * x[0] - 400.0 * x[1] + 2.0),
              sigma * (-400.0 * x[0]),
              sigma * 220.2,
              sigma * (1080.0 * x[2] * x[2] - 360.0 * x[3] + 2.0),
              sigma * 19.8,
              sigma * (-360.0 * x[2]),
              sigma * 200.2;
}

} // namespace sinew
