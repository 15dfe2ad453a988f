#pragma once
#include "sinew/problems/nlp.hpp"

#include <string>

namespace sinew {

/// The extended Rosenbrock function, unconstrained (n even):
///
///     f(x) = Σ_{j=0}^{n/2-1} [ 100 (x_{2j+1} − x_{2j}²)² + (1 − x_{2j})² ]
///
/// Start x = (−1.2, 1, −1.2, 1, …). Optimum f* = 0 at x* = (1, …, 1).
/// Source: J. J. Moré, B. S. Garbow, K. E. Hillstrom, "Testing unconstrained
/// optimization software", ACM TOMS 7 (1981) 17–41, problem 21; for n = 2 it
/// is Rosenbrock's function (The Computer Journal 3 (1960) 175–184).
///
/// The chained variant Σ_{i} 100 (x_{i+1} − x_i²)² + (1 − x_i)² is not used:
/// from this start it has a local minimum with f ≈ 3.98 for n >= 4, which
/// Ipopt finds (seen: f = 3.9866 on n = 1000), so f* = 0 is not what a
/// local solver is expected to reach.
///
/// Its Hessian is block diagonal with 2×2 blocks; the lower triangle holds
/// (2j, 2j), (2j+1, 2j), (2j+1, 2j+1) for each pair j.
class Rosenbrock : public Nlp {
public:
    /// n variables, n >= 2 and even; InputError otherwise.
    explicit Rosenbrock(int n);

    std::string name() const override;
    int num_variables() const override { return n_; }
    Vector starting_point() const override;

    double objective(ConstVectorRef x) override;
    void gradient(ConstVectorRef x, VectorRef grad) override;

    const SparsityPattern& hessian_pattern() const override { return hessian_pattern_; }
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    int n_;
    SparsityPattern hessian_pattern_;
};

} // namespace sinew
