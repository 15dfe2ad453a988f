#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/element_rest_shape.hpp"
#include "sinew/energies/potentials/total_potential.hpp"

#include "energies/deformation_regimes.hpp"
#include "potentials/potential_checks.hpp"
#include "potentials/test_meshes.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

/// A model from the catalog for one group, and a stiffer variant of it for a
/// second group, so that every test mesh has two groups.
struct GroupModels {
    std::string name;
    ParameterValues soft;
    ParameterValues stiff;
};

std::vector<GroupModels> solid_models()
{
    return {
        {"stable-neo-hookean", {{"mu", 1e4}, {"lambda", 5e4}}, {{"mu", 3e4}, {"lambda", 1e5}}},
        {"fixed-corotated", {{"mu", 1e4}, {"lambda", 5e4}}, {{"mu", 3e4}, {"lambda", 1e5}}},
        {"mooney-rivlin-muscle", {}, {{"A", 400.0}, {"B", 100.0}, {"K", 1e5}}},
        {"qr-anisotropic", {}, {{"mu", 2e4}, {"lambda", 2e5}, {"kx", 5e4}, {"ky", 1e4}}},
    };
}

std::shared_ptr<ElasticPotential> make_elastic(Mesh mesh, const GroupModels& models)
{
    alternate_groups(mesh, "soft", "stiff");
    return std::make_shared<ElasticPotential>(
        mesh, std::vector<ElementModel>{make_element_model(mesh.kind, models.name, models.soft),
                                        make_element_model(mesh.kind, models.name, models.stiff)});
}

/// Random unit fibers, activations in [0, 1] and damage in [0, 0.5].
void randomize_material_points(ElasticPotential& elastic, int material_dimension, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::normal_distribution<double> normal;
    for (int e = 0; e < elastic.num_elements(); ++e) {
        Eigen::VectorXd fiber(material_dimension);
        for (int i = 0; i < material_dimension; ++i)
            fiber[i] = normal(rng);
        elastic.set_fiber(e, fiber);
        elastic.set_activation(e, u01(rng));
        elastic.set_damage(e, 0.5 * u01(rng));
    }
}

/// x_i = A ξ_i + noise, ξ_i = Q X_i the material coordinates of node i, the
/// noise uniform with amplitude 0.05·h·σ_min(A), small enough that no element
/// inverts, even near inversion.
template <int Rows, int Cols>
Eigen::VectorXd deformed(const Mesh& mesh, const Eigen::Matrix<double, Rows, Cols>& A,
                         const Eigen::Matrix<double, Cols, Rows>& Q, double h, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    const Eigen::Matrix<double, Cols, Cols> C = A.transpose() * A;
    const double sigma_min = std::sqrt(std::max(
        0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, Cols, Cols>>(C, Eigen::EigenvaluesOnly).eigenvalues()[0]));
    Eigen::VectorXd x(Rows * mesh.num_nodes());
    for (int i = 0; i < mesh.num_nodes(); ++i) {
        const Eigen::Matrix<double, Rows, 1> X = mesh.nodes.col(i);
        x.segment<Rows>(Rows * i) = A * (Q * X);
        for (int k = 0; k < Rows; ++k)
            x[Rows * i + k] += 0.05 * h * sigma_min * u11(rng);
    }
    return x;
}

void require_accurate(const DerivativeErrors& errors)
{
    CAPTURE(errors.gradient, errors.hessian, errors.gradient_scale, errors.hessian_scale);
    REQUIRE(errors.gradient_scale > 0.0);
    REQUIRE(errors.hessian_scale > 0.0);
    CHECK(errors.gradient < 1e-7);
    CHECK(errors.hessian < 1e-7);
}

constexpr double kH = 0.5;  // element size of the test meshes

} // namespace

TEST_CASE("elastic potential on tets: gradient and Hessian match central differences", "[potentials][elastic]")
{
    std::mt19937 rng(11);
    for (const GroupModels& models : solid_models()) {
        auto elastic = make_elastic(box_of_tets(2, 2, 2, kH), models);
        randomize_material_points(*elastic, 3, rng);
        TotalPotential E({elastic});
        const Mesh mesh = box_of_tets(2, 2, 2, kH);
        for (Regime regime : all_regimes()) {
            CAPTURE(models.name, regime_name(regime));
            const Eigen::VectorXd x = deformed<3, 3>(mesh, random_deformation<3, 3>(regime, rng),
                                                     Eigen::Matrix3d::Identity(), kH, rng);
            REQUIRE(std::isfinite(E.value(x)));
            require_accurate(derivative_errors(E, x));
        }
    }
}

