#include "sinew/core/input_error.hpp"
#include "sinew/energies/constraints/orthogonality.hpp"
#include "sinew/inverse/rig_fit_problem.hpp"
#include "sinew/inverse/rig_fit_run.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/taylor_test.hpp"
#include "sinew/solvers/solver.hpp"

#include "inverse/rig_test_support.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

/// minimize ½‖x‖² subject to the orthogonality of the M stored at x[2..10]:
/// an NLP around the constraint set, for the shared derivative check.
class OrthogonalityNlp final : public Nlp {
public:
    OrthogonalityNlp() : set_("test", 2)
    {
        for (int c = 0; c < 13; ++c)
            hessian_pattern_.add(c, c);
        for (int q = 0; q < set_.hessian_pattern().nonzeros(); ++q)
            hessian_pattern_.add(set_.hessian_pattern().rows[q], set_.hessian_pattern().cols[q]);
    }
    std::string name() const override { return "orthogonality"; }
    int num_variables() const override { return 13; }
    int num_constraints() const override { return 6; }
    void constraint_bounds(VectorRef lower, VectorRef upper) const override
    {
        lower.setZero();
        upper.setZero();
    }
    Vector starting_point() const override { return Vector::Zero(13); }
    double objective(ConstVectorRef x) override { return 0.5 * x.squaredNorm(); }
    void gradient(ConstVectorRef x, VectorRef g) override { g = x; }
    void constraints(ConstVectorRef x, VectorRef c) override { set_.values(x, c); }
    const SparsityPattern& jacobian_pattern() const override { return set_.jacobian_pattern(); }
    void jacobian_values(ConstVectorRef x, VectorRef values) override { set_.jacobian_values(x, values); }
    const SparsityPattern& hessian_pattern() const override { return hessian_pattern_; }
    bool supports(Projection) const override { return true; }
    Orthogonality& set() { return set_; }

protected:
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override
    {
        fill(x, sigma, lambda, Projection::none, values);
    }
    void projected_hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override
    {
        fill(x, sigma, lambda, Projection::clamp, values);
    }

private:
    void fill(ConstVectorRef x, double sigma, ConstVectorRef lambda, Projection projection, VectorRef values)
    {
        values.head(13).setConstant(sigma);
        set_.hessian_values(x, lambda, projection, values.tail(set_.hessian_pattern().nonzeros()));
    }

    Orthogonality set_;
    SparsityPattern hessian_pattern_;
};

Eigen::MatrixXd dense_lower(const SparsityPattern& pattern, const Eigen::VectorXd& values, int n)
{
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
    for (int q = 0; q < pattern.nonzeros(); ++q) {
        H(pattern.rows[q], pattern.cols[q]) += values[q];
        if (pattern.rows[q] != pattern.cols[q])
            H(pattern.cols[q], pattern.rows[q]) += values[q];
    }
    return H;
}

/// Landmark targets of the rig at θ*, and the rig itself back at rest.
Eigen::VectorXd targets_of(MuscleRig& rig, const RigParameters& theta)
{
    REQUIRE(rig.evaluate(theta).ok);
    return rig.landmark_positions();
}

struct FitOutcome {
    Result result;
    double rms = 0.0;                ///< landmark RMS error (m)
    double parameter_error = 0.0;    ///< max |θ − θ*|
    double cranium_violation = 0.0;  ///< ‖M_cᵀM_c − I‖_F
    double jaw_violation = 0.0;
};

