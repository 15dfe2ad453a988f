#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"
#include "sinew/energies/potentials/total_potential.hpp"

#include "energies/deformation_regimes.hpp"
#include "potentials/potential_checks.hpp"
#include "potentials/test_meshes.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

/// x = A ξ + noise of amplitude `noise` (material coordinates ξ = Q X).
template <int Rows, int Cols>
Eigen::VectorXd perturbed(const Mesh& mesh, const Eigen::Matrix<double, Rows, Cols>& A,
                          const Eigen::Matrix<double, Cols, Rows>& Q, double noise, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    Eigen::VectorXd x(Rows * mesh.num_nodes());
    for (int i = 0; i < mesh.num_nodes(); ++i) {
        const Eigen::Matrix<double, Rows, 1> X = mesh.nodes.col(i);
        x.segment<Rows>(Rows * i) = A * (Q * X);
        for (int k = 0; k < Rows; ++k)
            x[Rows * i + k] += noise * u11(rng);
    }
    return x;
}

/// Over configurations in the compressed and near-inversion regimes: the
/// projected Hessian is PSD (smallest eigenvalue ≥ −1e-8·max|H|) every time,
/// and the exact one is indefinite at least once (so the check means
/// something).
template <int Rows, int Cols>
void check_projection(TotalPotential& E, const Mesh& mesh, const Eigen::Matrix<double, Cols, Rows>& Q,
                      std::mt19937& rng)
{
    bool saw_indefinite = false;
    for (Regime regime : {Regime::compression, Regime::near_inversion, Regime::moderate}) {
        for (int sample = 0; sample < 3; ++sample) {
            CAPTURE(regime_name(regime), sample);
            const Eigen::VectorXd x = perturbed<Rows, Cols>(mesh, random_deformation<Rows, Cols>(regime, rng), Q, 0.01, rng);
            REQUIRE(std::isfinite(E.value(x)));
            const Eigen::MatrixXd projected = dense_hessian(E, x, Projection::clamp);
            const double scale = projected.cwiseAbs().maxCoeff();
            REQUIRE(scale > 0.0);
            CHECK(smallest_eigenvalue(projected) >= -1e-8 * scale);
            const Eigen::MatrixXd exact = dense_hessian(E, x, Projection::none);
            saw_indefinite = saw_indefinite || smallest_eigenvalue(exact) < -1e-6 * exact.cwiseAbs().maxCoeff();
        }
    }
    CHECK(saw_indefinite);
}

} // namespace

TEST_CASE("projected Hessian is PSD, tets", "[potentials][projection]")
{
    std::mt19937 rng(31);
    for (const std::string name : {"stable-neo-hookean", "fixed-corotated", "mooney-rivlin-muscle", "qr-anisotropic"}) {
        CAPTURE(name);
        const Mesh mesh = box_of_tets(2, 2, 2, 0.5);
        auto elastic = std::make_shared<ElasticPotential>(
            mesh, std::vector<ElementModel>{make_element_model(mesh.kind, name, {})});
        for (int e = 0; e < mesh.num_elements(); ++e) {
            elastic->set_fiber(e, random_unit_vector<3>(rng));
            elastic->set_activation(e, 0.7);
        }
        // A ball pressed into the block adds the penalty's indefinite part.
        auto ball = std::make_shared<ObstaclePenaltyPotential>(
            3, mesh.num_nodes(), SphereObstacle{Eigen::Vector3d(0.5, 0.5, 1.2), 0.5}, 1e4);
        TotalPotential E({elastic, ball});
        check_projection<3, 3>(E, mesh, Eigen::Matrix3d::Identity(), rng);
    }
}

TEST_CASE("projected Hessian is PSD, triangles in 2D and in 3D", "[potentials][projection]")
{
    std::mt19937 rng(32);
    {
        const Mesh mesh = rectangle_of_triangles(3, 3, 0.5);
        auto elastic = std::make_shared<ElasticPotential>(
            mesh, std::vector<ElementModel>{make_element_model(mesh.kind, "qr-anisotropic", {})});
        for (int e = 0; e < mesh.num_elements(); ++e)
            elastic->set_fiber(e, random_unit_vector<2>(rng));
        TotalPotential E({elastic});
        check_projection<2, 2>(E, mesh, Eigen::Matrix2d::Identity(), rng);
    }
    {
        const Eigen::Matrix3d R = random_rotation<3>(rng);
        const Mesh mesh = sheet_of_triangles(3, 3, 0.5, R);
        auto elastic = std::make_shared<ElasticPotential>(
            mesh, std::vector<ElementModel>{make_element_model(mesh.kind, "codim-corotated", {})});
        TotalPotential E({elastic});
        check_projection<3, 2>(E, mesh, Eigen::Matrix<double, 2, 3>(R.transpose().topRows<2>()), rng);
    }
}
