#include "sinew/problems/classic/hs056.hpp"

#include <cmath>

namespace sinew {

Hs056::Hs056()
{
    // cᵢ = xᵢ − 4.2 sin²x₃₊ᵢ for i < 3; c₃ links x₀, x₁, x₂ and x₆.
    for (int i = 0; i < 3; ++i) {
        jacobian_pattern_.add(i, i);
        jacobian_pattern_.add(i, i + 3);
    }
    for (int col : {0, 1, 2, 6})
        jacobian_pattern_.add(3, col);
    // ∇²f couples x₀, x₁, x₂ off the diagonal; each constraint adds one
    // diagonal entry for its angle x₃…x₆.
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(2, 0);
    hessian_pattern_.add(2, 1);
    for (int i = 3; i < 7; ++i)
        hessian_pattern_.add(i, i);
}

void Hs056::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs056::starting_point() const
{
    const double a = std::asin(std::sqrt(1.0 / 4.2));
    const double b = std::asin(std::sqrt(5.0 / 7.2));
    Vector x(7);
    x << 1.0, 1.0, 1.0, a, a, a, b;
    return x;
}

double Hs056::objective(ConstVectorRef x)
{
    return -x[0] * x[1] * x[2];
}

void Hs056::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << -x[1] * x[2], -x[0] * x[2], -x[0] * x[1], 0.0, 0.0, 0.0, 0.0;
}

void Hs056::constraints(ConstVectorRef x, VectorRef c)
{
    const auto sin_squared = [](double t) { return std::sin(t) * std::sin(t); };
    c << x[0] - 4.2 * sin_squared(x[3]),
         x[1] - 4.2 * sin_squared(x[4]),
         x[2] - 4.2 * sin_squared(x[5]),
         x[0] + 2.0 * x[1] + 2.0 * x[2] - 7.2 * sin_squared(x[6]);
}

void Hs056::jacobian_values(ConstVectorRef x, VectorRef values)
{
    // d(sin²t)/dt = sin 2t; pattern order (0,0), (0,3), (1,1), (1,4), (2,2), (2,5), (3,0), (3,1), (3,2), (3,6).
    values << 1.0, -4.2 * std::sin(2.0 * x[3]),
              1.0, -4.2 * std::sin(2.0 * x[4]),
              1.0, -4.2 * std::sin(2.0 * x[5]),
              1.0, 2.0, 2.0, -7.2 * std::sin(2.0 * x[6]);
}

void Hs056::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // d²(sin²t)/dt² = 2 cos 2t; pattern order (1,0), (2,0), (2,1), (3,3), (4,4), (5,5), (6,6).
    values << -sigma * x[2],
              -sigma * x[1],
              -sigma * x[0],
              -8.4 * std::cos(2.0 * x[3]) * lambda[0],
              -8.4 * std::cos(2.0 * x[4]) * lambda[1],
              -8.4 * std::cos(2.0 * x[5]) * lambda[2],
              -14.4 * std::cos(2.0 * x[6]) * lambda[3];
}

} // namespace sinew
