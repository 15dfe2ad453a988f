#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 81 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), nonconvex, with 0-based variables x₀…x₄:
///
///     minimize   exp(x₀x₁x₂x₃x₄) − ½ (x₀³ + x₁³ + 1)²
///     subject to c₀ = x₀² + x₁² + x₂² + x₃² + x₄² − 10 = 0
///                c₁ = x₁x₂ − 5x₃x₄ = 0
///                c₂ = x₀³ + x₁³ + 1 = 0
///                −2.3 ≤ x₀, x₁ ≤ 2.3,  −3.2 ≤ x₂, x₃, x₄ ≤ 3.2
///
/// Start (−2, 2, 2, −1, −1). Published optimum f* = 0.0539498478 (9 digits).
/// The printed x* (−1.717142, 1.159571, 1.827248, −0.7636474, −0.7636390) has
/// a misprint in x₁ (1.159571 for 1.5957…: it violates c₂ by 2.5). c₂ = 0
/// makes the second term of f vanish on the feasible set, so the minimizer is
/// that of HS 78 (min x₀x₁x₂x₃x₄, same constraints, Hs078) and f* = exp of its
/// f*. Solving the KKT conditions to 40 digits gives f* = 0.0539498477702720,
/// which rounds to the printed value, at x = (−1.71714357039438,
/// 1.59570969018355, 1.82724575292719, −0.763643078184130, −0.763643078184130),
/// where no bound is active.
class Hs081 : public Nlp {
public:
    Hs081();

    std::string name() const override { return "hs081"; }
    int num_variables() const override { return 5; }
    int num_constraints() const override { return 3; }
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
