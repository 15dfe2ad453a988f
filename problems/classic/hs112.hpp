#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// Hock-Schittkowski problem 112 (W. Hock, K. Schittkowski, "Test Examples for
/// Nonlinear Programming Codes", Lecture Notes in Economics and Mathematical
/// Systems 187, Springer, 1981), a chemical equilibrium (minimal Gibbs free
/// energy), convex, with 0-based variables x₀…x₉ and S = Σₖ xₖ:
///
///     minimize   Σⱼ xⱼ (aⱼ + ln(xⱼ / S))
///     subject to c₀ = x₀ + 2x₁ + 2x₂ + x₅ + x₉ − 2 = 0
///                c₁ = x₃ + 2x₄ + x₅ + x₆ − 1 = 0
///                c₂ = x₂ + x₆ + x₇ + 2x₈ + x₉ − 1 = 0
///                xⱼ ≥ 10⁻⁶
///
/// with a = (−6.089, −17.164, −34.054, −5.914, −24.721, −14.986, −24.100,
/// −10.708, −26.662, −22.179) (the book's cⱼ). Start xⱼ = 0.1 (infeasible).
///
/// Published optimum f* = −47.76109026 (printed to 10 digits, in the later
/// listings of the collection). The 1981 book prints f* = −47.707579 at
/// x* = (0.01773548, 0.08200180, 0.8825646, 0.7233256e−3, 0.4907851,
/// 0.4335469e−3, 0.01727298, 0.007765639, 0.01984929, 0.05269826), which is
/// feasible (to 9e−8) but not stationary (f = −47.70758 there). f is convex
/// (Σⱼ xⱼ ln(xⱼ/S) is the perspective of the negative entropy) and the
/// constraints are linear, so the KKT point is the minimizer: solving the KKT
/// conditions to 40 digits gives f* = −47.7610908594, which the later f* has
/// to 7 digits (−47.76109; it is 6e−7 off), at x = (0.0406680873556902,
/// 0.147730354340822, 0.783153354009234, 0.00141421980903012,
/// 0.485246648699273, 0.000693172078421066, 0.0273993107140033,
/// 0.0179472795849254, 0.0373143659130304, 0.0968713238657771), where no
/// bound is active. f is defined only for xⱼ > 0: objective() returns
/// +infinity elsewhere.
class Hs112 : public Nlp {
public:
    Hs112();

    std::string name() const override { return "hs112"; }
    int num_variables() const override { return 10; }
    int num_constraints() const override { return 3; }
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
