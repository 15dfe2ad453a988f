#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 9 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), nonconvex, with 0-based variables x₀, x₁:
///
///     minimize   sin(πx₀/12) cos(πx₁/16)
///     subject to c₀ = 4x₀ − 3x₁ = 0
///
/// Start (0, 0). Published optimum f* = −1/2 at every x* = (12k − 3, 16k − 4),
/// k an integer (along c₀ = 0, f = sin(πt/2)/2 with x = (3t, 4t)).
class Hs009 : public Nlp {
public:
    Hs009();

    std::string name() const override { return "hs009"; }
    int num_variables() const override { return 2; }
    int num_constraints() const override { return 1; }
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
