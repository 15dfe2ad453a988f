#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 63 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), nonconvex, with 0-based variables x₀…x₂:
///
///     minimize   1000 − x₀² − 2x₁² − x₂² − x₀x₁ − x₀x₂
///     subject to c₀ = 8x₀ + 14x₁ + 7x₂ − 56 = 0
///                c₁ = x₀² + x₁² + x₂² − 25 = 0
///                xᵢ ≥ 0
///
/// Start (2, 2, 2). Published optimum f* = 961.7151721 (printed to 10 digits)
/// at x* = (3.512118414, 0.2169881741, 3.552174034). Solving the KKT
/// conditions to 40 digits gives f* = 961.715172130052, which rounds to it.
class Hs063 : public Nlp {
public:
    Hs063();

    std::string name() const override { return "hs063"; }
    int num_variables() const override { return 3; }
    int num_constraints() const override { return 2; }
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
