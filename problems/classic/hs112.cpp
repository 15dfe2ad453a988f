#include "sinew/problems/classic/hs112.hpp"

#include <cmath>

namespace sinew {
namespace {

constexpr int kN = 10;

/// The free-energy constants aⱼ (the book's cⱼ).
constexpr double kA[kN] = {-6.089, -17.164, -34.054, -5.914, -24.721, -14.986, -24.100, -10.708, -26.662, -22.179};

} // namespace

Hs112::Hs112()
{
    // Three linear rows, in row order and by column within a row.
    for (const int col : {0, 1, 2, 5, 9})
        jacobian_pattern_.add(0, col);
    for (const int col : {3, 4, 5, 6})
        jacobian_pattern_.add(1, col);
    for (const int col : {2, 6, 7, 8, 9})
        jacobian_pattern_.add(2, col);
    // ∇²f = diag(1/xⱼ) − (1/S) 11ᵀ is dense: the whole lower triangle, row by row.
    for (int row = 0; row < kN; ++row)
        for (int col = 0; col <= row; ++col)
            hessian_pattern_.add(row, col);
}

void Hs112::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setConstant(1e-6);
    upper.setConstant(kInfinity);
}

void Hs112::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs112::starting_point() const
{
    return Vector::Constant(kN, 0.1);
}

double Hs112::objective(ConstVectorRef x)
{
    for (int j = 0; j < kN; ++j)
        if (!(x[j] > 0.0))
            return kInfinity;  // ln(xⱼ / S) undefined
    const double s = x.sum();
    double f = 0.0;
    for (int j = 0; j < kN; ++j)
        f += x[j] * (kA[j] + std::log(x[j] / s));  // xⱼ (aⱼ + ln(xⱼ / S))
    return f;
}

void Hs112::gradient(ConstVectorRef x, VectorRef grad)
{
    // ∂f/∂xⱼ = aⱼ + ln(xⱼ/S) + 1 − Σₖ xₖ/S = aⱼ + ln(xⱼ/S).
    const double s = x.sum();
    for (int j = 0; j < kN; ++j)
        grad[j] = kA[j] + std::log(x[j] / s);
}

void Hs112::constraints(ConstVectorRef x, VectorRef c)
{
    c << x[0] + 2.0 * x[1] + 2.0 * x[2] + x[5] + x[9] - 2.0,  // c₀ = x₀ + 2x₁ + 2x₂ + x₅ + x₉ − 2
         x[3] + 2.0 * x[4] + x[5] + x[6] - 1.0,               // c₁ = x₃ + 2x₄ + x₅ + x₆ − 1
         x[2] + x[6] + x[7] + 2.0 * x[8] + x[9] - 1.0;        // c₂ = x₂ + x₆ + x₇ + 2x₈ + x₉ − 1
}

void Hs112::jacobian_values(ConstVectorRef, VectorRef values)
{
    values << 1.0, 2.0, 2.0, 1.0, 1.0,  // ∇c₀ at columns 0, 1, 2, 5, 9
              1.0, 2.0, 1.0, 1.0,       // ∇c₁ at columns 3, 4, 5, 6
              1.0, 1.0, 1.0, 2.0, 1.0;  // ∇c₂ at columns 2, 6, 7, 8, 9
}

void Hs112::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∂²f/∂xⱼ∂xₖ = σ (δⱼₖ/xⱼ − 1/S); the constraints are linear. Row-by-row
    // lower-triangle order.
    const double off_diagonal = -sigma / x.sum();
    int k = 0;
    for (int row = 0; row < kN; ++row) {
        for (int col = 0; col < row; ++col)
            values[k++] = off_diagonal;
        values[k++] = sigma / x[row] + off_diagonal;
    }
}

} // namespace sinew
