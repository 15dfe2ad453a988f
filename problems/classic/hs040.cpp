#include "sinew/problems/classic/hs040.hpp"

namespace sinew {

Hs040::Hs040()
{
    jacobian_pattern_.add(0, 0);
    jacobian_pattern_.add(0, 1);
    jacobian_pattern_.add(1, 0);
    jacobian_pattern_.add(1, 2);
    jacobian_pattern_.add(1, 3);
    jacobian_pattern_.add(2, 1);
    jacobian_pattern_.add(2, 3);
    // ∇²f fills the strict lower triangle; the constraints add (0,0), (1,1),
    // (3,0) and (3,3). Only (2,2) is structurally zero.
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
    hessian_pattern_.add(2, 0);
    hessian_pattern_.add(2, 1);
    hessian_pattern_.add(3, 0);
    hessian_pattern_.add(3, 1);
    hessian_pattern_.add(3, 2);
    hessian_pattern_.add(3, 3);
}

void Hs040::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

Nlp::Vector Hs040::starting_point() const
{
    return Vector::Constant(4, 0.8);
}

double Hs040::objective(ConstVectorRef x)
{
    return -x[0] * x[1] * x[2] * x[3];
}

void Hs040::gradient(ConstVectorRef x, VectorRef grad)
{
    grad << -x[1] * x[2] * x[3], -x[0] * x[2] * x[3], -x[0] * x[1] * x[3], -x[0] * x[1] * x[2];
}

void Hs040::constraints(ConstVectorRef x, VectorRef c)
{
    c << x[0] * x[0] * x[0] + x[1] * x[1] - 1.0,  // c₀ = x₀³ + x₁² − 1
         x[0] * x[0] * x[3] - x[2],               // c₁ = x₀²x₃ − x₂
         x[3] * x[3] - x[1];                      // c₂ = x₃² − x₁
}

void Hs040::jacobian_values(ConstVectorRef x, VectorRef values)
{
    values << 3.0 * x[0] * x[0], 2.0 * x[1],         // ∇c₀ at columns 0, 1
              2.0 * x[0] * x[3], -1.0, x[0] * x[0],  // ∇c₁ at columns 0, 2, 3
              -1.0, 2.0 * x[3];                      // ∇c₂ at columns 1, 3
}

void Hs040::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    // σ ∇²f + λ₀ diag(6x₀, 2, 0, 0) + λ₁ ∇²(x₀²x₃) + λ₂ 2e₃e₃ᵀ, in pattern order
    // (0,0), (1,0), (1,1), (2,0), (2,1), (3,0), (3,1), (3,2), (3,3).
    const double s = sigma;
    values << 6.0 * x[0] * lambda[0] + 2.0 * x[3] * lambda[1],
              -s * x[2] * x[3],
              2.0 * lambda[0],
              -s * x[1] * x[3],
              -s * x[0] * x[3],
              -s * x[1] * x[2] + 2.0 * x[0] * lambda[1],
              -s * x[0] * x[2],
              -s * x[0] * x[1],
              2.0 * lambda[2];
}

} // namespace sinew
