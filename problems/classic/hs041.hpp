#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 41 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), nonconvex, with 0-based variables x₀…x₃:
///
///     minimize   2 − x₀x₁x₂
///     subject to c₀ = x₀ + 2x₁ + 2x₂ − x₃ = 0
///                0 ≤ x₀, x₁, x₂ ≤ 1,  0 ≤ x₃ ≤ 2
///
/// Start (2, 2, 2, 2), outside the box. Published optimum f* = 52/27 at
/// x* = (2/3, 1/3, 1/3, 2).
class Hs041 : public Nlp {
public:
    Hs041();

    std::string name() const override { return "hs041"; }
    int num_variables() const override { return 4; }
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
