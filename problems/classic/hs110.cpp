#include "sinew/problems/classic/hs110.hpp"

#include <cmath>

namespace sinew {
namespace {

constexpr int kN = 10;

/// q = (Πᵢ xᵢ)^0.2, as exp(0.2 Σ ln xᵢ) to stay clear of overflow.
double fifth_root_of_product(Nlp::ConstVectorRef x)
{
    double log_sum = 0.0;
    for (int i = 0; i < kN; ++i)
        log_sum += std::log(x[i]);
    return std::exp(0.2 * log_sum);
}

} // namespace

Hs110::Hs110()
{
    // The product term couples every pair: the whole lower triangle, row by row.
    for (int row = 0; row < kN; ++row)
        for (int col = 0; col <= row; ++col)
            hessian_pattern_.add(row, col);
}

void Hs110::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setConstant(2.001);
    upper.setConstant(9.999);
}

Nlp::Vector Hs110::starting_point() const
{
    return Vector::Constant(kN, 9.0);
}

double Hs110::objective(ConstVectorRef x)
{
    double sum = 0.0;
    for (int i = 0; i < kN; ++i) {
        if (!(x[i] > 2.0 && x[i] < 10.0))
            return kInfinity;  // ln(xᵢ − 2) or ln(10 − xᵢ) undefined
        const double a = std::log(x[i] - 2.0);
        const double b = std::log(10.0 - x[i]);
        sum += a * a + b * b;
    }
    return sum - fifth_root_of_product(x);
}

void Hs110::gradient(ConstVectorRef x, VectorRef grad)
{
    // ∂f/∂xᵢ = 2 ln(xᵢ − 2)/(xᵢ − 2) − 2 ln(10 − xᵢ)/(10 − xᵢ) − 0.2 q / xᵢ
    const double q = fifth_root_of_product(x);
    for (int i = 0; i < kN; ++i) {
        const double u = x[i] - 2.0;
        const double v = 10.0 - x[i];
        grad[i] = 2.0 * std::log(u) / u - 2.0 * std::log(v) / v - 0.2 * q / x[i];
    }
}

void Hs110::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    // The separable terms give the diagonal 2(1 − ln u)/u² + 2(1 − ln v)/v²
    // (u = xᵢ − 2, v = 10 − xᵢ); −q gives 0.16 q/xᵢ² on the diagonal and
    // −0.04 q/(xᵢxⱼ) off it. Row-by-row lower-triangle order.
    const double q = fifth_root_of_product(x);
    int k = 0;
    for (int row = 0; row < kN; ++row) {
        for (int col = 0; col < row; ++col)
            values[k++] = -sigma * 0.04 * q / (x[row] * x[col]);
        const double u = x[row] - 2.0;
        const double v = 10.0 - x[row];
        const double separable = 2.0 * (1.0 - std::log(u)) / (u * u) + 2.0 * (1.0 - std::log(v)) / (v * v);
        values[k++] = sigma * (separable + 0.16 * q / (x[row] * x[row]));
    }
}

} // namespace sinew
