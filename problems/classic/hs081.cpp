#include "sinew/problems/classic/hs081.hpp"

#include <cmath>

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

/// q = x₀³ + x₁³ + 1, which is c₂ and the inner term of f's second part.
double cubic_sum(Nlp::ConstVectorRef x)
{
    return x[0] * x[0] * x[0] + x[1] * x[1] * x[1] + 1.0;
}

/// Position of (row, col), row >= col, in the row-by-row lower triangle.
constexpr int lower_triangle_index(int row, int col) { return row * (row + 1) / 2 + col; }

} // namespace

Hs081::Hs081()
{
    // c₀ = Σ xᵢ² − 10 touches every variable; c₁ and c₂ four or two of them.
    for (int col = 0; col < kN; ++col)
        jacobian_pattern_.add(0, col);
    for (int col = 1; col < kN; ++col)
        jacobian_pattern_.add(1, col);
    jacobian_pattern_.add(2, 0);
    jacobian_pattern_.add(2, 1);
    // ∇² exp(p) = exp(p) (∇p ∇pᵀ + ∇²p) is dense: the whole lower triangle,
    // row by row.
    for (int row = 0; row < kN; ++row)
        for (int col = 0; col <= row; ++col)
            hessian_pattern_.add(row, col);
}

void Hs081::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower << -2.3, -2.3, -3.2, -3.2, -3.2;
    upper << 2.3, 2.3, 3.2, 3.2, 3.2;
}

void Hs081::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs081::starting_point() const
{
    Vector x(kN);
    x << -2.0, 2.0, 2.0, -1.0, -1.0;
    return x;
}

double Hs081::objective(ConstVectorRef x)
{
    const double q = cubic_sum(x);
    return std::exp(product_without(x, -1, -1)) - 0.5 * q * q;  // exp(x₀x₁x₂x₃x₄) − ½ (x₀³ + x₁³ + 1)²
}

void Hs081::gradient(ConstVectorRef x, VectorRef grad)
{
    // ∂f/∂xᵢ = exp(p) Π_{k≠i} xₖ, minus 3q x₀² and 3q x₁² for i = 0, 1.
    const double e = std::exp(product_without(x, -1, -1));
    const double q = cubic_sum(x);
    for (int i = 0; i < kN; ++i)
        grad[i] = e * product_without(x, i, -1);
    grad[0] -= 3.0 * q * x[0] * x[0];
    grad[1] -= 3.0 * q * x[1] * x[1];
}

void Hs081::constraints(ConstVectorRef x, VectorRef c)
{
    c << x.squaredNorm() - 10.0,           // c₀ = Σ xᵢ² − 10
         x[1] * x[2] - 5.0 * x[3] * x[4],  // c₁ = x₁x₂ − 5x₃x₄
         cubic_sum(x);                     // c₂ = x₀³ + x₁³ + 1
}

void Hs081::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << 2.0 * x[0], 2.0 * x[1], 2.0 * x[2], 2.0 * x[3], 2.0 * x[4],  // ∇c₀ = 2x
              x[2], x[1], -5.0 * x[4], -5.0 * x[3],                        // ∇c₁ at columns 1…4
              3.0 * x[0] * x[0], 3.0 * x[1] * x[1];                        // ∇c₂ at columns 0, 1
}

void Hs081::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // exp(p) part: σ e (∂ᵢp ∂ⱼp + ∂ᵢⱼp) with ∂ᵢp = Π_{k≠i} xₖ, ∂ᵢⱼp = Π_{k≠i,j} xₖ
    // off the diagonal and 0 on it. −½q² part: −σ (9x₀⁴ + 6q x₀) at (0,0),
    // −9σ x₀²x₁² at (1,0), −σ (9x₁⁴ + 6q x₁) at (1,1). Constraints: λ₀ 2I;
    // λ₁ at (2,1) and −5λ₁ at (4,3); λ₂ 6x₀ at (0,0) and 6x₁ at (1,1).
    // Row-by-row order.
    const double e = std::exp(product_without(x, -1, -1));
    const double q = cubic_sum(x);
    int k = 0;
    for (int row = 0; row < kN; ++row) {
        const double dp_row = product_without(x, row, -1);
        for (int col = 0; col < row; ++col)
            values[k++] = sigma * e * (dp_row * product_without(x, col, -1) + product_without(x, row, col));
        values[k++] = sigma * e * dp_row * dp_row + 2.0 * lambda[0];
    }
    const double x0_squared = x[0] * x[0];
    const double x1_squared = x[1] * x[1];
    values[lower_triangle_index(0, 0)] +=
        -sigma * (9.0 * x0_squared * x0_squared + 6.0 * q * x[0]) + 6.0 * x[0] * lambda[2];
    values[lower_triangle_index(1, 0)] += -sigma * 9.0 * x0_squared * x1_squared;
    values[lower_triangle_index(1, 1)] +=
        -sigma * (9.0 * x1_squared * x1_squared + 6.0 * q * x[1]) + 6.0 * x[1] * lambda[2];
    values[lower_triangle_index(2, 1)] += lambda[1];
    values[lower_triangle_index(4, 3)] += -5.0 * lambda[1];
}

} // namespace sinew
