#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 56 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), nonconvex, with 0-based variables x₀…x₆:
///
///     minimize   −x₀x₁x₂
///     subject to c₀ = x₀ − 4.2 sin²x₃ = 0
///                c₁ = x₁ − 4.2 sin²x₄ = 0
///                c₂ = x₂ − 4.2 sin²x₅ = 0
///                c₃ = x₀ + 2x₁ + 2x₂ − 7.2 sin²x₆ = 0
///
/// Start (1, 1, 1, a, a, a, b) with a = asin √(1/4.2), b = asin √(5/7.2)
/// (feasible). Published optimum f* = −3.456 at
/// x* = (2.4, 1.2, 1.2, asin √(4/7), asin √(2/7), asin √(2/7), π/2).
class Hs056 : public Nlp {
public:
    Hs056();

    std::string name() const override { return "hs056"; }
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

protected:
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    SparsityPattern jacobian_pattern_;
    SparsityPattern hessian_pattern_;
};

} // namespace sinew