FitOutcome fit(const std::string& solver, SolverOptions options, OrthogonalityForm form, const RigParameters& truth)
{
    MuscleRig rig(slab_rig(), tight_settings());
    const Eigen::VectorXd targets = targets_of(rig, truth);
    RigFitSettings settings;
    settings.orthogonality = form;
    RigFitProblem problem(rig, targets, settings);
    FitOutcome outcome;
    outcome.result = solve(problem, solver, options);
    const Eigen::VectorXd& theta = outcome.result.x;
    INFO(solver << ": " << to_string(outcome.result.status) << ", " << outcome.result.message << ", "
                << outcome.result.iterations << " iterations");
    outcome.rms = std::sqrt(problem.residual(theta).squaredNorm() / rig.num_landmarks());
    outcome.parameter_error = (theta - truth.packed()).cwiseAbs().maxCoeff();
    outcome.cranium_violation = problem.cranium_violation(theta);
    outcome.jaw_violation = problem.jaw_violation(theta);
    return outcome;
}

} // namespace

TEST_CASE("orthogonality constraints: Jacobian and Hessian against differences, projection PSD",
          "[inverse][orthogonality]")
{
    OrthogonalityNlp nlp;
    std::mt19937 rng(5);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 20; ++trial) {
        Eigen::VectorXd x(13);
        for (int i = 0; i < 13; ++i)
            x[i] = normal(rng);
        const DerivativeCheckReport report = check_derivatives(nlp, x, {1e-6, 1.0, static_cast<unsigned>(trial)});
        CAPTURE(report.to_text());
        CHECK(report.passed(1e-7));
        Eigen::VectorXd lambda(6), values(nlp.hessian_pattern().nonzeros());
        for (int i = 0; i < 6; ++i)
            lambda[i] = normal(rng);
        nlp.hessian(x, 0.0, lambda, Projection::clamp, values);
        const Eigen::MatrixXd H = dense_lower(nlp.hessian_pattern(), values, 13);
        CHECK(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H).eigenvalues().minCoeff() >= -1e-12);
    }
    Eigen::VectorXd rotation = Eigen::VectorXd::Zero(13);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i)
            rotation[2 + 3 * k + i] = R(k, i);
    CHECK(nlp.set().violation(rotation) < 1e-15);
    Eigen::VectorXd c(6);
    nlp.set().values(rotation, c);
    CHECK(c.cwiseAbs().maxCoeff() < 1e-15);
    CHECK_THROWS_AS(Orthogonality("bad", -1), InputError);
}

TEST_CASE("rig fit: noise-free targets are recovered by ipopt and by kkt-newton with exact orthogonality",
          "[inverse][rig][fit]")
{
    const RigParameters truth = moved_parameters(8.0);
    SolverOptions ipopt;
    ipopt.tolerance = 1e-14;
    ipopt.max_iterations = 200;
    ipopt.backend["hessian_approximation"] = "exact";
    SolverOptions kkt;
    kkt.tolerance = 1e-14;
    kkt.max_iterations = 200;
    for (const auto& [solver, options] : {std::pair<std::string, SolverOptions>{"ipopt", ipopt}, {"kkt-newton", kkt}}) {
        CAPTURE(solver);
        const FitOutcome outcome = fit(solver, options, OrthogonalityForm::constraints, truth);
        const double size = MuscleRig(slab_rig(), tight_settings()).size();
        CAPTURE(to_string(outcome.result.status), outcome.result.iterations, outcome.rms, outcome.parameter_error,
                outcome.cranium_violation, outcome.jaw_violation);
        CHECK(outcome.rms <= 1e-6 * size);
        CHECK(outcome.parameter_error <= 1e-5);
        CHECK(outcome.cranium_violation <= 1e-9);
        CHECK(outcome.jaw_violation <= 1e-9);
    }
}

