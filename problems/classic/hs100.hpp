#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 100 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), with 0-based variables x₀…x₆:
///
///     minimize   (x₀ − 10)² + 5(x₁ − 12)² + x₂⁴ + 3(x₃ − 11)² + 10x₄⁶ + 7x₅²
///                + x₆⁴ − 4x₅x₆ − 10x₅ − 8x₆
///     subject to c₀ = 127 − 2x₀² − 3x₁⁴ − x₂ − 4x₃² − 5x₄ ≥ 0
///                c₁ = 282 − 7x₀ − 3x₁ − 10x₂² − x₃ + x₄ ≥ 0
///                c₂ = 196 − 23x₀ − x₁² − 6x₅² + 8x₆ ≥ 0
///                c₃ = −4x₀² − x₁² + 3x₀x₁ − 2x₂² − 5x₅ + 11x₆ ≥ 0
///
/// Start (1, 2, 0, 4, 0, 1, 1). Published optimum f* = 680.6300573 at
/// x* = (2.330499, 1.951372, −0.4775414, 4.365726, −0.6244870, 1.038131, 1.594227),
/// where c₀ and c₃ are active. Solving the KKT conditions to 30 digits with
/// those two active gives f* = 680.63005737440, which agrees to all published digits.
class Hs100 : public Nlp {
public:
    Hs100();

    std::string name() const override { return "hs100"; }
    int num_variables() const override { return 7; }
    int num_constraints() const override { return 4; }
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
