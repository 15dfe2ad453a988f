// The patch test: boundary nodes placed by a homogeneous deformation
// x = F̄ X + t; the equilibrium of any homogeneous material puts every interior
// node at F̄ X + t too (constant F, constant P: the element forces on an
// interior node cancel).
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/solvers/solver.hpp"

#include "energies/deformation_regimes.hpp"
#include "potentials/test_meshes.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

constexpr int kCells = 4;
constexpr double kH = 0.25;  // mesh size

/// Solves with Ipopt from the rest state of the interior nodes and returns the
/// largest distance of a node from M X + t.
double patch_error(const Mesh& mesh, const std::shared_ptr<ElasticPotential>& elastic, const Eigen::MatrixXd& M,
                   const Eigen::VectorXd& t, const std::vector<int>& boundary, DirichletStrategy strategy)
{
    auto potential = std::make_shared<TotalPotential>(std::vector<std::shared_ptr<Potential>>{elastic});
    QuasistaticOptions options;
    options.dirichlet = strategy;
    QuasistaticProblem nlp(mesh.nodes, potential, {DirichletSet{"boundary", boundary, M, t}}, options);
    SolverOptions solver_options;
    solver_options.tolerance = 1e-12;
    const Result result = solve(nlp, "ipopt", solver_options);
    CAPTURE(result.message, result.iterations, result.kkt_residual);
    REQUIRE(result.status == Status::converged);
    const Eigen::VectorXd x = nlp.full_configuration(result.x);
    const int d = static_cast<int>(mesh.nodes.rows());
    double error = 0.0;
    for (int node = 0; node < mesh.num_nodes(); ++node)
        error = std::max(error, (x.segment(d * node, d) - (M * mesh.nodes.col(node) + t)).cwiseAbs().maxCoeff());
    return error;
}

std::shared_ptr<ElasticPotential> uniform_material(const Mesh& mesh, const std::string& model,
                                                   const ParameterValues& parameters, const Eigen::VectorXd& fiber,
                                                   double activation)
{
    auto elastic = std::make_shared<ElasticPotential>(
        mesh, std::vector<ElementModel>{make_element_model(mesh.kind, model, parameters)});
    for (int e = 0; e < mesh.num_elements(); ++e) {
        elastic->set_fiber(e, fiber);
        elastic->set_activation(e, activation);
    }
    return elastic;
}

} // namespace

TEST_CASE("patch test on tets: interior nodes at F̄X + t for every 3D model", "[quasistatic][patch]")
{
    const Mesh mesh = box_of_tets(kCells, kCells, kCells, kH);
    const std::vector<int> boundary = lattice_boundary_nodes(kCells, kCells, kCells);
    Eigen::Matrix3d F;
    F << 1.10, 0.05, -0.03, 0.02, 0.95, 0.04, -0.05, 0.03, 1.05;
    const Eigen::Vector3d t(0.1, -0.2, 0.05);
    const Eigen::Vector3d fiber = Eigen::Vector3d(1.0, 0.5, 0.2).normalized();
    const std::vector<std::pair<std::string, ParameterValues>> models{
        {"stable-neo-hookean", {}},
        {"fixed-corotated", {}},
        {"mooney-rivlin-muscle", {}},
        {"qr-anisotropic", {{"ky", 2e4}}},
    };
    for (const auto& [name, parameters] : models) {
        for (DirichletStrategy strategy : {DirichletStrategy::eliminate, DirichletStrategy::equality_constraints}) {
            CAPTURE(name, to_string(strategy));
            auto elastic = uniform_material(mesh, name, parameters, fiber, 0.3);
            CHECK(patch_error(mesh, elastic, F, t, boundary, strategy) <= 1e-8 * kH);
        }
    }
}

TEST_CASE("patch test on 2D triangles: qr-anisotropic", "[quasistatic][patch]")
{
    const Mesh mesh = rectangle_of_triangles(kCells, kCells, kH);
    Eigen::Matrix2d F;
    F << 1.08, 0.04, -0.03, 0.96;
    auto elastic = uniform_material(mesh, "qr-anisotropic", {}, Eigen::Vector2d(0.8, 0.6), 0.0);
    CHECK(patch_error(mesh, elastic, F, Eigen::Vector2d(-0.1, 0.3), lattice_boundary_nodes(kCells, kCells, 0),
                      DirichletStrategy::eliminate) <= 1e-8 * kH);
}

TEST_CASE("patch test on a tilted sheet of triangles in 3D: codim-corotated, in-plane F̄", "[quasistatic][patch]")
{
    std::mt19937 rng(71);
    const Eigen::Matrix3d R = random_rotation<3>(rng);
    const Mesh mesh = sheet_of_triangles(kCells, kCells, kH, R);
    // An in-plane stretch (both principal stretches > 1: the sheet is taut) in
    // the sheet's own coordinates, mapped to space: M = R diag(F̄, 1) Rᵀ.
    Eigen::Matrix3d F_sheet = Eigen::Matrix3d::Identity();
    F_sheet.topLeftCorner<2, 2>() << 1.10, 0.03, 0.02, 1.06;
    const Eigen::Matrix3d M = R * F_sheet * R.transpose();
    auto elastic = uniform_material(mesh, "codim-corotated", {}, Eigen::Vector2d(1.0, 0.0), 0.0);
    CHECK(patch_error(mesh, elastic, M, R * Eigen::Vector3d(0.05, -0.02, 0.0), lattice_boundary_nodes(kCells, kCells, 0),
                      DirichletStrategy::eliminate) <= 1e-8 * kH);
}
