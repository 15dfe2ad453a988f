#include "sinew/problems/classic/hs009.hpp"

#include <cmath>

namespace sinew {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kA = kPi / 12.0;
constexpr double kB = kPi / 16.0;

} // namespace

Hs009::Hs009()
{
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(0, 1);
    // c₀ is linear; ∇²f is dense.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
}

void Hs009::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs009::starting_point() const
{
    return Vector::Zero(2);
}

double Hs009::objective(ConstVectorRef x)
{
    return std::sin(kA * x[0]) * std::cos(kB * x[1]);  // sin(πx₀/12) cos(πx₁/16)
}

void Hs009::gradient(ConstVectorRef x, VectorRef grad)
{
    const double s0 = std::sin(kA * x[0]), c0 = std::cos(kA * x[0]);
    const double s1 = std::sin(kB * x[1]), c1 = std::cos(kB * x[1]);
    grad << kA * c0 * c1, -kB * s0 * s1;
}

void Hs009::constraints(ConstVectorRef x, VectorRef c)
{
    c[0] = 4.0 * x[0] - 3.0 * x[1];
}

void Hs009::jacobian_values(ConstVectorRef, VectorRef values)
{
    values << 4.0, -3.0;
}

void Hs009::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    // σ ∇²f only, in pattern order (0,0), (1,0), (1,1).
    const double s0 = std::sin(kA * x[0]), c0 = std::cos(kA * x[0]);
    const double s1 = std::sin(kB * x[1]), c1 = std::cos(kB * x[1]);
    values << -sigma * kA * kA * s0 * c1,
              -sigma * kA * kB * c0 * s1,
              -sigma * kB * kB * s0 * c1;
}

} // namespace sinew
