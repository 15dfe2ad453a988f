// Constraint sets composed into the quasistatic NLP (issue 12): Dirichlet
// conditions as the set PrescribedCoordinates, and a nonlinear set beside
// them, through the shared derivative checks and solved by the constrained
// strategies.
#include "sinew/energies/constraints/prescribed_coordinates.hpp"
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/problems/taylor_test.hpp"
#include "sinew/solvers/solver.hpp"

#include "potentials/test_meshes.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

/// Fixed squared distances between node pairs, cₖ = |x_b − x_a|² − Lₖ²
/// (a thread of inextensible segments; the form issue 13 builds on). Its
/// Hessian term λₖ∇²cₖ is λₖ[2I −2I; −2I 2I]: PSD for λₖ ≥ 0 and projected to
/// zero for λₖ < 0.
class SegmentLengths final : public ConstraintSet {
public:
    SegmentLengths(std::vector<std::pair<int, int>> segments, std::vector<double> lengths)
        : segments_(std::move(segments)), lengths_(std::move(lengths))
    {
        for (int k = 0; k < num_constraints(); ++k) {
            const auto [a, b] = segments_[k];
            for (int i = 0; i < 3; ++i) {
                jacobian_.add(k, 3 * a + i);
                jacobian_.add(k, 3 * b + i);
                hessian_.add(3 * a + i, 3 * a + i);
                hessian_.add(3 * b + i, 3 * b + i);
                hessian_.add(std::max(3 * a + i, 3 * b + i), std::min(3 * a + i, 3 * b + i));
            }
        }
    }
    std::string name() const override { return "segment lengths"; }
    int num_constraints() const override { return static_cast<int>(segments_.size()); }
    void values(ConstVectorRef x, VectorRef c) override
    {
        for (int k = 0; k < num_constraints(); ++k)
            c[k] = edge(x, k).squaredNorm() - lengths_[k] * lengths_[k];
    }
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override
    {
        for (int k = 0; k < num_constraints(); ++k) {
            const Eigen::Vector3d e = edge(x, k);
            for (int i = 0; i < 3; ++i) {
                values[6 * k + 2 * i] = -2.0 * e[i];     // ∂c/∂x_a
                values[6 * k + 2 * i + 1] = 2.0 * e[i];  // ∂c/∂x_b
            }
        }
    }
    const SparsityPattern& hessian_pattern() const override { return hessian_; }
    void hessian_values(ConstVectorRef, ConstVectorRef lambda, Projection projection, VectorRef values) override
    {
        for (int k = 0; k < num_constraints(); ++k) {
            const double weight = projection == Projection::clamp ? std::max(lambda[k], 0.0) : lambda[k];
            for (int i = 0; i < 3; ++i) {
                values[9 * k + 3 * i] = 2.0 * weight;
                values[9 * k + 3 * i + 1] = 2.0 * weight;
                values[9 * k + 3 * i + 2] = -2.0 * weight;
            }
        }
    }

private:
    Eigen::Vector3d edge(ConstVectorRef x, int k) const
    {
        const auto [a, b] = segments_[k];
        return x.segment<3>(3 * b) - x.segment<3>(3 * a);
    }
    std::vector<std::pair<int, int>> segments_;
    std::vector<double> lengths_;
    SparsityPattern jacobian_, hessian_;
};

/// A 2 × 2 × 4 bar of Neo-Hookean tets hanging from its bottom face is
/// stretched by its top face; two segments along its side must keep 0.9 of
/// their rest length.
struct ConstrainedBar {
    Mesh mesh = box_of_tets(2, 2, 4, 0.25);
    std::shared_ptr<TotalPotential> potential = std::make_shared<TotalPotential>(std::vector<std::shared_ptr<Potential>>{
        std::make_shared<ElasticPotential>(mesh, std::vector<ElementModel>{make_element_model(mesh.kind, "stable-neo-hookean", {})})});
    std::vector<DirichletSet> dirichlet() const
    {
        std::vector<int> bottom, top;
        for (int j = 0; j <= 2; ++j)
            for (int i = 0; i <= 2; ++i) {
                bottom.push_back(grid_node(i, j, 0, 2, 2));
                top.push_back(grid_node(i, j, 4, 2, 2));
            }
        DirichletSet pulled{"top", top, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, 0.2)};
        return {fixed_at_rest("bottom", bottom, 3), pulled};
    }
    QuasistaticOptions options(DirichletStrategy strategy) const
    {
        QuasistaticOptions o;
        o.dirichlet = strategy;
        const int a = grid_node(0, 0, 1, 2, 2), b = grid_node(0, 0, 2, 2, 2), c = grid_node(0, 0, 3, 2, 2);
        o.constraints = {std::make_shared<SegmentLengths>(std::vector<std::pair<int, int>>{{a, b}, {b, c}},
                                                          std::vector<double>{0.9 * 0.25, 0.9 * 0.25})};
        return o;
    }
};

} // namespace

