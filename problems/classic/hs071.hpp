#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 71 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), with 0-based variables x₀…x₃:
///
///     minimize   x₀ x₃ (x₀ + x₁ + x₂) + x₂
///     subject to c₀ = x₀ x₁ x₂ x₃ ≥ 25
///                c₁ = x₀² + x₁² + x₂² + x₃² = 40
///                1 ≤ xᵢ ≤ 5
///
/// Start (1, 5, 5, 1). Published optimum f* = 17.0140173 at
/// x* = (1, 4.7429994, 3.8211503, 1.3794082).
class Hs071 : public Nlp {
public:
    Hs071();

    std::string name() const override { return "hs071"; }
    int num_variables() const override { return 4; }
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
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    SparsityPattern jacobian_pattern_;
    SparsityPattern hessian_pattern_;
};

} // namespace sinew