TEST_CASE("rig fit run: kkt-newton recovers theta* with and without a ball pressing in, on the branch solved from rest",
          "[inverse][rig][fit][contact]")
{
    SolverOptions options;
    options.tolerance = 1e-14;
    options.max_iterations = 200;
    for (const bool pressed : {false, true}) {
        CAPTURE(pressed);
        const RigDefinition definition = pressed ? slab_rig_pressed_by_ball() : slab_rig();
        const RigFitOutcome outcome =
            run_rig_fit(definition, tight_settings(), targets_at(definition, moved_parameters(8.0)),
                        {"kkt-newton", "kkt-newton", OrthogonalityForm::constraints, options}, {});
        CAPTURE(to_string(outcome.result.status), outcome.result.message, outcome.rms, outcome.activation_error);
        CHECK(outcome.activation_error <= 1e-5);
        CHECK(outcome.rms <= 1e-9);
        // The fit's warm-started equilibrium is the one solved from rest.
        CHECK(outcome.branch_distance <= 1e-9);
        CHECK(outcome.branch_node >= 0);
        if (pressed) {
            CHECK(outcome.max_penetration > 0.0);
            CHECK(outcome.max_penetration < 1e-4);
            CHECK(outcome.contact_force > 0.1);
        } else {
            CHECK(outcome.max_penetration == 0.0);
            CHECK(outcome.contact_force == 0.0);
        }
    }
}

TEST_CASE("rig fit: the objective gradient matches central differences of re-solves in both orthogonality forms",
          "[inverse][rig][fit]")
{
    // At maps off the orthogonal ones (so the penalty acts), with a Tikhonov
    // term, targets from another θ: every entry of ∇f (adjoint + penalty +
    // Tikhonov) against central differences of f, each side a full re-solve.
    for (const OrthogonalityForm form : {OrthogonalityForm::constraints, OrthogonalityForm::penalty}) {
        CAPTURE(to_string(form));
        MuscleRig rig(slab_rig(), tight_settings());
        const Eigen::VectorXd targets = targets_of(rig, moved_parameters(10.0));
        RigFitSettings settings;
        settings.orthogonality = form;
        settings.tikhonov = 1e-5;
        RigFitProblem problem(rig, targets, settings);
        RigParameters at = moved_parameters(4.0);
        at.cranium_map(0, 1) += 0.01;
        at.jaw_map(2, 2) -= 0.02;
        const Eigen::VectorXd theta = at.packed();
        REQUIRE(std::isfinite(problem.objective(theta)));
        Eigen::VectorXd gradient(theta.size());
        problem.gradient(theta, gradient);
        const Eigen::VectorXd differences = objective_differences(problem, theta);
        CAPTURE(gradient.transpose(), differences.transpose());
        REQUIRE(differences.norm() > 0.0);
        CHECK((gradient - differences).norm() <= 1e-6 * differences.norm());
    }
}

TEST_CASE("rig fit: bad targets and settings are refused with a message", "[inverse][rig][fit][errors]")
{
    MuscleRig rig(slab_rig(), tight_settings());
    Eigen::VectorXd targets = Eigen::VectorXd::Zero(3 * rig.num_landmarks());
    CHECK_THROWS_AS(RigFitProblem(rig, Eigen::VectorXd::Zero(5), {}), InputError);
    targets[4] = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(RigFitProblem(rig, targets, {}), Catch::Contains("landmark 1 is not finite"));
    targets[4] = 0.0;
    RigFitSettings negative;
    negative.tikhonov = -1.0;
    CHECK_THROWS_AS(RigFitProblem(rig, targets, negative), InputError);
}

TEST_CASE("rig fit strategies: the caller's backend options reach every strategy and its own take precedence",
          "[inverse][rig][fit]")
{
    SolverOptions base;
    base.tolerance = 1e-9;
    base.backend["print_level"] = "0";
    base.backend["hessian_approximation"] = "limited-memory";
    const std::vector<RigFitStrategy> strategies = rig_fit_strategies(base);
    REQUIRE(strategies.size() >= 2);
    for (const RigFitStrategy& strategy : strategies) {
        CHECK(strategy.options.tolerance == 1e-9);
        CHECK(strategy.options.backend.at("print_level") == "0");
    }
    CHECK(strategies.front().label == "ipopt (Gauss-Newton)");
    CHECK(strategies.front().options.backend.at("hessian_approximation") == "exact");
    CHECK(strategies.front().options.backend.at("constr_mult_init_max") == "0");
}
