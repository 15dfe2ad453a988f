// AnisoMPM's driving force of damage (seed 004 Alg. 2, 5, 8; issue 34): the
// structural tensor, σ⁺ from the undegraded Cauchy stress, Φ, and σ_c from
// a critical stretch.
#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/qr_anisotropic.hpp"
#include "sinew/mpm/damage/driving_force.hpp"
#include "sinew/mpm/damage/structural_tensor.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace sinew;

namespace {

/// The disk tear's material (issue 34: E = 100, ν = 0.25, so μ = 40, λ = 40;
/// the QR model's λ is the Lamé λ + μ at rest) with fibre stiffness kx.
template <int Dim>
QrAnisotropic<Dim> disk_material(double kx = 0.0)
{
    return QrAnisotropic<Dim>({{"mu", 40.0}, {"lambda", 80.0}, {"kx", kx}});
}

Eigen::Matrix3d random_rotation(std::mt19937& rng)
{
    std::normal_distribution<double> n(0.0, 1.0);
    return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

Eigen::Matrix2d random_rotation_2d(std::mt19937& rng)
{
    std::uniform_real_distribution<double> angle(-M_PI, M_PI);
    return Eigen::Rotation2Dd(angle(rng)).toRotationMatrix();
}

/// A symmetric positive definite stretch with eigenvalues in [0.6, 1.6].
template <int Dim>
Eigen::Matrix<double, Dim, Dim> random_stretch(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(-1.0, 1.0), s(0.6, 1.6);
    Eigen::Matrix<double, Dim, Dim> M;
    for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j)
            M(i, j) = u(rng);
    const Eigen::HouseholderQR<Eigen::Matrix<double, Dim, Dim>> qr(M);
    const Eigen::Matrix<double, Dim, Dim> Q = qr.householderQ();
    Eigen::Matrix<double, Dim, 1> lambda;
    for (int i = 0; i < Dim; ++i)
        lambda[i] = s(rng);
    return Q * lambda.asDiagonal() * Q.transpose();
}

PhaseFieldPoint<3> orthotropic_field()
{
    PhaseFieldPoint<3> field;
    field.director1 = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
    field.director2 = Eigen::Vector3d(2.0, 1.0, -2.0) / 3.0;
    field.directors_used = 2;
    field.weight1 = -1.0;
    field.weight2 = 0.5;
    return field;
}

} // namespace

TEST_CASE("damage: the structural tensor turns the directors with the material and ignores its stretch",
          "[mpm][damage]")
{
    std::mt19937 rng(3);
    for (int trial = 0; trial < 50; ++trial) {
        const Eigen::Matrix3d Q = random_rotation(rng);
        const Eigen::Matrix3d F = Q * random_stretch<3>(rng);
        const PhaseFieldPoint<3> field = orthotropic_field();
        const Eigen::Vector3d a1 = Q * field.director1, a2 = Q * field.director2;
        const Eigen::Matrix3d expected =
            Eigen::Matrix3d::Identity() + field.weight1 * a1 * a1.transpose() + field.weight2 * a2 * a2.transpose();
        CHECK((structural_tensor(field, F) - expected).cwiseAbs().maxCoeff() < 1e-12);

        const Eigen::Matrix2d Q2 = random_rotation_2d(rng);
        PhaseFieldPoint<2> plane;
        plane.director1 = Eigen::Vector2d(0.6, 0.8);
        plane.weight1 = 2.0;
        const Eigen::Vector2d b = Q2 * plane.director1;
        CHECK((structural_tensor(plane, Eigen::Matrix2d(Q2 * random_stretch<2>(rng))) -
               (Eigen::Matrix2d::Identity() + 2.0 * b * b.transpose()))
                  .cwiseAbs()
                  .maxCoeff() < 1e-12);
    }
}

TEST_CASE("damage: sigma_crit from a stretch p makes Phi 1 at (1 + p) I, below it no damage, above it some",
          "[mpm][damage]")
{
    const double p = 0.35;
    const auto check = [&](const auto& model, const auto& field) {
        constexpr int Dim = std::decay_t<decltype(field)>::Vector::RowsAtCompileTime;
        using Matrix = Eigen::Matrix<double, Dim, Dim>;
        const MaterialPoint<Dim> point;
        auto calibrated = field;
        calibrated.sigma_crit = critical_stress_from_stretch(model, point, field, p);
        CHECK(calibrated.sigma_crit > 0.0);
        const auto at = [&](double stretch) {
            return driving_force(model, Matrix((1.0 + stretch) * Matrix::Identity()), point, calibrated);
        };
        CHECK(at(p)->phi == Approx(1.0).epsilon(1e-12));
        CHECK(at(0.9 * p)->phi < 1.0);
        CHECK(at(0.9 * p)->current == 0.0);
        CHECK(at(1.1 * p)->current > 0.0);
        // Any rotation of the material keeps Φ (σ, R and A turn together).
        std::mt19937 rng(5);
        for (int trial = 0; trial < 20; ++trial) {
            Matrix Q;
            if constexpr (Dim == 2)
                Q = random_rotation_2d(rng);
            else
                Q = random_rotation(rng);
            const Matrix F = random_stretch<Dim>(rng) * Matrix(Eigen::Matrix<double, Dim, 1>::Constant(1.1).asDiagonal());
            const double phi = driving_force(model, F, point, calibrated)->phi;
            CAPTURE(trial, phi);
            CHECK(driving_force(model, Matrix(Q * F), point, calibrated)->phi == Approx(phi).epsilon(1e-10).margin(1e-14));
        }
        // D̃ = max(ζ⟨Φ − 1⟩, D̃ᴴ) never decreases as the load comes and goes.
        double history = 0.0;
        for (const double stretch : {0.2, 1.2 * p, 1.5 * p, 1.1 * p, 0.0, 2.0 * p}) {
            const double next = driving_force_with_history(at(stretch)->current, history);
            CHECK(next >= history);
            history = next;
        }
        CHECK(history == at(2.0 * p)->current);
    };
    PhaseFieldPoint<2> plane;
    check(disk_material<2>(), plane);
    plane.weight1 = 0.0;
    check(disk_material<2>(), plane);
    PhaseFieldPoint<3> transverse;
    check(disk_material<3>(50.0), transverse);
    check(disk_material<3>(), orthotropic_field());
}

