#pragma once
#include "sinew/problems/nlp.hpp"

namespace sinew {

/// What HS 78 and HS 81 share (Hock & Schittkowski 1981: problems 78–81 have
/// the same five variables and three equality constraints)
///
///     c₀ = Σ xᵢ² − 10,   c₁ = x₁x₂ − 5x₃x₄,   c₂ = x₀³ + x₁³ + 1,
///
/// and an objective built on the product p = x₀x₁x₂x₃x₄. Jacobian pattern:
/// row 0 every column, row 1 columns 1…4, row 2 columns 0 and 1. Hessians are
/// the dense lower triangle of 5 × 5, row by row.
namespace hs078_family {

constexpr int kVariables = 5;

/// Π_{k ∉ {skip_a, skip_b}} x_k (no division, so zeros are fine); −1 skips nothing.
double product_without(Nlp::ConstVectorRef x, int skip_a, int skip_b);
/// Position of (row, col), row ≥ col, in the row-by-row lower triangle.
constexpr int lower_triangle_index(int row, int col) { return row * (row + 1) / 2 + col; }

void add_jacobian_pattern(SparsityPattern& pattern);
/// The dense lower triangle, row by row.
void add_hessian_pattern(SparsityPattern& pattern);
void constraints(Nlp::ConstVectorRef x, Nlp::VectorRef c);
void jacobian_values(Nlp::ConstVectorRef x, Nlp::VectorRef values);
/// values += Σᵢ λᵢ ∇²cᵢ: λ₀ 2I; λ₁ at (2,1) and −5λ₁ at (4,3); λ₂ 6x₀ at (0,0) and 6x₁ at (1,1).
void add_constraint_curvature(Nlp::ConstVectorRef x, Nlp::ConstVectorRef lambda, Nlp::VectorRef values);

} // namespace hs078_family
} // namespace sinew
