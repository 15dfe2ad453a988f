// DESIGN.md: the same input gives bitwise-identical value, gradient and
// Hessian for any thread count.
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/gravity_potential.hpp"
#include "sinew/energies/potentials/lumped_mass.hpp"
#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"
#include "sinew/energies/potentials/total_potential.hpp"

#include "energies/deformation_regimes.hpp"
#include "potentials/test_meshes.hpp"

#include <catch2/catch.hpp>
#include <omp.h>

#include <cstring>
#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

struct Evaluation {
    double value = 0.0;
    Eigen::VectorXd gradient;
    Eigen::VectorXd hessian;
    Eigen::VectorXd projected_hessian;
};

Evaluation evaluate_with_threads(TotalPotential& E, const Eigen::VectorXd& x, int threads)
{
    omp_set_num_threads(threads);
    REQUIRE(omp_get_max_threads() == threads);
    Evaluation out;
    out.value = E.value(x);
    out.gradient.resize(x.size());
    E.gradient(x, out.gradient);
    out.hessian.resize(E.hessian_pattern().nonzeros());
    E.hessian_values(x, Projection::none, out.hessian);
    out.projected_hessian.resize(E.hessian_pattern().nonzeros());
    E.hessian_values(x, Projection::clamp, out.projected_hessian);
    return out;
}

bool bitwise_equal(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), static_cast<std::size_t>(a.size()) * sizeof(double)) == 0;
}

} // namespace

TEST_CASE("assembly is bitwise identical with 1 and 2 threads", "[potentials][determinism]")
{
    std::mt19937 rng(41);
    const Mesh mesh = box_of_tets(12, 3, 3, 0.25);
    auto elastic = std::make_shared<ElasticPotential>(
        mesh, std::vector<ElementModel>{make_element_model(mesh.kind, "mooney-rivlin-muscle", {})});
    for (int e = 0; e < mesh.num_elements(); ++e) {
        elastic->set_fiber(e, random_unit_vector<3>(rng));
        elastic->set_activation(e, 0.5);
    }
    auto gravity = std::make_shared<GravityPotential>(3, lumped_masses(mesh, {1000.0}), Eigen::Vector3d(0, 0, -9.81));
    auto floor = std::make_shared<ObstaclePenaltyPotential>(3, mesh.num_nodes(),
                                                            PlaneObstacle{Eigen::Vector3d(0, 0, 1), 0.05}, 1e5);
    TotalPotential E({elastic, gravity, floor});
    // Several blocks per color, so that two threads really share the work.
    REQUIRE(elastic->num_blocks() >= 2 * elastic->num_colors());

    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    const Eigen::Matrix3d A = random_deformation<3, 3>(Regime::compression, rng);
    Eigen::VectorXd x(3 * mesh.num_nodes());
    for (int i = 0; i < mesh.num_nodes(); ++i)
        x.segment<3>(3 * i) = A * mesh.nodes.col(i) + 0.01 * Eigen::Vector3d(u11(rng), u11(rng), u11(rng));

    const int threads_before = omp_get_max_threads();
    const Evaluation one = evaluate_with_threads(E, x, 1);
    const Evaluation two = evaluate_with_threads(E, x, 2);
    omp_set_num_threads(threads_before);

    REQUIRE(std::isfinite(one.value));
    CHECK(std::memcmp(&one.value, &two.value, sizeof(double)) == 0);
    CHECK(bitwise_equal(one.gradient, two.gradient));
    CHECK(bitwise_equal(one.hessian, two.hessian));
    CHECK(bitwise_equal(one.projected_hessian, two.projected_hessian));
}
