#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 4 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), with 0-based variables x₀, x₁:
///
///     minimize   (x₀ + 1)³ / 3 + x₁
///     subject to x₀ ≥ 1, x₁ ≥ 0
///
/// Start (1.125, 0.125). Published optimum f* = 8/3 at x* = (1, 0), where both
/// bounds are active.
class Hs004 : public Nlp {
public:
    Hs004();

    std::string name() const override { return "hs004"; }
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
