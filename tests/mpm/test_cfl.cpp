// The CFL bound of explicit MPM steps (issue 33): the elastic wave speed of
// an isotropic model at rest is the longitudinal speed √((λ + 2μ)/ρ) in
// every direction, and the bound adds the particles' own speed.
#include "sinew/energies/models/model_catalog.hpp"
#include "sinew/mpm/cfl.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <cmath>

using namespace sinew;

TEST_CASE("CFL: the wave speed of a Lame model at rest is the longitudinal one")
{
    const double mu = 3e4, lambda = 5e4, rho = 1200.0;
    for (const char* name : {"fixed-corotated", "stable-neo-hookean"}) {
        CAPTURE(name);
        const auto model = make_model<3, 3>(name, ParameterValues{{"mu", mu}, {"lambda", lambda}});
        const double c = elastic_wave_speed<3>(*model, Eigen::Matrix3d::Identity(), MaterialPoint<3>{}, rho);
        CHECK(c == Approx(std::sqrt((lambda + 2.0 * mu) / rho)).epsilon(1e-10));
        // A rotation changes no wave speed (P(RF) = R P(F)).
        const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
        CHECK(elastic_wave_speed<3>(*model, R, MaterialPoint<3>{}, rho) == Approx(c).epsilon(1e-8));
    }
}

TEST_CASE("CFL: the bound is cfl dx over the fastest wave plus particle speed")
{
    const double mu = 1e4, lambda = 2e4;
    const auto model = make_model<3, 3>("fixed-corotated", ParameterValues{{"mu", mu}, {"lambda", lambda}});
    const std::vector<const Model3d*> models{model.get()};
    Particles<3> particles;
    particles.add(Eigen::Vector3d::Zero(), Eigen::Vector3d(3.0, 4.0, 0.0), 1.0, 1e-3);  // ρ = 1000, |v| = 5
    particles.add(Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero(), 1.0, 1e-3);
    const double c = std::sqrt((lambda + 2.0 * mu) / 1000.0);
    CHECK(cfl_time_step<3>(particles, models, 0.02, 0.4) == Approx(0.4 * 0.02 / (c + 5.0)).epsilon(1e-10));
    CHECK(std::isinf(cfl_time_step<3>(Particles<3>{}, models, 0.02, 0.4)));
}
