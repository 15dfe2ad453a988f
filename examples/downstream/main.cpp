// A downstream program: its own NLP, solved by sinew with Ipopt and NLopt.
//
//   minimize (x₀ − 2)² + (x₁ − 1)²  subject to  x₀² + x₁² = 1
//
// The closest point of the unit circle to (2, 1) is (2, 1)/√5, with
// f* = (√5 − 1)² = 6 − 2√5.
#include <sinew/problems/nlp.hpp>
#include <sinew/solvers/solver.hpp>

#include <cmath>
#include <iostream>
#include <string>

namespace {

class CircleProjection : public sinew::Nlp {
public:
    CircleProjection()
    {
        jacobian_.add(0, 0);
        jacobian_.add(0, 1);
        hessian_.add(0, 0);
        hessian_.add(1, 1);
    }
    std::string name() const override { return "circle_projection"; }
    int num_variables() const override { return 2; }
    int num_constraints() const override { return 1; }
    void constraint_bounds(VectorRef lower, VectorRef upper) const override { lower[0] = upper[0] = 1.0; }
    Vector starting_point() const override { return Eigen::Vector2d(0.5, 0.5); }
    double objective(ConstVectorRef x) override { return std::pow(x[0] - 2, 2) + std::pow(x[1] - 1, 2); }
    void gradient(ConstVectorRef x, VectorRef g) override
    {
        g[0] = 2 * (x[0] - 2);
        g[1] = 2 * (x[1] - 1);
    }
    void constraints(ConstVectorRef x, VectorRef c) override { c[0] = x.squaredNorm(); }
    const sinew::SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override { values = 2 * x; }
    const sinew::SparsityPattern& hessian_pattern() const override { return hessian_; }
    void hessian_values(ConstVectorRef, double sigma, ConstVectorRef lambda, VectorRef values) override
    {
        values.setConstant(2 * sigma + 2 * lambda[0]);
    }

private:
    sinew::SparsityPattern jacobian_, hessian_;
};

} // namespace

int main()
{
    const double expected = 6.0 - 2.0 * std::sqrt(5.0);
    int failures = 0;
    for (const char* solver : {"ipopt", "nlopt-slsqp"}) {
        CircleProjection problem;
        sinew::SolverOptions options;
        // Backend options pass through by name. SLSQP stops on the relative
        // change of f; at its default (options.tolerance = 1e-8) the KKT
        // residual here is still ~1e-4, so ask for a smaller change.
        if (std::string(solver) == "nlopt-slsqp")
            options.backend["ftol_rel"] = "1e-14";
        const sinew::Result result = sinew::solve(problem, solver, options);
const bool ok = result.status == sinew::Status::converged && std::abs(result.objective - expected) < 1e-7;
        std::cout << solver << ": " << sinew::to_string(result.status) << ", f = " << result.objective
                  << " (expected " << expected << "), " << result.message << (ok ? "" : "  <-- wrong") << "\n";
        failures += ok ? 0 : 1;
    }
    return failures == 0 ? 0 : 1;
}
