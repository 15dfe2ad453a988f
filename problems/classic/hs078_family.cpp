#include "sinew/problems/classic/hs078_family.hpp"

namespace sinew::hs078_family {

double product_without(Nlp::ConstVectorRef x, int skip_a, int skip_b)
{
    double p = 1.0;
    for (int k = 0; k < kVariables; ++k)
        if (k != skip_a && k != skip_b)
            p *= x[k];
    return p;
}

void add_jacobian_pattern(SparsityPattern& pattern)
{
    // c₀ = Σ xᵢ² − 10 touches every variable; c₁ and c₂ four or two of them.
    for (int col = 0; col < kVariables; ++col)
        pattern.add(0, col);
    for (int col = 1; col < kVariables; ++col)
        pattern.add(1, col);
    pattern.add(2, 0);
    pattern.add(2, 1);
}

void add_hessian_pattern(SparsityPattern& pattern)
{
    for (int row = 0; row < kVariables; ++row)
        for (int col = 0; col <= row; ++col)
            pattern.add(row, col);
}

void constraints(Nlp::ConstVectorRef x, Nlp::VectorRef c)
{
    c << x.squaredNorm() - 10.0,                          // c₀ = Σ xᵢ² − 10
         x[1] * x[2] - 5.0 * x[3] * x[4],                 // c₁ = x₁x₂ − 5x₃x₄
         x[0] * x[0] * x[0] + x[1] * x[1] * x[1] + 1.0;  // c₂ = x₀³ + x₁³ + 1
}

void jacobian_values(Nlp::ConstVectorRef x, Nlp::VectorRef values)
{
    values << 2.0 * x[0], 2.0 * x[1], 2.0 * x[2], 2.0 * x[3], 2.0 * x[4],  // ∇c₀ = 2x
              x[2], x[1], -5.0 * x[4], -5.0 * x[3],                        // ∇c₁ at columns 1…4
              3.0 * x[0] * x[0], 3.0 * x[1] * x[1];                        // ∇c₂ at columns 0, 1
}

void add_constraint_curvature(Nlp::ConstVectorRef x, Nlp::ConstVectorRef lambda, Nlp::VectorRef values)
{
    for (int i = 0; i < kVariables; ++i)
        values[lower_triangle_index(i, i)] += 2.0 * lambda[0];  // λ₀ ∇²c₀ = 2λ₀ I
    values[lower_triangle_index(2, 1)] += lambda[1];             // λ₁ ∇²c₁
    values[lower_triangle_index(4, 3)] += -5.0 * lambda[1];
    values[lower_triangle_index(0, 0)] += 6.0 * x[0] * lambda[2];  // λ₂ ∇²c₂
    values[lower_triangle_index(1, 1)] += 6.0 * x[1] * lambda[2];
}

} // namespace sinew::hs078_family
