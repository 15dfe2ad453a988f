#include "sinew/problems/classic/hs078.hpp"

#include "sinew/problems/classic/hs078_family.hpp"

namespace sinew {

using namespace hs078_family;

Hs078::Hs078()
{
    add_jacobian_pattern(jacobian_pattern_);
    // ∇²f fills the strict lower triangle and ∇²c₀ = 2I the diagonal.
    add_hessian_pattern(hessian_pattern_);
}

void Hs078::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs078::starting_point() const
{
    Vector x(kVariables);
    x << -2.0, 1.5, 2.0, -1.0, -1.0;
    return x;
}

double Hs078::objective(ConstVectorRef x)
{
    return product_without(x, -1, -1);  // x₀x₁x₂x₃x₄
}

void Hs078::gradient(ConstVectorRef x, VectorRef grad)
{
    for (int i = 0; i < kVariables; ++i)
        grad[i] = product_without(x, i, -1);
}

void Hs078::constraints(ConstVectorRef x, VectorRef c) { hs078_family::constraints(x, c); }

void Hs078::jacobian_values(ConstVectorRef x, VectorRef values) { hs078_family::jacobian_values(x, values); }

void Hs078::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // σ ∂²f/∂xᵢ∂xⱼ = σ Π_{k≠i,j} xₖ off the diagonal, 0 on it; then Σ λᵢ∇²cᵢ.
    int k = 0;
    for (int row = 0; row < kVariables; ++row) {
        for (int col = 0; col < row; ++col)
            values[k++] = sigma * product_without(x, row, col);
        values[k++] = 0.0;
    }
    add_constraint_curvature(x, lambda, values);
}

} // namespace sinew
