#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 35 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), a convex QP, with 0-based variables x₀…x₂:
///
///     minimize   9 − 8x₀ − 6x₁ − 4x₂ + 2x₀² + 2x₁² + x₂² + 2x₀x₁ + 2x₀x₂
///     subject to c₀ = 3 − x₀ − x₁ − 2x₂ ≥ 0
///                xᵢ ≥ 0
///
/// Start (0.5, 0.5, 0.5). Published optimum f* = 1/9 at x* = (4/3, 7/9, 4/9).
class Hs035 : public Nlp {
public:
    Hs035();

    std::string name() const override { return "hs035"; }
    int num_variables() const override { return 3; }
    int num_constraints() const override { return 1; }
    void variable_bounds(VectorRef lower, VectorRef upper) const override;
    void constraint_bounds(VectorRef lower, VectorRef upper) const override;
    Vector starting_point() const override;

    double objective(ConstVectorRef x) override;
    void gradient(ConstVectorRef x, VectorRef grad) override;
    void constraints(ConstVectorRef x, VectorRef c) override;

    const SparsityPattern& jacobian_pattern() const override { return jacobian_pattern_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override;
    const SparsityPattern& hessian_pattern() const override { return hessian_pattern_; }
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    SparsityPattern jacobian_pattern_;
    SparsityPattern hessian_pattern_;
};

} // namespace sinew
