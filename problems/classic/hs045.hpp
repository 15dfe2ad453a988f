#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 45 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), nonconvex, with 0-based variables x₀…x₄:
///
///     minimize   2 − x₀x₁x₂x₃x₄ / 120
///     subject to 0 ≤ xᵢ ≤ i + 1
///
/// Start (2, 2, 2, 2, 2), outside the box (x₀ > 1). Published optimum f* = 1
/// at x* = (1, 2, 3, 4, 5), the corner where every upper bound is active.
class Hs045 : public Nlp {
public:
    Hs045();

    std::string name() const override { return "hs045"; }
    int num_variables() const override { return 5; }
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
