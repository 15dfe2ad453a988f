#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/gravity_potential.hpp"
#include "sinew/energies/potentials/lumped_mass.hpp"
#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"
#include "sinew/energies/potentials/point_load_potential.hpp"
#include "sinew/energies/potentials/total_potential.hpp"

#include "potentials/test_meshes.hpp"

#include <catch2/catch.hpp>

#include <limits>

using namespace sinew;
using namespace sinew::test;
using Catch::Contains;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

ElementModel tet_model() { return make_element_model(ElementKind::tetrahedron, "stable-neo-hookean", {}); }

} // namespace

TEST_CASE("elastic potential: a model of the wrong F shape for the element kind is refused, naming both shapes",
          "[potentials][input]")
{
    const Mesh tets = box_of_tets(1, 1, 1, 1.0);
    const ElementModel plane = make_element_model(ElementKind::triangle_2d, "qr-anisotropic", {});
    CHECK_THROWS_WITH(ElasticPotential(tets, {plane}),
                      Contains("group 0 ('tissue')") && Contains("2x2") && Contains("tetrahedron elements need 3x3"));
    const Mesh sheet = sheet_of_triangles(1, 1, 1.0, Eigen::Matrix3d::Identity());
    CHECK_THROWS_WITH(ElasticPotential(sheet, {tet_model()}), Contains("3x3") && Contains("need 3x2"));
    // The catalog refuses to build a model for a shape it does not take.
    CHECK_THROWS_AS(make_element_model(ElementKind::triangle_3d, "stable-neo-hookean", {}), InputError);
    CHECK_THROWS_WITH(ElasticPotential(tets, {std::shared_ptr<const Model3d>()}), Contains("has no model"));
}

TEST_CASE("elastic potential: group indices and counts are checked", "[potentials][input]")
{
    Mesh mesh = box_of_tets(1, 1, 1, 1.0);
    mesh.element_groups[3] = 5;
    CHECK_THROWS_WITH(ElasticPotential(mesh, {tet_model()}), Contains("element 3") && Contains("group index 5"));
    mesh.element_groups[3] = -1;
    CHECK_THROWS_WITH(ElasticPotential(mesh, {tet_model()}), Contains("group index -1"));
    mesh.element_groups[3] = 0;
    CHECK_THROWS_WITH(ElasticPotential(mesh, {tet_model(), tet_model()}), Contains("1 element groups but 2 models"));
    mesh.element_groups.pop_back();
    CHECK_THROWS_WITH(ElasticPotential(mesh, {tet_model()}), Contains("5 group indices"));
}

TEST_CASE("elastic potential: inconsistent or degenerate meshes are refused", "[potentials][input]")
{
    Mesh mesh = box_of_tets(1, 1, 1, 1.0);
    mesh.elements(2, 4) = 99;
    CHECK_THROWS_WITH(ElasticPotential(mesh, {tet_model()}), Contains("element 4 names node 99"));
    mesh = box_of_tets(1, 1, 1, 1.0);
    mesh.nodes(1, 2) = kNaN;
    CHECK_THROWS_WITH(ElasticPotential(mesh, {tet_model()}), Contains("non-finite rest coordinate"));
    mesh = box_of_tets(1, 1, 1, 1.0);
    mesh.elements(3, 1) = mesh.elements(2, 1);
    CHECK_THROWS_WITH(ElasticPotential(mesh, {tet_model()}), Contains("element 1 is degenerate"));
    mesh = box_of_tets(1, 1, 1, 1.0);
    mesh.kind = ElementKind::triangle_3d;
    CHECK_THROWS_WITH(ElasticPotential(mesh, {tet_model()}), Contains("triangle_3d elements have 3 nodes"));
}

TEST_CASE("elastic potential: material point data is checked", "[potentials][input]")
{
    Mesh mesh = box_of_tets(1, 1, 1, 1.0);
    ElasticPotential elastic(mesh, {tet_model()});
    CHECK_THROWS_WITH(elastic.set_activation(2, 1.5), Contains("element 2: activation"));
    CHECK_THROWS_WITH(elastic.set_activation(2, kNaN), Contains("activation"));
    CHECK_THROWS_WITH(elastic.set_damage(0, -0.1), Contains("damage"));
    CHECK_THROWS_WITH(elastic.set_activation(6, 0.5), Contains("element 6 is outside [0, 6)"));
    CHECK_THROWS_WITH(elastic.set_fiber(1, Eigen::Vector3d::Zero()), Contains("fiber is zero"));
    CHECK_THROWS_WITH(elastic.set_fiber(1, Eigen::Vector2d(1, 0)), Contains("2 components, expected 3"));
    mesh.element_fibers = Eigen::MatrixXd::Ones(2, mesh.num_elements());
    CHECK_THROWS_WITH(ElasticPotential(mesh, {tet_model()}), Contains("mesh fibers are 2x6"));
}

