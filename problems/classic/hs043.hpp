#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 43, the Rosen-Suzuki problem (W. Hock,
/// K. Schittkowski, "Test Examples for Nonlinear Programming Codes", Lecture
/// Notes in Economics and Mathematical Systems 187, Springer, 1981), with
/// 0-based variables x₀…x₃:
///
///     minimize   x₀² + x₁² + 2x₂² + x₃² − 5x₀ − 5x₁ − 21x₂ + 7x₃
///     subject to c₀ = 8 − x₀² − x₁² − x₂² − x₃² − x₀ + x₁ − x₂ + x₃ ≥ 0
///                c₁ = 10 − x₀² − 2x₁² − x₂² − 2x₃² + x₀ + x₃ ≥ 0
///                c₂ = 5 − 2x₀² − x₁² − x₂² − 2x₀ + x₁ + x₃ ≥ 0
///
/// Start (0, 0, 0, 0). Published optimum f* = −44 at x* = (0, 1, 2, −1),
/// where c₀ and c₂ are active.
class Hs043 : public Nlp {
public:
    Hs043();

    std::string name() const override { return "hs043"; }
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
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    SparsityPattern jacobian_pattern_;
    SparsityPattern hessian_pattern_;
};

} // namespace sinew
