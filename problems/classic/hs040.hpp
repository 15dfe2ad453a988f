#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 40 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), nonconvex, with 0-based variables x₀…x₃:
///
///     minimize   −x₀x₁x₂x₃
///     subject to c₀ = x₀³ + x₁² − 1 = 0
///                c₁ = x₀²x₃ − x₂ = 0
///                c₂ = x₃² − x₁ = 0
///
/// Start (0.8, 0.8, 0.8, 0.8). Published optimum f* = −1/4 at
/// x* = (2^(−1/3), 2^(−1/2), 2^(−11/12), 2^(−1/4)).
class Hs040 : public Nlp {
public:
    Hs040();

    std::string name() const override { return "hs040"; }
    int num_variables() const override { return 4; }
    int num_constraints() const override { return 3; }
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
