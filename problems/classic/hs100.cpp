#include "sinew/problems/classic/hs100.hpp"

#include <initializer_list>

namespace sinew {

Hs100::Hs100()
{
    // Row by row; jacobian_values follows this order.
    for (int col : {0, 1, 2, 3, 4})
        jacobian_pattern_.add(0, col);
    for (int col : {0, 1, 2, 3, 4})
        jacobian_pattern_.add(1, col);
    for (int col : {0, 1, 5, 6})
        jacobian_pattern_.add(2, col);
    for (int col : {0, 1, 2, 5, 6})
        jacobian_pattern_.add(3, col);
    // ∇²L: the diagonal, (1,0) from the x₀x₁ term of c₃ and (6,5) from the x₅x₆ term of f.
    // Row by row, in the order hessian_values writes them.
    const int entries[9][2] = {{0, 0}, {1, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}, {5, 5}, {6, 5}, {6, 6}};
    for (const auto& entry : entries)
        hessian_pattern_.add(entry[0], entry[1]);
}

void Hs100::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setConstant(kInfinity);
}

Nlp::Vector Hs100::starting_point() const
{
    Vector x(7);
    x << 1.0, 2.0, 0.0, 4.0, 0.0, 1.0, 1.0;
    return x;
}

double Hs100::objective(ConstVectorRef x)
{
    const double a = x[0] - 10.0;
    const double b = x[1] - 12.0;
    const double d = x[3] - 11.0;
    const double x2s = x[2] * x[2];
    const double x4s = x[4] * x[4];
    const double x6s = x[6] * x[6];
    return a * a + 5.0 * b * b + x2s * x2s + 3.0 * d * d + 10.0 * x4s * x4s * x4s + 7.0 * x[5] * x[5] + x6s * x6s -
           4.0 * x[5] * x[6] - 10.0 * x[5] - 8.0 * x[6];
}

void Hs100::gradient(ConstVectorRef x, VectorRef grad)
{
    const double x4s = x[4] * x[4];
    grad << 2.0 * (x[0] - 10.0),
            10.0 * (x[1] - 12.0),
            4.0 * x[2] * x[2] * x[2],
            6.0 * (x[3] - 11.0),
            60.0 * x4s * x4s * x[4],
            14.0 * x[5] - 4.0 * x[6] - 10.0,
            4.0 * x[6] * x[6] * x[6] - 4.0 * x[5] - 8.0;
}

void Hs100::constraints(ConstVectorRef x, VectorRef c)
{
    const double x1s = x[1] * x[1];
    c << 127.0 - 2.0 * x[0] * x[0] - 3.0 * x1s * x1s - x[2] - 4.0 * x[3] * x[3] - 5.0 * x[4],
         282.0 - 7.0 * x[0] - 3.0 * x[1] - 10.0 * x[2] * x[2] - x[3] + x[4],
         196.0 - 23.0 * x[0] - x1s - 6.0 * x[5] * x[5] + 8.0 * x[6],
         -4.0 * x[0] * x[0] - x1s + 3.0 * x[0] * x[1] - 2.0 * x[2] * x[2] - 5.0 * x[5] + 11.0 * x[6];
}

void Hs100::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << -4.0 * x[0], -12.0 * x[1] * x[1] * x[1], -1.0, -8.0 * x[3], -5.0,    // ∇c₀, cols 0–4
              -7.0, -3.0, -20.0 * x[2], -1.0, 1.0,                                 // ∇c₁, cols 0–4
              -23.0, -2.0 * x[1], -12.0 * x[5], 8.0,                               // ∇c₂, cols 0, 1, 5, 6
              -8.0 * x[0] + 3.0 * x[1], -2.0 * x[1] + 3.0 * x[0], -4.0 * x[2], -5.0, 11.0;  // ∇c₃, cols 0, 1, 2, 5, 6
}

void Hs100::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // σ ∇²f + Σ λᵢ ∇²cᵢ in pattern order (0,0), (1,0), (1,1), (2,2), (3,3), (4,4), (5,5), (6,5), (6,6).
    const double l0 = lambda[0];
    const double l1 = lambda[1];
    const double l2 = lambda[2];
    const double l3 = lambda[3];
    const double x4s = x[4] * x[4];
    values << sigma * 2.0 - 4.0 * l0 - 8.0 * l3,
              3.0 * l3,
              sigma * 10.0 - 36.0 * l0 * x[1] * x[1] - 2.0 * l2 - 2.0 * l3,
              sigma * 12.0 * x[2] * x[2] - 20.0 * l1 - 4.0 * l3,
              sigma * 6.0 - 8.0 * l0,
              sigma * 300.0 * x4s * x4s,
              sigma * 14.0 - 12.0 * l2,
              sigma * -4.0,
              sigma * 12.0 * x[6] * x[6];
}

} // namespace sinew
