#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 62 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), with 0-based variables x₀…x₂:
///
///     minimize   −32.174 [255 ln((x₀ + x₁ + x₂ + 0.03) / (0.09x₀ + x₁ + x₂ + 0.03))
///                         + 280 ln((x₁ + x₂ + 0.03) / (0.07x₁ + x₂ + 0.03))
///                         + 290 ln((x₂ + 0.03) / (0.13x₂ + 0.03))]
///     subject to c₀ = x₀ + x₁ + x₂ − 1 = 0
///                0 ≤ xᵢ ≤ 1
///
/// Start (0.7, 0.2, 0.1). Published optimum f* = −26272.51448 (printed to 10
/// digits) at x* = (0.6178126908, 0.328202223, 0.05398508606). Solving the KKT
/// conditions to 40 digits gives f* = −26272.5144873183, which rounds to it.
/// f is defined only where every logarithm's argument is positive, which the
/// bounds ensure: objective() returns +infinity elsewhere.
class Hs062 : public Nlp {
public:
    Hs062();

    std::string name() const override { return "hs062"; }
    int num_variables() const override { return 3; }
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
