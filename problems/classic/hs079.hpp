#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 79 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), nonconvex, with 0-based variables x₀…x₄:
///
///     minimize   (x₀ − 1)² + (x₀ − x₁)² + (x₁ − x₂)² + (x₂ − x₃)⁴ + (x₃ − x₄)⁴
///     subject to c₀ = x₀ + x₁² + x₂³ − 2 − 3√2 = 0
///                c₁ = x₁ − x₂² + x₃ + 2 − 2√2 = 0
///                c₂ = x₀x₄ − 2 = 0
///
/// Start (2, 2, 2, 2, 2). Published optimum f* = 0.0787768209 (9 digits) at
/// x* = (1.191127, 1.362603, 1.472818, 1.635017, 1.679081). Solving the KKT
/// conditions to 40 digits from that x* gives f* = 0.0787768208710569, which
/// rounds to the printed value, at x = (1.19112745631105, 1.36260316496174,
/// 1.47281793151209, 1.63501661916799, 1.67908143616641).
class Hs079 : public Nlp {
public:
    Hs079();

    std::string name() const override { return "hs079"; }
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