namespace {

/// A model that refuses every input, as a model does for data it cannot use.
class RefusingModel final : public Model3d {
public:
    std::string name() const override { return "refusing"; }
    double energy(const Deformation&, const Point&) const override { throw InputError("refusing: no"); }
    double evaluate(const Deformation&, const Point&, Stress*, Stiffness*, Projection) const override
    {
        throw InputError("refusing: no");
    }
};

} // namespace

TEST_CASE("elastic potential: a model's exception leaves the parallel loops as an exception",
          "[potentials][input]")
{
    const Mesh mesh = box_of_tets(3, 1, 1, 1.0);
    auto elastic = std::make_shared<ElasticPotential>(
        mesh, std::vector<ElementModel>{std::shared_ptr<const Model3d>(std::make_shared<RefusingModel>())});
    TotalPotential E({elastic});
    const Eigen::VectorXd x = rest_coordinates(mesh);
    Eigen::VectorXd g(x.size()), h(E.hessian_pattern().nonzeros());
    CHECK_THROWS_WITH(E.value(x), Contains("refusing: no"));
    CHECK_THROWS_WITH(E.gradient(x, g), Contains("refusing: no"));
    CHECK_THROWS_WITH(E.hessian_values(x, Projection::clamp, h), Contains("refusing: no"));
}

TEST_CASE("external potentials: bad data is refused, naming it", "[potentials][input]")
{
    const Mesh mesh = box_of_tets(1, 1, 1, 1.0);
    CHECK_THROWS_WITH(lumped_masses(mesh, {-1.0}), Contains("density of group 0"));
    CHECK_THROWS_WITH(lumped_masses(mesh, {1.0, 2.0}), Contains("2 densities given for 1 element groups"));
    CHECK_THROWS_WITH(GravityPotential(3, Eigen::VectorXd::Ones(8), Eigen::Vector2d(0, 1)), Contains("g has 2"));
    CHECK_THROWS_WITH(GravityPotential(3, Eigen::VectorXd::Ones(8), Eigen::Vector3d(0, kNaN, 1)),
                      Contains("not finite"));
    CHECK_THROWS_WITH(PointLoadPotential(3, 8, {8}, Eigen::Vector3d(1, 0, 0)), Contains("node 8, outside [0, 8)"));
    CHECK_THROWS_WITH(PointLoadPotential(3, 8, {1}, Eigen::Vector3d(1, kNaN, 0)), Contains("load 0 (node 1)"));
    CHECK_THROWS_WITH(ObstaclePenaltyPotential(3, 8, SphereObstacle{Eigen::Vector3d::Zero(), 0.0}, 1.0),
                      Contains("radius"));
    CHECK_THROWS_WITH(ObstaclePenaltyPotential(3, 8, PlaneObstacle{Eigen::Vector3d::Zero(), 0.0}, 1.0),
                      Contains("normal must be nonzero"));
    CHECK_THROWS_WITH(ObstaclePenaltyPotential(3, 8, PlaneObstacle{Eigen::Vector2d(0, 1), 0.0}, 1.0),
                      Contains("normal has 2 components, expected 3"));
    CHECK_THROWS_WITH(ObstaclePenaltyPotential(3, 8, PlaneObstacle{Eigen::Vector3d(0, 0, 1), 0.0}, -5.0),
                      Contains("stiffness"));
    CHECK_THROWS_WITH(ObstaclePenaltyPotential(3, 8, PlaneObstacle{Eigen::Vector3d(0, 0, 1), 0.0}, 1.0, {2, 2}),
                      Contains("node 2 is listed twice"));
    auto elastic = std::make_shared<ElasticPotential>(mesh, std::vector<ElementModel>{tet_model()});
    auto loads = std::make_shared<PointLoadPotential>(3, 9, std::vector<int>{}, Eigen::MatrixXd(3, 0));
    CHECK_THROWS_WITH(TotalPotential({elastic, loads}), Contains("'point loads' has 9 nodes"));
    CHECK_THROWS_WITH(TotalPotential({}), Contains("no terms"));
}
