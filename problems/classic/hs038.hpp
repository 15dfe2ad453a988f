#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 38 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), Colville's function, nonconvex, with 0-based
/// variables x₀…x₃:
///
///     minimize   100(x₁ − x₀²)² + (1 − x₀)² + 90(x₃ − x₂²)² + (1 − x₂)²
///                + 10.1((x₁ − 1)² + (x₃ − 1)²) + 19.8(x₁ − 1)(x₃ − 1)
///     subject to −10 ≤ xᵢ ≤ 10
///
/// Start (−3, −1, −3, −1). Published optimum f* = 0 at x* = (1, 1, 1, 1).
class Hs038 : public Nlp {
public:
    Hs038();

    std::string name() const override { return "hs038"; }
    int num_variables() const override { return 4; }
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
