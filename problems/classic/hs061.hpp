#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 61 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), with 0-based variables x₀…x₂:
///
///     minimize   4x₀² + 2x₁² + 2x₂² − 33x₀ + 16x₁ − 24x₂
///     subject to c₀ = 3x₀ − 2x₁² − 7 = 0
///                c₁ = 4x₀ − x₂² − 11 = 0
///
/// Start (0, 0, 0). Published optimum f* = −143.6461422 (printed to 10 digits)
/// at x* = (5.326770157, −2.118998639, 3.210464239). Solving the KKT
/// conditions to 40 digits gives f* = −143.646142197780, which rounds to it.
class Hs061 : public Nlp {
public:
    Hs061();

    std::string name() const override { return "hs061"; }
    int num_variables() const override { return 3; }
    int num_constraints() const override { return 2; }
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
