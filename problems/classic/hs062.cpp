#include "sinew/problems/classic/hs062.hpp"

#include <cmath>

namespace sinew {
namespace {

/// f = Σₜ wₜ ln(aₜ·x + bₜ): each of the three logarithms of a ratio is the
/// difference of two logarithms of affine functions.
struct LogTerm {
    double weight;
    double a[3];
    double b;
};

constexpr double kScale = -32.174;
constexpr LogTerm kTerms[6] = {
    {kScale * 255.0, {1.0, 1.0, 1.0}, 0.03},     // ln(x₀ + x₁ + x₂ + 0.03)
    {-kScale * 255.0, {0.09, 1.0, 1.0}, 0.03},   // − ln(0.09x₀ + x₁ + x₂ + 0.03)
    {kScale * 280.0, {0.0, 1.0, 1.0}, 0.03},     // ln(x₁ + x₂ + 0.03)
    {-kScale * 280.0, {0.0, 0.07, 1.0}, 0.03},   // − ln(0.07x₁ + x₂ + 0.03)
    {kScale * 290.0, {0.0, 0.0, 1.0}, 0.03},     // ln(x₂ + 0.03)
    {-kScale * 290.0, {0.0, 0.0, 0.13}, 0.03},   // − ln(0.13x₂ + 0.03)
};

double argument(const LogTerm& t, Nlp::ConstVectorRef x)
{
    return t.a[0] * x[0] + t.a[1] * x[1] + t.a[2] * x[2] + t.b;
}

} // namespace

Hs062::Hs062()
{
    for (int col = 0; col < 3; ++col)
        jacobian_pattern_.add(0, col);
    // ∇²f is dense; c₀ is linear.
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col <= row; ++col)
            hessian_pattern_.add(row, col);
}

void Hs062::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setOnes();
}

void Hs062::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs062::starting_point() const
{
    Vector x(3);
    x << 0.7, 0.2, 0.1;
    return x;
}

double Hs062::objective(ConstVectorRef x)
{
    double f = 0.0;
    for (const LogTerm& t : kTerms) {
        const double u = argument(t, x);
        if (!(u > 0.0))
            return kInfinity;  // the logarithm is undefined
        f += t.weight * std::log(u);
    }
    return f;
}

void Hs062::gradient(ConstVectorRef x, VectorRef grad)
{
    // ∇ w ln(a·x + b) = w a / (a·x + b)
    grad.setZero();
    for (const LogTerm& t : kTerms) {
        const double g = t.weight / argument(t, x);
        for (int i = 0; i < 3; ++i)
            grad[i] += g * t.a[i];
    }
}

void Hs062::constraints(ConstVectorRef x, VectorRef c)
{
    c[0] = x[0] + x[1] + x[2] - 1.0;
}

void Hs062::jacobian_values(ConstVectorRef, VectorRef values)
{
    values << 1.0, 1.0, 1.0;
}

void Hs062::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∇²f only: ∇² w ln(a·x + b) = −w a aᵀ / (a·x + b)², row-by-row lower triangle.
    values.setZero();
    for (const LogTerm& t : kTerms) {
        const double u = argument(t, x);
        const double h = -sigma * t.weight / (u * u);
        int k = 0;
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col <= row; ++col)
                values[k++] += h * t.a[row] * t.a[col];
    }
}

} // namespace sinew