TEST_CASE("elastic potential on 2D triangles: gradient and Hessian match central differences",
          "[potentials][elastic]")
{
    std::mt19937 rng(12);
    const GroupModels models{"qr-anisotropic", {}, {{"mu", 2e4}, {"lambda", 2e5}, {"kx", 5e4}}};
    const Mesh mesh = rectangle_of_triangles(3, 3, kH);
    auto elastic = make_elastic(mesh, models);
    randomize_material_points(*elastic, 2, rng);
    TotalPotential E({elastic});
    for (Regime regime : all_regimes()) {
        CAPTURE(regime_name(regime));
        const Eigen::VectorXd x =
            deformed<2, 2>(mesh, random_deformation<2, 2>(regime, rng), Eigen::Matrix2d::Identity(), kH, rng);
        REQUIRE(std::isfinite(E.value(x)));
        require_accurate(derivative_errors(E, x));
    }
}

TEST_CASE("elastic potential on triangles in 3D: gradient and Hessian match central differences",
          "[potentials][elastic]")
{
    std::mt19937 rng(13);
    const Eigen::Matrix3d R = random_rotation<3>(rng);
    const Mesh mesh = sheet_of_triangles(3, 3, kH, R);
    const GroupModels models{"codim-corotated", {}, {{"mu", 30.0}, {"lambda", 5.0}}};
    auto elastic = make_elastic(mesh, models);
    TotalPotential E({elastic});
    const Eigen::Matrix<double, 2, 3> Q = R.transpose().topRows<2>();
    for (Regime regime : all_regimes()) {
        CAPTURE(regime_name(regime));
        const Eigen::VectorXd x = deformed<3, 2>(mesh, random_deformation<3, 2>(regime, rng), Q, kH, rng);
        REQUIRE(std::isfinite(E.value(x)));
        require_accurate(derivative_errors(E, x));
    }
}

namespace {

/// E at x = A ξ over a mesh of total rest measure W: every element has F = A
/// (up to an orthogonal change of its material frame, to which the isotropic
/// membrane model is blind), so E = W ψ(A). Rigid motions cost nothing.
template <int Rows, int Cols>
void check_homogeneous(const Mesh& mesh, const std::string& model_name, double measure,
                       const Eigen::Matrix<double, Cols, Rows>& Q, std::mt19937& rng)
{
    CAPTURE(model_name);
    const ElementModel model = make_element_model(mesh.kind, model_name, {});
    auto elastic = std::make_shared<ElasticPotential>(mesh, std::vector<ElementModel>{model});
    TotalPotential E({elastic});
    const auto& pointwise = *std::get<std::shared_ptr<const ConstitutiveModel<Rows, Cols>>>(model);
    for (Regime regime : {Regime::moderate, Regime::large_stretch, Regime::compression}) {
        const Eigen::Matrix<double, Rows, Cols> A = random_deformation<Rows, Cols>(regime, rng);
        const Eigen::VectorXd x = deformed<Rows, Cols>(mesh, A, Q, 0.0, rng);
        CHECK(E.value(x) == Approx(measure * pointwise.energy(A, MaterialPoint<Cols>{})).epsilon(1e-12));
    }
    const Eigen::VectorXd X = rest_coordinates(mesh);
    CHECK(E.value(X) == Approx(0.0).margin(1e-9));
    CHECK(gradient_of(E, X).cwiseAbs().maxCoeff() < 1e-9);
    const Eigen::Matrix<double, Rows, Rows> R = random_rotation<Rows>(rng);
    Eigen::VectorXd moved = X;
    for (int i = 0; i < mesh.num_nodes(); ++i)
        moved.segment<Rows>(Rows * i) = R * X.segment<Rows>(Rows * i) + Eigen::Matrix<double, Rows, 1>::Constant(0.7);
    CHECK(E.value(moved) == Approx(0.0).margin(1e-8));
}

} // namespace

TEST_CASE("elastic potential: E = Σ W_e ψ(F_e) with F = Ds·Dm⁻¹, zero for rigid motions, every element kind",
          "[potentials][elastic]")
{
    std::mt19937 rng(14);
    check_homogeneous<3, 3>(box_of_tets(2, 1, 1, kH), "stable-neo-hookean", 2 * kH * kH * kH,
                            Eigen::Matrix3d::Identity(), rng);
    check_homogeneous<2, 2>(rectangle_of_triangles(2, 3, kH), "qr-anisotropic", 6 * kH * kH,
                            Eigen::Matrix2d::Identity(), rng);
    const Eigen::Matrix3d R = random_rotation<3>(rng);
    check_homogeneous<3, 2>(sheet_of_triangles(2, 3, kH, R), "codim-corotated", 6 * kH * kH,
                            Eigen::Matrix<double, 2, 3>(R.transpose().topRows<2>()), rng);
}

