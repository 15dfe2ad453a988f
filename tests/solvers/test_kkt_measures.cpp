// The KKT residual must see each way a point can fail to be optimal.
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/solvers/kkt_measures.hpp"

#include <catch2/catch.hpp>

using namespace sinew;

namespace {

/// min (x₀ − 2)² + (x₁ + 1)²  s.t. 0 <= x <= 1,  x₀ + x₁ <= 0.5 (n = 2, m = 1).
/// Solution: x = (0.5, 0), since x₀ + x₁ <= 0.5 and x₁ >= 0 are active.
class BoxProblem : public Nlp {
public:
    BoxProblem()
    {
        jacobian_.add(0, 0);
        jacobian_.add(0, 1);
        hessian_.add(0, 0);
        hessian_.add(1, 1);
    }
    std::string name() const override { return "box"; }
    int num_variables() const override { return 2; }
    int num_constraints() const override { return 1; }
    void variable_bounds(VectorRef l, VectorRef u) const override
    {
        l.setZero();
        u.setOnes();
    }
    void constraint_bounds(VectorRef l, VectorRef u) const override
    {
        l[0] = -kInfinity;
        u[0] = 0.5;
    }
    Vector starting_point() const override { return Vector::Zero(2); }
    double objective(ConstVectorRef x) override { return (x[0] - 2) * (x[0] - 2) + (x[1] + 1) * (x[1] + 1); }
    void gradient(ConstVectorRef x, VectorRef g) override
    {
        g[0] = 2 * (x[0] - 2);
        g[1] = 2 * (x[1] + 1);
    }
    void constraints(ConstVectorRef x, VectorRef c) override { c[0] = x[0] + x[1]; }
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef, VectorRef v) override { v.setOnes(); }
    const SparsityPattern& hessian_pattern() const override { return hessian_; }
    void hessian_values(ConstVectorRef, double sigma, ConstVectorRef, VectorRef v) override
    {
        v.setConstant(2 * sigma);
    }

private:
    SparsityPattern jacobian_, hessian_;
};

} // namespace

TEST_CASE("estimated multipliers make the KKT residual vanish at the solution")
{
    BoxProblem problem;
    const Eigen::Vector2d x(0.5, 0.0);
    Eigen::VectorXd lambda, zl, zu;
    estimate_multipliers(problem, x, 1e-8, lambda, zl, zu);
    // ∇f = (−3, 2): λ = 3 on c <= 0.5 (upper, so λ >= 0), z_L₁ = 5.
    CHECK(lambda[0] == Approx(3.0));
    CHECK(zl[1] == Approx(5.0));
    CHECK(zu.cwiseAbs().maxCoeff() == 0.0);
    CHECK(kkt_residual(problem, x, lambda, zl, zu) < 1e-12);
}

TEST_CASE("the KKT residual sees stationarity, sign and complementarity errors")
{
    BoxProblem problem;
    const Eigen::Vector2d x(0.5, 0.0);
    const Eigen::VectorXd lambda = Eigen::VectorXd::Constant(1, 3.0);
    Eigen::VectorXd zl = Eigen::Vector2d(0.0, 5.0), zu = Eigen::Vector2d::Zero();
    CHECK(kkt_residual(problem, x, lambda, zl, zu) < 1e-12);
    // Not stationary away from the solution.
    CHECK(kkt_residual(problem, Eigen::Vector2d(0.4, 0.0), lambda, zl, zu) > 0.1);
    // A negative λ on a constraint with no lower bound is a sign error.
    Eigen::VectorXd wrong_sign = -lambda;
    CHECK(kkt_residual(problem, x, wrong_sign, zl, zu) >= 3.0);
    // A bound multiplier on an inactive bound breaks complementarity.
    const Eigen::Vector2d y(0.5, 0.2);
    CHECK(kkt_residual(problem, y, lambda, zl, zu) >= 5.0 * 0.2 - 1e-12);
}
