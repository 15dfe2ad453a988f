// The finite-volume forces of seed 000 §4.4, built from the rest geometry as
// the seed builds them, are minus the elastic gradient (DESIGN.md).
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/total_potential.hpp"

#include "energies/deformation_regimes.hpp"
#include "potentials/potential_checks.hpp"
#include "potentials/test_meshes.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

/// Area-weighted outward normal A·N of the face of the rest tet X that leaves
/// out vertex k.
Eigen::Vector3d outward_area_normal(const Eigen::Matrix<double, 3, 4>& X, int k)
{
    int face[3];
    int n = 0;
    for (int a = 0; a < 4; ++a)
        if (a != k)
            face[n++] = a;
    Eigen::Vector3d an = 0.5 * (X.col(face[1]) - X.col(face[0])).cross(X.col(face[2]) - X.col(face[0]));
    if (an.dot(X.col(k) - X.col(face[0])) > 0.0)
        an = -an;
    return an;
}

} // namespace

TEST_CASE("finite-volume forces G = P·Bm (seed 000 §4.4) equal minus the elastic gradient on tets",
          "[potentials][elastic][fvm]")
{
    std::mt19937 rng(21);
    for (const std::string model_name : {"stable-neo-hookean", "mooney-rivlin-muscle"}) {
        CAPTURE(model_name);
        Mesh mesh = box_of_tets(2, 2, 2, 0.5);
        const ElementModel model = make_element_model(mesh.kind, model_name, {});
        const Model3d& pointwise = *std::get<std::shared_ptr<const Model3d>>(model);
        auto elastic = std::make_shared<ElasticPotential>(mesh, std::vector<ElementModel>{model});
        std::vector<MaterialPoint<3>> points(mesh.num_elements());
        for (int e = 0; e < mesh.num_elements(); ++e) {
            points[e].fiber = random_unit_vector<3>(rng);
            points[e].activation = 0.4;
            elastic->set_fiber(e, points[e].fiber);
            elastic->set_activation(e, points[e].activation);
        }
        TotalPotential E({elastic});

        for (Regime regime : {Regime::moderate, Regime::rotated, Regime::large_stretch}) {
            CAPTURE(regime_name(regime));
            const Eigen::Matrix3d A = random_deformation<3, 3>(regime, rng);
            Eigen::VectorXd x(3 * mesh.num_nodes());
            std::uniform_real_distribution<double> u11(-1.0, 1.0);
            for (int i = 0; i < mesh.num_nodes(); ++i)
                x.segment<3>(3 * i) = A * mesh.nodes.col(i) + 0.02 * Eigen::Vector3d(u11(rng), u11(rng), u11(rng));

            Eigen::VectorXd forces = Eigen::VectorXd::Zero(x.size());
            for (int e = 0; e < mesh.num_elements(); ++e) {
                Eigen::Matrix<double, 3, 4> X, xs;
                for (int a = 0; a < 4; ++a) {
                    X.col(a) = mesh.nodes.col(mesh.elements(a, e));
                    xs.col(a) = x.segment<3>(3 * mesh.elements(a, e));
                }
                Eigen::Matrix3d Dm, Ds;
                for (int a = 0; a < 3; ++a) {
                    Dm.col(a) = X.col(a + 1) - X.col(0);
                    Ds.col(a) = xs.col(a + 1) - xs.col(0);
                }
                // b_j = (1/3) A N of the face opposite vertex j (§4.4).
                Eigen::Matrix3d Bm;
                for (int j = 0; j < 3; ++j)
                    Bm.col(j) = outward_area_normal(X, j + 1) / 3.0;
                // The seed's claim Bm = −V Dm⁻ᵀ, checked on the way.
                const double V = Dm.determinant() / 6.0;
                CHECK((Bm + V * Dm.inverse().transpose()).norm() < 1e-14);

                Eigen::Matrix3d P;
                pointwise.evaluate(Ds * Dm.inverse(), points[e], &P, nullptr, Projection::none);
                const Eigen::Matrix3d G = P * Bm;
                for (int j = 0; j < 3; ++j)
                    forces.segment<3>(3 * mesh.elements(j + 1, e)) += G.col(j);
                forces.segment<3>(3 * mesh.elements(0, e)) -= G.rowwise().sum();
            }
            const Eigen::VectorXd gradient = gradient_of(E, x);
            REQUIRE(gradient.cwiseAbs().maxCoeff() > 0.0);
            CHECK(relative_error(forces, Eigen::VectorXd(-gradient)) < 1e-12);
        }
    }
}
