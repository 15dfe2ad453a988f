#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 76 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), a convex QP, with 0-based variables x₀…x₃:
///
///     minimize   x₀² + 0.5x₁² + x₂² + 0.5x₃² − x₀x₂ + x₂x₃ − x₀ − 3x₁ + x₂ − x₃
///     subject to c₀ = 5 − x₀ − 2x₁ − x₂ − x₃ ≥ 0
///                c₁ = 4 − 3x₀ − x₁ − 2x₂ + x₃ ≥ 0
///                c₂ = x₁ + 4x₂ − 1.5 ≥ 0
///                xᵢ ≥ 0
///
/// Start (0.5, 0.5, 0.5, 0.5). Published optimum f* = −4.681818181 at
/// x* = (0.2727273, 2.090909, −0.26e-10, 0.5454545); exactly
/// x* = (3/11, 23/11, 0, 6/11), f* = −103/22, with c₀ and the bound on x₂ active.
class Hs076 : public Nlp {
public:
    Hs076();

    std::string name() const override { return "hs076"; }
    int num_variables() const override { return 4; }
    int num_constraints() const override { return 3; }
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
