#include "sinew/problems/classic/hs081.hpp"

#include "sinew/problems/classic/hs078_family.hpp"

#include <cmath>

namespace sinew {
namespace {

/// q = x₀³ + x₁³ + 1, which is c₂ and the inner term of f's second part.
double cubic_sum(Nlp::ConstVectorRef x)
{
    return x[0] * x[0] * x[0] + x[1] * x[1] * x[1] + 1.0;
}

} // namespace

using namespace hs078_family;

Hs081::Hs081()
{
    add_jacobian_pattern(jacobian_pattern_);
    // ∇² exp(p) = exp(p) (∇p ∇pᵀ + ∇²p) is dense.
    add_hessian_pattern(hessian_pattern_);
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
    Vector x(kVariables);
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
    for (int i = 0; i < kVariables; ++i)
        grad[i] = e * product_without(x, i, -1);
    grad[0] -= 3.0 * q * x[0] * x[0];
    grad[1] -= 3.0 * q * x[1] * x[1];
}

void Hs081::constraints(ConstVectorRef x, VectorRef c) { hs078_family::constraints(x, c); }

void Hs081::jacobian_values(ConstVectorRef x, VectorRef values) { hs078_family::jacobian_values(x, values); }

void Hs081::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // exp(p) part: σ e (∂ᵢp ∂ⱼp + ∂ᵢⱼp) with ∂ᵢp = Π_{k≠i} xₖ, ∂ᵢⱼp = Π_{k≠i,j} xₖ
    // off the diagonal and 0 on it. −½q² part: −σ (9x₀⁴ + 6q x₀) at (0,0),
    // −9σ x₀²x₁² at (1,0), −σ (9x₁⁴ + 6q x₁) at (1,1); then Σ λᵢ∇²cᵢ.
    // Row-by-row order.
    const double e = std::exp(product_without(x, -1, -1));
    const double q = cubic_sum(x);
    int k = 0;
    for (int row = 0; row < kVariables; ++row) {
        const double dp_row = product_without(x, row, -1);
        for (int col = 0; col < row; ++col)
            values[k++] = sigma * e * (dp_row * product_without(x, col, -1) + product_without(x, row, col));
        values[k++] = sigma * e * dp_row * dp_row;
    }
    const double x0_squared = x[0] * x[0];
    const double x1_squared = x[1] * x[1];
    values[lower_triangle_index(0, 0)] += -sigma * (9.0 * x0_squared * x0_squared + 6.0 * q * x[0]);
    values[lower_triangle_index(1, 0)] += -sigma * 9.0 * x0_squared * x1_squared;
    values[lower_triangle_index(1, 1)] += -sigma * (9.0 * x1_squared * x1_squared + 6.0 * q * x[1]);
    add_constraint_curvature(x, lambda, values);
}

} // namespace sinew
