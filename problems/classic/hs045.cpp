#include "sinew/problems/classic/hs045.hpp"

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

} // namespace

Hs045::Hs045()
{
    // f is multilinear: ∇²f has a zero diagonal and a dense strict lower triangle, row by row.
    for (int row = 1; row < kN; ++row)
        for (int col = 0; col < row; ++col)
            hessian_pattern_.add(row, col);
}

void Hs045::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper << 1.0, 2.0, 3.0, 4.0, 5.0;
}

Nlp::Vector Hs045::starting_point() const
{
    return Vector::Constant(kN, 2.0);
}

double Hs045::objective(ConstVectorRef x)
{
    return 2.0 - product_without(x, -1, -1) / 120.0;  // 2 − Π xᵢ / 120
}

void Hs045::gradient(ConstVectorRef x, VectorRef grad)
{
    // ∂f/∂xᵢ = −Π_{k≠i} xₖ / 120
    for (int i = 0; i < kN; ++i)
        grad[i] = -product_without(x, i, -1) / 120.0;
}

void Hs045::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    // ∂²f/∂xᵢ∂xⱼ = −Π_{k≠i,j} xₖ / 120 for i ≠ j, in the pattern's row-by-row order.
    int k = 0;
    for (int row = 1; row < kN; ++row)
        for (int col = 0; col < row; ++col)
            values[k++] = -sigma * product_without(x, row, col) / 120.0;
}

} // namespace sinew
