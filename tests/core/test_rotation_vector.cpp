// R(ω) = exp([ω]×) and its derivatives, through the shared derivative check.
#include "sinew/core/rotation_vector.hpp"
#include "sinew/problems/derivative_check.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <random>

using namespace sinew;

namespace {

/// minimize ½|ω|² subject to vec R(ω) = vec R(ω₀): 9 constraints whose
/// Jacobian is ∂R/∂ω (the check's Hessian is not compared: R's second
/// derivatives are not part of the map).
class RotationNlp final : public Nlp {
public:
    explicit RotationNlp(Eigen::Vector3d omega) : omega_(std::move(omega))
    {
        for (int k = 0; k < 9; ++k)
            for (int i = 0; i < 3; ++i)
                jacobian_pattern_.add(k, i);
    }
    std::string name() const override { return "rotation"; }
    int num_variables() const override { return 3; }
    int num_constraints() const override { return 9; }
    void constraint_bounds(VectorRef lower, VectorRef upper) const override
    {
        lower.setZero();
        upper.setZero();
    }
    Vector starting_point() const override { return omega_; }
    double objective(ConstVectorRef x) override { return 0.5 * x.squaredNorm(); }
    void gradient(ConstVectorRef x, VectorRef g) override { g = x; }
    void constraints(ConstVectorRef x, VectorRef c) override
    {
        const Eigen::Matrix3d R = rotation_matrix(x);
        for (int k = 0; k < 9; ++k)
            c[k] = R(k / 3, k % 3);
    }
    const SparsityPattern& jacobian_pattern() const override { return jacobian_pattern_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override
    {
        const std::array<Eigen::Matrix3d, 3> dR = rotation_matrix_derivatives(x);
        int q = 0;
        for (int k = 0; k < 9; ++k)
            for (int i = 0; i < 3; ++i)
                values[q++] = dR[i](k / 3, k % 3);
    }
    const SparsityPattern& hessian_pattern() const override { return hessian_pattern_; }

protected:
    void hessian_values(ConstVectorRef, double, ConstVectorRef, VectorRef) override {}

private:
    Eigen::Vector3d omega_;
    SparsityPattern jacobian_pattern_;
    SparsityPattern hessian_pattern_;
};

} // namespace

TEST_CASE("rotation vectors: R(omega) is the rotation by |omega| about omega and round-trips", "[core][rotation]")
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const double angle : {0.0, 1e-12, 1e-5, 0.999e-2, 1.001e-2, 0.3, 1.7, 3.1}) {
        CAPTURE(angle);
        const Eigen::Vector3d axis = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
        const Eigen::Matrix3d expected = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
        const Eigen::Matrix3d R = rotation_matrix(angle * axis);
        CHECK((R - expected).norm() < 1e-14);
        CHECK((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-14);
        if (angle > 0.0)
            CHECK((rotation_vector(R) - angle * axis).norm() < 1e-13);
    }
}

TEST_CASE("rotation vectors: dR/domega against central differences from zero to near pi", "[core][rotation]")
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    // At rest, tiny, on both sides of the switch to series, moderate, large, near π.
    for (const double angle : {0.0, 1e-9, 1e-4, 0.999e-2, 1.001e-2, 0.2, 1.3, 2.5, 3.1}) {
        for (int draw = 0; draw < 3; ++draw) {
            CAPTURE(angle, draw);
            const Eigen::Vector3d axis = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
            RotationNlp nlp(angle * axis);
            const DerivativeCheckReport report = check_derivatives(nlp, nlp.starting_point());
            CAPTURE(report.to_text());
            CHECK(report.jacobian.entries_compared == 27);
            CHECK(report.jacobian.worst_relative_error < 1e-6);
            CHECK(report.gradient.worst_relative_error < 1e-6);
        }
    }
    // At 0 the derivative is [e_k]× exactly.
    const std::array<Eigen::Matrix3d, 3> at_rest = rotation_matrix_derivatives(Eigen::Vector3d::Zero());
    CHECK(at_rest[2](1, 0) == 1.0);
    CHECK(at_rest[2](0, 1) == -1.0);
    CHECK(at_rest[0](2, 1) == 1.0);
}
