#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 5 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), McCormick's function, nonconvex, with 0-based
/// variables x₀, x₁:
///
///     minimize   sin(x₀ + x₁) + (x₀ − x₁)² − 1.5x₀ + 2.5x₁ + 1
///     subject to −1.5 ≤ x₀ ≤ 4, −3 ≤ x₁ ≤ 3
///
/// Start (0, 0). Published optimum f* = −√3/2 − π/3 ≈ −1.9132229549810 at
/// x* = (1/2 − π/3, −1/2 − π/3), in the interior of the box.
class Hs005 : public Nlp {
public:
    Hs005();

    std::string name() const override { return "hs005"; }
    int num_variables() const override { return 2; }
    void variable_bounds(VectorRef lower, VectorRef upper) const override;
    Vector starting_point() const override;

    double objective(ConstVectorRef x) override;
    void gradient(ConstVectorRef x, VectorRef grad) override;

    const SparsityPattern& hessian_pattern() const override { return hessian_pattern_; }

protected:
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    SparsityPattern hessian_pattern_;
};

} // namespace sinew
