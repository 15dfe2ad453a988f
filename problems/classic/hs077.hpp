#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 77 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), nonconvex, with 0-based variables x₀…x₄:
///
///     minimize   (x₀ − 1)² + (x₀ − x₁)² + (x₂ − 1)² + (x₃ − 1)⁴ + (x₄ − 1)⁶
///     subject to c₀ = x₀²x₃ + sin(x₃ − x₄) − 2√2 = 0
///                c₁ = x₁ + x₂⁴x₃² − 8 − √2 = 0
///
/// Start (2, 2, 2, 2, 2). Published optimum f* = 0.24150513 (8 digits) at
/// x* = (1.166172, 1.182111, 1.380257, 1.506036, 0.6109203). Solving the KKT
/// conditions to 40 digits from that x* gives f* = 0.241505128790, which rounds
/// to the printed value, at x = (1.16617218970930, 1.18211138880270,
/// 1.38025704314546, 1.50603627362305, 0.610920196043091).
class Hs077 : public Nlp {
public:
    Hs077();

    std::string name() const override { return "hs077"; }
    int num_variables() const override { return 5; }
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
