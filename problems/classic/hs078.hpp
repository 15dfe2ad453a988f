#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 78 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), nonconvex, with 0-based variables x₀…x₄:
///
///     minimize   x₀x₁x₂x₃x₄
///     subject to c₀ = x₀² + x₁² + x₂² + x₃² + x₄² − 10 = 0
///                c₁ = x₁x₂ − 5x₃x₄ = 0
///                c₂ = x₀³ + x₁³ + 1 = 0
///
/// Start (−2, 1.5, 2, −1, −1). Published optimum f* = −2.91970041 (9 digits) at
/// x* = (−1.717142, 1.595708, 1.827248, −0.7636429, −0.7636435). Solving the
/// KKT conditions to 40 digits from that x* gives f* = −2.91970040896368,
/// which rounds to the printed value, at x = (−1.71714357039438,
/// 1.59570969018355, 1.82724575292719, −0.763643078184130, −0.763643078184130).
class Hs078 : public Nlp {
public:
    Hs078();

    std::string name() const override { return "hs078"; }
    int num_variables() const override { return 5; }
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