TEST_CASE("elastic potential: membrane fibers given in space are stored in each element's rest frame",
          "[potentials][elastic]")
{
    std::mt19937 rng(15);
    const Eigen::Matrix3d R = random_rotation<3>(rng);
    Mesh mesh = sheet_of_triangles(2, 2, kH, R);
    // A direction with an out-of-plane part: only its in-plane part counts.
    const Eigen::Vector3d in_plane = R * Eigen::Vector3d(0.6, 0.8, 0.0);
    const Eigen::Vector3d spatial = in_plane + 0.5 * R.col(2);
    mesh.element_fibers = spatial.replicate(1, mesh.num_elements());
    ElasticPotential elastic(mesh, {make_element_model(mesh.kind, "codim-corotated", {})});
    for (int e = 0; e < mesh.num_elements(); ++e) {
        const Eigen::Matrix<double, 3, 2> frame = membrane_rest_frame(
            mesh.nodes.col(mesh.elements(0, e)), mesh.nodes.col(mesh.elements(1, e)), mesh.nodes.col(mesh.elements(2, e)));
        CHECK((frame * elastic.fiber(e) - in_plane).norm() < 1e-14);
    }
    CHECK_THROWS_AS(elastic.set_fiber(0, R.col(2)), InputError);
}

TEST_CASE("elastic potential: the activation gradient of a muscle is the alpha-difference of the gradient",
          "[potentials][elastic][activation]")
{
    // ∂(∇E)/∂α for one α shared by a set of elements (seed 000 eq. 4), against
    // central differences of ∇E with that α moved on those elements alone;
    // every regime, both fiber stretches. Elements outside the set keep theirs.
    std::mt19937 rng(23);
    int active_regimes = 0;
    for (const double stretch : {0.0, 1.0}) {  // fiber_stretch: physbam, deviatoric
        const Mesh mesh = box_of_tets(2, 2, 2, kH);
        const GroupModels models{"mooney-rivlin-muscle",
                                 {{"fiber_stretch", stretch}},
                                 {{"A", 400.0}, {"B", 100.0}, {"K", 1e5}, {"fiber_stretch", stretch}}};
        auto elastic = make_elastic(mesh, models);
        randomize_material_points(*elastic, 3, rng);
        std::vector<int> muscle;
        for (int e = 0; e < elastic->num_elements(); e += 3)
            muscle.push_back(e);
        TotalPotential E({elastic});
        for (Regime regime : all_regimes()) {
            CAPTURE(stretch, regime_name(regime));
            const Eigen::VectorXd x =
                deformed<3, 3>(mesh, random_deformation<3, 3>(regime, rng), Eigen::Matrix3d::Identity(), kH, rng);
            const double alpha = 0.5;
            for (const int e : muscle)
                elastic->set_activation(e, alpha);
            Eigen::VectorXd analytic = Eigen::VectorXd::Zero(x.size());
            elastic->add_activation_gradient(x, muscle, analytic);
            const double h = 0.25;  // ∇E is linear in α: the difference is exact but for rounding
            Eigen::VectorXd g_plus, g_minus;
            for (const int e : muscle)
                elastic->set_activation(e, alpha + h);
            g_plus = gradient_of(E, x);
            for (const int e : muscle)
                elastic->set_activation(e, alpha - h);
            g_minus = gradient_of(E, x);
            const Eigen::VectorXd differences = (g_plus - g_minus) / (2 * h);
            // Fibers stretched beyond 1.6 λ_opt exert no active force (the curve is 0 there).
            const double size = std::max(differences.cwiseAbs().maxCoeff(), 1e-12 * g_plus.cwiseAbs().maxCoeff());
            CHECK((analytic - differences).cwiseAbs().maxCoeff() <= 1e-8 * size);
            active_regimes += differences.cwiseAbs().maxCoeff() > 0.0;
        }
    }
    CHECK(active_regimes >= 8);
    const Mesh mesh = box_of_tets(1, 1, 1, kH);
    auto elastic = make_elastic(mesh, solid_models()[2]);
    Eigen::VectorXd x = rest_coordinates(mesh), g = Eigen::VectorXd::Zero(x.size());
    CHECK_THROWS_AS(elastic->add_activation_gradient(x, {elastic->num_elements()}, g), InputError);
    Eigen::VectorXd short_gradient = Eigen::VectorXd::Zero(3);
    CHECK_THROWS_AS(elastic->add_activation_gradient(x, {0}, short_gradient), InputError);
}
