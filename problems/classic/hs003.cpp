#include "sinew/problems/classic/hs003.hpp"

namespace sinew {
namespace {

constexpr double kWeight = 1e-5;  ///< the weight of (x₁ − x₀)²

} // namespace

Hs003::Hs003()
{
    // ∇²f is constant and dense: the whole lower triangle, row by row.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
}

void Hs003::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower << -kInfinity, 0.0;  // x₀ free, x₁ ≥ 0
    upper.setConstant(kInfinity);
}

Nlp::Vector Hs003::starting_point() const
{
    Vector x(2);
    x << 10.0, 1.0;
    return x;
}

double Hs003::objective(ConstVectorRef x)
{
    const double d = x[1] - x[0];
    return x[1] + kWeight * d * d;  // x₁ + 10⁻⁵ (x₁ − x₀)²
}

void Hs003::gradient(ConstVectorRef x, VectorRef grad)
{
    const double d = x[1] - x[0];
    grad << -2.0 * kWeight * d,      // ∂f/∂x₀ = −2·10⁻⁵ (x₁ − x₀)
            1.0 + 2.0 * kWeight * d;  // ∂f/∂x₁ = 1 + 2·10⁻⁵ (x₁ − x₀)
}

void Hs003::hessian_values(ConstVectorRef, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∇²f = 2·10⁻⁵ σ [1 −1; −1 1], in pattern order (0,0), (1,0), (1,1).
    const double w = 2.0 * kWeight * sigma;
    values << w, -w, w;
}

} // namespace sinew