TEST_CASE("damage: compression and an inverted F drive no damage", "[mpm][damage]")
{
    const QrAnisotropic<3> model = disk_material<3>(20.0);
    PhaseFieldPoint<3> field;
    field.sigma_crit = 1e-3;
    const MaterialPoint<3> point;
    for (const Eigen::Vector3d& s : {Eigen::Vector3d(0.8, 0.8, 0.8), Eigen::Vector3d(0.9, 0.85, 0.95)}) {
        const auto force = driving_force(model, Eigen::Matrix3d(s.asDiagonal()), point, field);
        REQUIRE(force);
        CHECK(force->tension.cwiseAbs().maxCoeff() < 1e-12);
        CHECK(force->phi < 1e-12);
        CHECK(force->current == 0.0);
    }
    CHECK_FALSE(driving_force(model, Eigen::Matrix3d(Eigen::Vector3d(1.2, 1.0, -0.5).asDiagonal()), point, field));
    CHECK_FALSE(driving_force(model, Eigen::Matrix3d(Eigen::Matrix3d::Zero()), point, field));
    CHECK_FALSE(
        driving_force(model, Eigen::Matrix3d(Eigen::Matrix3d::Constant(std::numeric_limits<double>::quiet_NaN())), point, field));
}

TEST_CASE("damage: the undegraded stress ignores the point's damage", "[mpm][damage]")
{
    const QrAnisotropic<3> model = disk_material<3>(30.0);
    MaterialPoint<3> intact, broken;
    broken.damage = 0.9;
    const Eigen::Matrix3d F = (Eigen::Matrix3d() << 1.3, 0.1, 0.0, -0.05, 1.1, 0.2, 0.0, 0.1, 0.95).finished();
    CHECK(*undegraded_cauchy_stress(model, F, broken) == *undegraded_cauchy_stress(model, F, intact));
}

TEST_CASE("damage: with alpha = -1 the fibre's own tension drops out, so pulling across the fibres drives more than "
          "along them",
          "[mpm][damage]")
{
    // a₁ = e_x, A = I − e_x e_xᵀ: uniaxial strain along x gives σ = diag(s₁, s₂, s₂)
    // and Φσ_c² = 2s₂², across it diag(s₂, s₁, s₂) and s₁² + s₂² (s₁ > s₂):
    // the seed's cracks open along the fibres when the material is pulled across them.
    const Eigen::Matrix3d along = Eigen::Vector3d(1.3, 1.0, 1.0).asDiagonal();
    const Eigen::Matrix3d across = Eigen::Vector3d(1.0, 1.3, 1.0).asDiagonal();
    PhaseFieldPoint<3> field;
    const MaterialPoint<3> point;
    const double soft_along = driving_force(disk_material<3>(), along, point, field)->phi;
    const double soft_across = driving_force(disk_material<3>(), across, point, field)->phi;
    CHECK(soft_across > 1.5 * soft_along);
    // A stiff fibre adds tension along x only, which A removes.
    const double stiff_along = driving_force(disk_material<3>(400.0), along, point, field)->phi;
    CHECK(stiff_along == Approx(soft_along).epsilon(1e-12));
    // Without the director's weight, the fibre's tension counts in full.
    field.weight1 = 0.0;
    CHECK(driving_force(disk_material<3>(400.0), along, point, field)->phi > 10.0 * soft_along);
}

TEST_CASE("damage: invalid phase-field points and stretches are named", "[mpm][damage][errors]")
{
    PhaseFieldPoint<3> field;
    CHECK(phase_field_point_error(field).empty());
    CHECK(phase_field_point_error(orthotropic_field()).empty());
    auto expect = [](PhaseFieldPoint<3> bad, const char* word) {
        const std::string message = phase_field_point_error(bad);
        CAPTURE(message);
        CHECK(message.find(word) != std::string::npos);
    };
    PhaseFieldPoint<3> bad = field;
    bad.director1 = Eigen::Vector3d::Zero();
    expect(bad, "a1");
    bad = orthotropic_field();
    bad.director2 = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
    expect(bad, "orthogonal");
    bad = field;
    bad.weight1 = -1.5;
    expect(bad, "weight");
    bad = field;
    bad.sigma_crit = 0.0;
    expect(bad, "sigma_crit");
    bad = field;
    bad.eta = std::numeric_limits<double>::infinity();
    expect(bad, "eta");
    bad = field;
    bad.l0 = -1.0;
    expect(bad, "l0");
    bad = field;
    bad.directors_used = 3;
    expect(bad, "directors_used");
    PhaseFieldPoint<2> plane;
    plane.directors_used = 2;
    CHECK(phase_field_point_error(plane).find("3D") != std::string::npos);
    for (const double p : {0.0, -0.1, std::numeric_limits<double>::quiet_NaN()})
        CHECK_THROWS_AS(critical_stress_from_stretch(disk_material<3>(), MaterialPoint<3>{}, field, p), InputError);
}