TEST_CASE("PrescribedCoordinates: c = x_i - target with unit Jacobian rows", "[constraint-sets]")
{
    PrescribedCoordinates set({1, 4}, Eigen::Vector2d(0.5, -2.0));
    Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(6, 0.0, 5.0);
    Eigen::VectorXd c(2), j(2);
    set.values(x, c);
    set.jacobian_values(x, j);
    CHECK(c[0] == 0.5);
    CHECK(c[1] == 6.0);
    CHECK(j == Eigen::Vector2d::Ones());
    CHECK(set.jacobian_pattern().cols == std::vector<int>{1, 4});
    CHECK(set.hessian_pattern().nonzeros() == 0);
}

TEST_CASE("a nonlinear constraint set in the quasistatic NLP passes the derivative checks for both Dirichlet "
          "strategies",
          "[constraint-sets]")
{
    ConstrainedBar bar;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    for (DirichletStrategy strategy : {DirichletStrategy::eliminate, DirichletStrategy::equality_constraints}) {
        CAPTURE(to_string(strategy));
        QuasistaticProblem nlp(bar.mesh.nodes, bar.potential, bar.dirichlet(), bar.options(strategy));
        CHECK(nlp.num_constraints() == 2 + (strategy == DirichletStrategy::eliminate ? 0 : nlp.num_prescribed_coordinates()));
        Eigen::VectorXd x = nlp.starting_point();
        for (int i = 0; i < x.size(); ++i)
            x[i] += 0.02 * u11(rng);
        const DerivativeCheckReport entrywise = check_derivatives(nlp, x);
        CAPTURE(entrywise.to_text());
        CHECK(entrywise.passed(1e-5));
        CHECK(entrywise.jacobian.entries_compared > 0);
        const TaylorReport taylor = taylor_test(nlp, x);
        CAPTURE(taylor.to_text());
        CHECK(taylor.passed());
    }
}

TEST_CASE("the projected Hessian of the quasistatic NLP projects constraint curvature too", "[constraint-sets]")
{
    ConstrainedBar bar;
    QuasistaticProblem nlp(bar.mesh.nodes, bar.potential, bar.dirichlet(), bar.options(DirichletStrategy::eliminate));
    const int n = nlp.num_variables();
    const Eigen::VectorXd x = nlp.starting_point();
    const Eigen::Vector2d lambda(-50.0, -50.0);  // negative: λ∇²c is negative semidefinite
    Eigen::VectorXd values(nlp.hessian_pattern().nonzeros());
    nlp.hessian(x, 1.0, lambda, Projection::clamp, values);
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
    for (int k = 0; k < values.size(); ++k) {
        H(nlp.hessian_pattern().rows[k], nlp.hessian_pattern().cols[k]) += values[k];
        if (nlp.hessian_pattern().rows[k] != nlp.hessian_pattern().cols[k])
            H(nlp.hessian_pattern().cols[k], nlp.hessian_pattern().rows[k]) += values[k];
    }
    const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H).eigenvalues().minCoeff();
    CHECK(smallest >= -1e-8 * H.cwiseAbs().maxCoeff());
}

TEST_CASE("kkt-newton and augmented-lagrangian solve the bar with its segment constraints, and agree with Ipopt",
          "[constraint-sets]")
{
    ConstrainedBar bar;
    SolverOptions options;
    options.constraint_tolerance = 1e-9;
    std::vector<Eigen::VectorXd> solutions;
    for (const std::string solver : {"ipopt", "kkt-newton", "augmented-lagrangian"}) {
        QuasistaticProblem nlp(bar.mesh.nodes, bar.potential, bar.dirichlet(), bar.options(DirichletStrategy::eliminate));
        const Result r = solve(nlp, solver, options);
        CAPTURE(solver, r.message, r.constraint_violation);
        CHECK(r.status == Status::converged);
        CHECK(r.constraint_violation <= 1e-9);
        solutions.push_back(nlp.full_configuration(r.x));
    }
    CHECK((solutions[1] - solutions[0]).cwiseAbs().maxCoeff() <= 1e-6);
    CHECK((solutions[2] - solutions[0]).cwiseAbs().maxCoeff() <= 1e-6);
}
