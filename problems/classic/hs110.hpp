#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 110 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), Paviani's function, with 0-based variables x₀…x₉:
///
///     minimize   Σᵢ [ln(xᵢ − 2)² + ln(10 − xᵢ)²] − (Πᵢ xᵢ)^0.2
///     subject to 2.001 ≤ xᵢ ≤ 9.999
///
/// Start xᵢ = 9. Published optimum f* = −45.77846971 (printed to 10 digits) at
/// xᵢ* = 9.35025655. Solving the symmetric stationarity condition to 40 digits
/// gives xᵢ = 9.3502658331, f = −45.7784697074, which rounds to the printed f*
/// (the printed x* is 9e-6 off, which moves f by only 1e-10). f is defined only
/// for 2 < xᵢ < 10: objective() returns +infinity elsewhere.
class Hs110 : public Nlp {
public:
    Hs110();

    std::string name() const override { return "hs110"; }
    int num_variables() const override { return 10; }
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
