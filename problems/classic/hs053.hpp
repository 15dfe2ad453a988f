#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 53 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), a convex QP, with 0-based variables x₀…x₄:
///
///     minimize   (x₀ − x₁)² + (x₁ + x₂ − 2)² + (x₃ − 1)² + (x₄ − 1)²
///     subject to c₀ = x₀ + 3x₁ = 0
///                c₁ = x₂ + x₃ − 2x₄ = 0
///                c₂ = x₁ − x₄ = 0
///                −10 ≤ xᵢ ≤ 10
///
/// Start (2, 2, 2, 2, 2). Published optimum f* = 176/43 at
/// x* = (−33, 11, 27, −5, 11)/43, where no bound is active.
class Hs053 : public Nlp {
public:
    Hs053();

    std::string name() const override { return "hs053"; }
    int num_variables() const override { return 5; }
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

protected:
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    SparsityPattern jacobian_pattern_;
    SparsityPattern hessian_pattern_;
};

} // namespace sinew
