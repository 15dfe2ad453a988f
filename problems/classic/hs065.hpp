#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 65 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), with 0-based variables x₀…x₂:
///
///     minimize   (x₀ − x₁)² + (x₀ + x₁ − 10)²/9 + (x₂ − 5)²
///     subject to c₀ = 48 − x₀² − x₁² − x₂² ≥ 0
///                −4.5 ≤ x₀, x₁ ≤ 4.5,  −5 ≤ x₂ ≤ 5
///
/// Start (−5, 5, 0), which violates the bound on x₀ (as published). Published
/// optimum f* = 0.9535288567 at x* = (3.650461821, 3.65046168, 4.6204170507).
/// The problem is symmetric in x₀, x₁; solving its KKT conditions to 30 digits
/// (c₀ active) gives x₀ = x₁ = 3.6504617252, x₂ = 4.6204175553,
/// f* = 0.95352885680, which agrees with the published f* to all its digits.
class Hs065 : public Nlp {
public:
    Hs065();

    std::string name() const override { return "hs065"; }
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
