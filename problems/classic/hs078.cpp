#include "sinew/problems/classic/hs078.hpp"

namespace sinew {
namespace {

constexpr int kN = 5;

/// Product of the xₖ with k ∉ {skip_a, skip_b} (no division, so zeros are fine).
double product_without(Nlp::ConstVectorRef x, int skip_a, int skip_b)
{
    double p = 1.0;
    for (int k = 0; k < kN; ++k)
        if (k != skip_a && k != skip_b)
            p *= x[k];
    return p;
}

/// Position of (row, col), row >= col, in the row-by-row lower triangle.
constexpr int lower_triangle_index(int row, int col) { return row * (row + 1) / 2 + col; }

} // namespace

Hs078::Hs078()
{
    // c₀ = Σ xᵢ² − 10 touches every variable; c₁ and c₂ two or four of them.
    for (int col = 0; col < kN; ++col)
        jacobian_pattern_.add(0, col);
    for (int col = 1; col < kN; ++col)
        jacobian_pattern_.add(1, col);
    jacobian_pattern_.add(2, 0);
    jacobian_pattern_.add(2, 1);
    // ∇²f fills the strict lower triangle and ∇²c₀ = 2I the diagonal: the
    // whole lower triangle, row by row.
    for (int row = 0; row < kN; ++row)
        for (int col = 0; col <= row; ++col)
            hessian_pattern_.add(row, col);
}

void Hs078::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs078::starting_point() const
{
    Vector x(kN);
    x << -2.0, 1.5, 2.0, -1.0, -1.0;
    return x;
}

double Hs078::objective(ConstVectorRef x)
{
    return product_without(x, -1, -1);  // x₀x₁x₂x₃x₄
}

void Hs078::gradient(ConstVectorRef x, VectorRef grad)
{
    for (int i = 0; i < kN; ++i)
        grad[i] = product_without(x, i, -1);
}

void Hs078::constraints(ConstVectorRef x, VectorRef c)
{
    c << x.squaredNorm() - 10.0,                          // c₀ = Σ xᵢ² − 10
         x[1] * x[2] - 5.0 * x[3] * x[4],                 // c₁ = x₁x₂ − 5x₃x₄
         x[0] * x[0] * x[0] + x[1] * x[1] * x[1] + 1.0;  // c₂ = x₀³ + x₁³ + 1
}

void Hs078::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << 2.0 * x[0], 2.0 * x[1], 2.0 * x[2], 2.0 * x[3], 2.0 * x[4],  // ∇c₀ = 2x
              x[2], x[1], -5.0 * x[4], -5.0 * x[3],                        // ∇c₁ at columns 1…4
              3.0 * x[0] * x[0], 3.0 * x[1] * x[1];                        // ∇c₂ at columns 0, 1
}

void Hs078::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // σ ∂²f/∂xᵢ∂xⱼ = σ Π_{k≠i,j} xₖ off the diagonal; λ₀ 2I; λ₁ at (2,1) and
    // −5λ₁ at (4,3); λ₂ 6x₀ at (0,0) and 6x₁ at (1,1). Row-by-row order.
    int k = 0;
    for (int row = 0; row < kN; ++row) {
        for (int col = 0; col < row; ++col)
            values[k++] = sigma * product_without(x, row, col);
        values[k++] = 2.0 * lambda[0];
    }
    values[lower_triangle_index(0, 0)] += 6.0 * x[0] * lambda[2];
    values[lower_triangle_index(1, 1)] += 6.0 * x[1] * lambda[2];
    values[lower_triangle_index(2, 1)] += lambda[1];
    values[lower_triangle_index(4, 3)] += -5.0 * lambda[1];
}

} // namespace sinew
