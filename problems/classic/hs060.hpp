#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 60 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), with 0-based variables x₀…x₂:
///
///     minimize   (x₀ − 1)² + (x₀ − x₁)² + (x₁ − x₂)⁴
///     subject to c₀ = x₀(1 + x₁²) + x₂⁴ − 4 − 3√2 = 0
///                −10 ≤ xᵢ ≤ 10
///
/// Start (2, 2, 2). Published optimum f* = 0.03256820025 at
/// x* = (1.104859024, 1.196674194, 1.535262257). Solving the KKT conditions to
/// 40 digits gives f* = 0.0325682002550698, which rounds to it.
class Hs060 : public Nlp {
public:
    Hs060();

    std::string name() const override { return "hs060"; }
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

protected:
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    SparsityPattern jacobian_pattern_;
    SparsityPattern hessian_pattern_;
};

} // namespace sinew
