// The near null space a quasistatic problem hands to an algebraic multigrid
// (problems/quasistatic/rigid_body_modes.hpp): the rigid-body modes of the
// nodes at the current configuration, which the elastic Hessian at a rigidly
// moved rest state annihilates.
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/problems/quasistatic/rigid_body_modes.hpp"

#include "potentials/test_meshes.hpp"

#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <catch2/catch.hpp>

#include <vector>

using namespace sinew;
using namespace sinew::test;

namespace {

/// The whole symmetric Hessian of the Lagrangian (σ = 1, λ = 0, no projection) at x.
Eigen::SparseMatrix<double> full_hessian(QuasistaticProblem& nlp, const Eigen::VectorXd& x)
{
    const SparsityPattern& pattern = nlp.hessian_pattern();
    Eigen::VectorXd values(pattern.nonzeros());
    nlp.hessian(x, 1.0, Eigen::VectorXd::Zero(nlp.num_constraints()), Projection::none, values);
    std::vector<Eigen::Triplet<double>> entries;
    for (int k = 0; k < pattern.nonzeros(); ++k) {
        entries.emplace_back(pattern.rows[k], pattern.cols[k], values[k]);
        if (pattern.rows[k] != pattern.cols[k])
            entries.emplace_back(pattern.cols[k], pattern.rows[k], values[k]);
    }
    Eigen::SparseMatrix<double> H(nlp.num_variables(), nlp.num_variables());
    H.setFromTriplets(entries.begin(), entries.end());
    return H;
}

struct ElasticBar {
    Mesh mesh = box_of_tets(2, 2, 3, 0.5);
    std::shared_ptr<TotalPotential> potential = std::make_shared<TotalPotential>(
        std::vector<std::shared_ptr<Potential>>{std::make_shared<ElasticPotential>(
            mesh, std::vector<ElementModel>{make_element_model(mesh.kind, "stable-neo-hookean", {})})});
    std::vector<DirichletSet> bottom() const { return {fixed_at_rest("bottom", {0, 1, 2}, 3)}; }
};

/// Every node moved by x = R X + t.
Eigen::VectorXd rigidly_moved(const Mesh& mesh, const Eigen::Matrix3d& R, const Eigen::Vector3d& t)
{
    Eigen::VectorXd configuration(3 * mesh.num_nodes());
    for (int node = 0; node < mesh.num_nodes(); ++node)
        configuration.segment<3>(3 * node) = R * mesh.nodes.col(node) + t;
    return configuration;
}

} // namespace

TEST_CASE("rigid-body modes: orthonormal, and annihilated by the elastic Hessian at a rigidly moved rest state",
          "[quasistatic][amg]")
{
    ElasticBar bar;
    QuasistaticOptions options;
    options.dirichlet = DirichletStrategy::equality_constraints;  // every coordinate a variable
    QuasistaticProblem nlp(bar.mesh.nodes, bar.potential, bar.bottom(), options);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const Eigen::VectorXd x = rigidly_moved(bar.mesh, R, Eigen::Vector3d(0.3, -1.0, 2.0));

    const NearNullSpace modes = nlp.near_null_space(x);
    REQUIRE(modes.vectors.rows() == nlp.num_variables());
    REQUIRE(modes.vectors.cols() == 6);
    CHECK(modes.block_size == 3);
    CHECK((modes.vectors.transpose() * modes.vectors - Eigen::MatrixXd::Identity(6, 6)).cwiseAbs().maxCoeff() <
          1e-12);

    const Eigen::SparseMatrix<double> H = full_hessian(nlp, x);
    const double scale = H.coeffs().cwiseAbs().maxCoeff();
    const double residual = (H * modes.vectors).cwiseAbs().maxCoeff();
    CAPTURE(scale, residual);
    CHECK(residual <= 1e-10 * scale);

    // The modes follow the configuration: those of the rest state are not
    // annihilated once the body is turned (their rotations have other axes).
    const Eigen::MatrixXd rest_modes = nlp.near_null_space(nlp.variables_of(rigidly_moved(
        bar.mesh, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()))).vectors;
    CHECK((H * rest_modes).cwiseAbs().maxCoeff() > 1e-3 * scale);
}

TEST_CASE("rigid-body modes: restricted to the free coordinates under elimination", "[quasistatic][amg]")
{
    ElasticBar bar;
    QuasistaticProblem nlp(bar.mesh.nodes, bar.potential, bar.bottom());
    const NearNullSpace modes = nlp.near_null_space(nlp.starting_point());
    REQUIRE(modes.vectors.rows() == nlp.num_variables());
    REQUIRE(modes.vectors.cols() == 6);
    CHECK((modes.vectors.transpose() * modes.vectors - Eigen::MatrixXd::Identity(6, 6)).cwiseAbs().maxCoeff() <
          1e-12);
    // Each is a rigid motion of the free nodes: the translation along x moves
    // every free node's x coordinate alike, so the x-rows of some unit
    // combination are constant. Check that span by projecting e_x's restriction.
    Eigen::VectorXd translation_x = Eigen::VectorXd::Zero(nlp.num_variables());
    for (int row = 0; row < nlp.num_variables(); row += 3)
        translation_x[row] = 1.0;
    const Eigen::VectorXd projected = modes.vectors * (modes.vectors.transpose() * translation_x);
    CHECK((projected - translation_x).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("rigid-body modes in 2D: two translations and the rotation in the plane", "[quasistatic][amg]")
{
    // Nodes (0,0), (1,0), (0,1), (2,3): the rotation about the centroid is (−y, x) relative to it.
    Eigen::VectorXd positions(8);
    positions << 0, 0, 1, 0, 0, 1, 2, 3;
    const NearNullSpace modes = rigid_body_modes(positions, 2, {0, 1, 2, 3, 4, 5, 6, 7});
    REQUIRE(modes.vectors.cols() == 3);
    CHECK(modes.block_size == 2);
    const Eigen::Vector2d centroid(0.75, 1.0);
    Eigen::VectorXd rotation(8);
    for (int node = 0; node < 4; ++node) {
        const Eigen::Vector2d r = positions.segment<2>(2 * node) - centroid;
        rotation.segment<2>(2 * node) = Eigen::Vector2d(-r.y(), r.x());
    }
    const Eigen::VectorXd projected = modes.vectors * (modes.vectors.transpose() * rotation);
    CHECK((projected - rotation).cwiseAbs().maxCoeff() < 1e-12);
}
