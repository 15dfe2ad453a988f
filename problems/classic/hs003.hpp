#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 3 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), with 0-based variables x₀, x₁:
///
///     minimize   x₁ + 10⁻⁵ (x₁ − x₀)²
///     subject to x₁ ≥ 0   (x₀ free)
///
/// Start (10, 1). Published optimum f* = 0 at x* = (0, 0), where the bound is
/// active (its multiplier is 1). ∇²f = 2·10⁻⁵ [1 −1; −1 1] is singular: along
/// (1, 1) f is linear, f(t, t) = t, so only the bound keeps f bounded below.
class Hs003 : public Nlp {
public:
    Hs003();

    std::string name() const override { return "hs003"; }
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
