#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 39 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), with 0-based variables x₀…x₃:
///
///     minimize   −x₀
///     subject to c₀ = x₁ − x₀³ − x₂² = 0
///                c₁ = x₀² − x₁ − x₃² = 0
///
/// Start (2, 2, 2, 2). Published optimum f* = −1 at x* = (1, 1, 0, 0).
class Hs039 : public Nlp {
public:
    Hs039();

    std::string name() const override { return "hs039"; }
    int num_variables() const override { return 4; }
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
