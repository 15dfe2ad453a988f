// The muscle model of seed 000: ψ → P → ∂P/∂F against central differences in
// every deformation regime and inverted, the SVD-frame block form against
// the full 9×9 of differences, the §5.6 projection, rest state, closed forms,
// the pure Mooney-Rivlin part, frame indifference and the continuation
// through inversion.
#include "sinew/energies/models/mooney_rivlin_muscle.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/rotation_variant_svd.hpp"
#include "energies/deformation_regimes.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using sinew::FiberStretch;
using sinew::MaterialPoint;
using sinew::MooneyRivlinMuscle;
using sinew::ParameterValues;
using sinew::Projection;
using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Stiffness = sinew::Model3d::Stiffness;
using Stress = sinew::Model3d::Stress;

const FiberStretch kStretches[] = {FiberStretch::physbam, FiberStretch::deviatoric};

/// The defaults (K/μ₀ = 2·10⁴, σ_max/μ₀ = 600: fiber dominated) or a balanced
/// set where every term has a comparable size, with the fiber stretch chosen.
ParameterValues parameters(bool balanced, FiberStretch stretch)
{
    ParameterValues values;
    if (balanced)
        values = {{"A", 1.0},         {"B", 0.6}, {"K", 8.0},  {"sigma_max", 2.0},
                  {"lambda_opt", 1.1}, {"P1", 0.3}, {"P2", 4.0}, {"lambda_star", 1.3}};
    values["fiber_stretch"] = stretch == FiberStretch::physbam ? 0.0 : 1.0;
    return values;
}

ParameterValues all_parameters(const ParameterValues& given)
{
    return sinew::resolve_parameters(MooneyRivlinMuscle::kName, MooneyRivlinMuscle::parameter_specs(), given);
}

/// Largest parameter in Pa: the absolute scale below which stresses count as zero.
double stress_scale(const ParameterValues& given)
{
    const ParameterValues all = all_parameters(given);
    return std::max({all.at("A"), all.at("B"), all.at("K"), all.at("sigma_max")});
}

ParameterValues without_fibers(ParameterValues values)
{
    values["sigma_max"] = 0.0;
    return values;
}

/// L = ln J continued below the threshold c as the model documents (§5.5).
double thresholded_log_volume(const Vec3& sigma, double c)
{
    double L = 0.0;
    for (int k = 0; k < 3; ++k)
        L += sigma[k] >= c ? std::log(sigma[k]) : std::log(c) + (sigma[k] - c) / c;
    return L;
}

/// Fiber stretch recomputed from its definition (seed 000 §4.2, §4.3.3).
double fiber_stretch_of(const MooneyRivlinMuscle& model, const Mat3& F, const Vec3& a)
{
    const double mu = (F * a).norm();
    if (model.fiber_stretch() == FiberStretch::physbam)
        return mu;
    const Vec3 sigma = sinew::rotation_variant_svd<3>(F).sigma;
    return mu * std::exp(-thresholded_log_volume(sigma, model.inversion_threshold()) / 3.0);
}

/// ψ is C¹ but its Hessian jumps where a fiber curve changes piece and where
/// a singular value crosses c: a central difference of P straddling such a
/// place measures the jump, not ∂P/∂F. Those F are skipped (the steps move λ
/// and σ by ~1e-5 at most, the margin is 1e-4).
bool near_a_kink(const MooneyRivlinMuscle& model, const Mat3& F, const Vec3& a)
{
    const double margin = 1e-4;
    const double lambda = fiber_stretch_of(model, F, a);
    for (double b : model.active_curve().break_points())
        if (std::abs(lambda - b) < margin)
            return true;
    for (double b : model.passive_curve().break_points())
        if (std::abs(lambda - b) < margin)
            return true;
    const Vec3 sigma = sinew::rotation_variant_svd<3>(F).sigma;
    return (sigma.array() - model.inversion_threshold()).abs().minCoeff() < margin;
}

MaterialPoint<3> random_point(std::mt19937& rng)
{
    MaterialPoint<3> point;
    point.fiber = sinew::test::random_unit_vector<3>(rng);
    point.activation = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    point.damage = std::uniform_real_distribution<double>(0.0, 1.0)(rng);  // not read by this model
    return point;
}

/// Inverted F: σ = (σ₀, σ₁, −s) with s well below σ₁, away from the inverted
/// tie σ₁ + σ₂ = 0 (where P has a kink, see the docs).
Mat3 random_inverted(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const Vec3 sigma(0.8 + 0.8 * u01(rng), 0.6 + 0.3 * u01(rng), -(0.005 + 0.4 * u01(rng)));
    return sinew::test::random_rotation<3>(rng) * sigma.asDiagonal() * sinew::test::random_rotation<3>(rng).transpose();
}

/// The 9×9 eigenvalue clamp of a symmetric matrix (the reference projection).
Stiffness spectral_clamp(const Stiffness& K)
{
    Eigen::SelfAdjointEigenSolver<Stiffness> eigen(0.5 * (K + K.transpose()));
    return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
}

double smallest_eigenvalue(const Stiffness& K)
{
    return Eigen::SelfAdjointEigenSolver<Stiffness>(0.5 * (K + K.transpose()), Eigen::EigenvaluesOnly)
        .eigenvalues()
        .minCoeff();
}

struct DerivativeErrors {
    double stress = 0.0;     ///< |P − P_fd|∞ / max(|P_fd|∞, floor)
    double stiffness = 0.0;  ///< |K − K_fd|∞ / max(|K_fd|∞, floor)
    double asymmetry = 0.0;  ///< |K − Kᵀ|∞ / |K|∞
    double smallest_projected_eigenvalue = 0.0;  ///< λ_min(K_clamp) / |K|∞
    double projection_change_where_psd = 0.0;    ///< |K_clamp − K|∞ / |K|∞ where λ_min(K) ≥ 0
    bool indefinite = false;                     ///< λ_min(K) < 0: the projection had work to do
};

// Tolerances, relative to the largest entry (floored at 1e-10 of the largest
// parameter): central differences with step h = 1e-6·max(1, |F|∞) carry
// truncation ~h²|∂³ψ|/6 and rounding ~1e-16|ψ|/h. Over all sampled F
// (regimes, inverted, repeated σ) the largest ratios seen are 4e-8 for P
// (near rest, where P → 0 and the rounding of ψ/h dominates) and 1.3e-9 for
// ∂P/∂F; the tolerances are 1e-6 and 1e-7. Symmetry and PSD are rounding
// only: 1e-12 and −1e-11 of |∂P/∂F|∞ (the brief's bound is −1e-9). Where
// λ_min(K) ≥ 0 the projection returns the exact K: 1e-14 relative.
constexpr double kStep = 1e-6;
constexpr double kStressTolerance = 1e-6;
constexpr double kStiffnessTolerance = 1e-7;
constexpr double kSymmetryTolerance = 1e-12;
constexpr double kPsdTolerance = 1e-11;
constexpr double kUnchangedTolerance = 1e-14;

/// All checks of one F: finite values first, then the comparisons.
DerivativeErrors check_derivatives(const MooneyRivlinMuscle& model, const Mat3& F, const MaterialPoint<3>& point,
                                   double scale)
{
    Stress P;
    Stiffness K, K_projected;
    const double psi = model.evaluate(F, point, &P, &K, Projection::none);
    model.evaluate(F, point, nullptr, &K_projected, Projection::clamp);
    REQUIRE(std::isfinite(psi));
    REQUIRE(P.allFinite());
    REQUIRE(K.allFinite());
    REQUIRE(K_projected.allFinite());
    REQUIRE(model.energy(F, point) == psi);

    const Stress P_fd = sinew::test::finite_difference_stress(model, F, point, kStep);
    const Stiffness K_fd = sinew::test::finite_difference_stiffness(model, F, point, kStep);
    REQUIRE(P_fd.allFinite());
    REQUIRE(K_fd.allFinite());
    REQUIRE(K.cwiseAbs().maxCoeff() > 0.0);

    DerivativeErrors e;
    e.stress = sinew::test::relative_difference(P, P_fd, 1e-10 * scale);
    e.stiffness = sinew::test::relative_difference(K, K_fd, 1e-10 * scale);
    const double size = std::max(K.cwiseAbs().maxCoeff(), 1e-10 * scale);
    e.asymmetry = (K - K.transpose()).cwiseAbs().maxCoeff() / size;
    e.smallest_projected_eigenvalue = smallest_eigenvalue(K_projected) / size;
    const double exact_smallest = smallest_eigenvalue(K);
    e.indefinite = exact_smallest < 0.0;
    if (!e.indefinite)
        e.projection_change_where_psd = (K_projected - K).cwiseAbs().maxCoeff() / size;
    return e;
}

void require_small(const DerivativeErrors& e)
{
    CHECK(e.stress < kStressTolerance);
    CHECK(e.stiffness < kStiffnessTolerance);
    CHECK(e.asymmetry < kSymmetryTolerance);
    CHECK(e.smallest_projected_eigenvalue > -kPsdTolerance);
    CHECK(e.projection_change_where_psd < kUnchangedTolerance);
}

/// Mooney-Rivlin + ln J volume term written directly in F (seed 000 §4.2,
/// §4.3.5), the reference twin for the model with its fiber terms off.
double mooney_rivlin_energy(double A, double B, double K, const Mat3& F)
{
    const double J = F.determinant();
    const Mat3 C = F.transpose() * F;
    const double trC = C.trace();
    const double trC2 = (C * C).trace();
    return A * std::pow(J, -2.0 / 3.0) * trC + B * std::pow(J, -4.0 / 3.0) * 0.5 * (trC * trC - trC2) +
           0.5 * K * std::log(J) * std::log(J);
}

/// §4.3.5: ∂(AĪ₁)/∂F + ∂(BĪ₂)/∂F + ∂U/∂F in F.
Mat3 mooney_rivlin_stress(double A, double B, double K, const Mat3& F)
{
    const double J = F.determinant();
    const Mat3 F_invT = F.inverse().transpose();
    const Mat3 C = F.transpose() * F;
    const double trC = C.trace();
    const double trC2 = (C * C).trace();
    const Mat3 dI1 = 2.0 * A * std::pow(J, -2.0 / 3.0) * (F - trC / 3.0 * F_invT);
    const Mat3 dI2 = 2.0 * B * std::pow(J, -4.0 / 3.0) * ((trC2 - trC * trC) / 3.0 * F_invT + trC * F - F * C);
    return dI1 + dI2 + K * std::log(J) * F_invT;
}

/// Central differences of the reference stress: the reference ∂P/∂F.
Stiffness mooney_rivlin_stiffness(double A, double B, double K, const Mat3& F, double h)
{
    Stiffness result;
    const double step = h * std::max(1.0, F.cwiseAbs().maxCoeff());
    for (int k = 0; k < 9; ++k) {
        Mat3 Fp = F, Fm = F;
        Fp.data()[k] += step;
        Fm.data()[k] -= step;
        const Mat3 dP = (mooney_rivlin_stress(A, B, K, Fp) - mooney_rivlin_stress(A, B, K, Fm)) / (2 * step);
        result.col(k) = Eigen::Map<const Vec9>(dP.data());
    }
    return result;
}

/// Q = V ⊗ U: column a + 3b is vec(u_a v_bᵀ), the SVD-frame basis of §4.5.
Stiffness svd_frame_basis(const sinew::RotationVariantSvd<3>& svd)
{
    Stiffness Q;
    for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) {
            const Mat3 mode = svd.U.col(a) * svd.V.col(b).transpose();
            Q.col(a + 3 * b) = Eigen::Map<const Vec9>(mode.data());
        }
    return Q;
}

} // namespace

TEST_CASE("mooney-rivlin-muscle: parameters with defaults and bad input", "[energies][muscle]")
{
    const MooneyRivlinMuscle model({});
    CHECK(model.name() == "mooney-rivlin-muscle");
    CHECK(std::string(MooneyRivlinMuscle::kName) == "mooney-rivlin-muscle");
    CHECK(model.fiber_stretch() == FiberStretch::physbam);
    CHECK(model.inversion_threshold() == 0.1);
    CHECK(MooneyRivlinMuscle({{"fiber_stretch", 1.0}}).fiber_stretch() == FiberStretch::deviatoric);
    const auto specs = MooneyRivlinMuscle::parameter_specs();
    const auto stretch = std::find_if(specs.begin(), specs.end(), [](const auto& s) { return s.name == "fiber_stretch"; });
    REQUIRE(stretch != specs.end());
    CHECK(stretch->choices == std::vector<std::string>{"physbam", "deviatoric"});
    CHECK(sinew::resolve_parameters(MooneyRivlinMuscle::kName, specs,
                                    sinew::ParameterText{{"fiber_stretch", "deviatoric"}})
              .at("fiber_stretch") == 1.0);
    for (const auto& name : {"A", "B", "K", "sigma_max", "lambda_opt", "P1", "P2", "lambda_star",
                             "fiber_stretch", "inversion_threshold"}) {
        CAPTURE(name);
        CHECK(std::any_of(specs.begin(), specs.end(), [&](const auto& s) { return s.name == name; }));
    }

    // Each bad value throws InputError naming the parameter.
    const std::vector<std::pair<std::string, double>> bad = {
        {"A", -1.0},         {"B", -1e-3},       {"K", -5.0},         {"sigma_max", -1.0},
        {"lambda_opt", 0.0}, {"P1", -0.1},       {"P2", 0.0},         {"lambda_star", 0.0},
        {"fiber_stretch", 2.0}, {"inversion_threshold", 0.6}, {"inversion_threshold", -0.1},
        {"A", std::numeric_limits<double>::quiet_NaN()}};
    for (const auto& [name, value] : bad) {
        CAPTURE(name, value);
        try {
            MooneyRivlinMuscle({{name, value}});
            FAIL("no InputError");
        } catch (const sinew::InputError& error) {
            CHECK(std::string(error.what()).find(name) != std::string::npos);
        }
    }
    // Cross check: the passive curve turns linear after slack, λ* ≥ λ_opt.
    try {
        MooneyRivlinMuscle({{"lambda_opt", 1.2}, {"lambda_star", 1.1}});
        FAIL("no InputError");
    } catch (const sinew::InputError& error) {
        CHECK(std::string(error.what()).find("lambda_star") != std::string::npos);
    }
    CHECK_THROWS_AS(MooneyRivlinMuscle({{"stiffness", 1.0}}), sinew::InputError);
}

TEST_CASE("mooney-rivlin-muscle: P and dP/dF against central differences in every regime", "[energies][muscle]")
{
    for (bool balanced : {false, true}) {
        for (FiberStretch stretch : kStretches) {
            const ParameterValues values = parameters(balanced, stretch);
            const MooneyRivlinMuscle model(values);
            const double scale = stress_scale(values);
            for (sinew::test::Regime regime : sinew::test::all_regimes()) {
                CAPTURE(balanced, static_cast<int>(stretch), sinew::test::regime_name(regime));
                std::mt19937 rng(1234 + static_cast<unsigned>(regime) + 17 * balanced + 101 * static_cast<int>(stretch));
                DerivativeErrors worst;
                int checked = 0, skipped = 0, indefinite = 0;
                while (checked < 1000) {
                    const Mat3 F = sinew::test::random_deformation<3, 3>(regime, rng);
                    const MaterialPoint<3> point = random_point(rng);
                    if (near_a_kink(model, F, point.fiber)) {
                        ++skipped;
                        continue;
                    }
                    CAPTURE(F, point.fiber, point.activation);
                    const DerivativeErrors e = check_derivatives(model, F, point, scale);
                    require_small(e);
                    worst.stress = std::max(worst.stress, e.stress);
                    worst.stiffness = std::max(worst.stiffness, e.stiffness);
                    worst.asymmetry = std::max(worst.asymmetry, e.asymmetry);
                    worst.smallest_projected_eigenvalue =
                        std::min(worst.smallest_projected_eigenvalue, e.smallest_projected_eigenvalue);
                    indefinite += e.indefinite;
                    ++checked;
                }
                CAPTURE(worst.stress, worst.stiffness, worst.asymmetry, worst.smallest_projected_eigenvalue, indefinite);
                CHECK(skipped < 100);
            }
        }
    }
}

TEST_CASE("mooney-rivlin-muscle: derivatives of inverted elements (thresholded model)", "[energies][muscle]")
{
    for (bool balanced : {false, true}) {
        for (FiberStretch stretch : kStretches) {
            const ParameterValues values = parameters(balanced, stretch);
            const MooneyRivlinMuscle model(values);
            const double scale = stress_scale(values);
            std::mt19937 rng(99 + 17 * balanced + 101 * static_cast<int>(stretch));
            int checked = 0;
            while (checked < 1000) {
                const Mat3 F = random_inverted(rng);
                const MaterialPoint<3> point = random_point(rng);
                if (near_a_kink(model, F, point.fiber))
                    continue;
                CAPTURE(balanced, static_cast<int>(stretch), F, point.fiber, point.activation);
                REQUIRE(F.determinant() < 0.0);
                require_small(check_derivatives(model, F, point, scale));
                ++checked;
            }
        }
    }
}

TEST_CASE("mooney-rivlin-muscle: dpsi/dalpha and dP/dalpha against differences in the activation", "[energies][muscle]")
{
    // ψ is linear in α (seed 000 eq. 4), so central differences in α are
    // exact but for rounding, whatever the step; ∂P/∂α is checked a second
    // way too, as the F-differences of ∂ψ/∂α. Every regime, inverted F
    // included, both fiber stretches.
    constexpr double kActivationStep = 0.25;
    constexpr double kTolerance = 1e-7;
    for (FiberStretch stretch : kStretches) {
        const ParameterValues values = parameters(true, stretch);
        const MooneyRivlinMuscle model(values);
        const double scale = stress_scale(values);
        std::mt19937 rng(77 + static_cast<int>(stretch));
        std::vector<Mat3> samples;
        for (sinew::test::Regime regime : sinew::test::all_regimes())
            for (int k = 0; k < 200; ++k)
                samples.push_back(sinew::test::random_deformation<3, 3>(regime, rng));
        for (int k = 0; k < 200; ++k)
            samples.push_back(random_inverted(rng));
        int nonzero = 0;
        for (const Mat3& F : samples) {
            const MaterialPoint<3> point = random_point(rng);
            if (near_a_kink(model, F, point.fiber))
                continue;
            CAPTURE(static_cast<int>(stretch), F, point.fiber, point.activation);
            Stress dP;
            const double dpsi = model.activation_derivative(F, point, &dP);
            const auto differences = sinew::test::finite_difference_activation(model, F, point, kActivationStep);
            CHECK(std::abs(dpsi - differences.dpsi) <= kTolerance * std::max(std::abs(differences.dpsi), 1e-10 * scale));
            CHECK(sinew::test::relative_difference(dP, differences.dP, 1e-10 * scale) < kTolerance);
            // ∂P/∂α = ∂(∂ψ/∂α)/∂F: differences of activation_derivative's value in F.
            Stress dP_of_dpsi;
            const double h = kStep * std::max(1.0, F.cwiseAbs().maxCoeff());
            for (int q = 0; q < 9; ++q) {
                Mat3 Fp = F, Fm = F;
                Fp.data()[q] += h;
                Fm.data()[q] -= h;
                dP_of_dpsi.data()[q] = (model.activation_derivative(Fp, point, nullptr) -
                                        model.activation_derivative(Fm, point, nullptr)) / (2 * h);
            }
            // Φ_a is O(σ_max) where f_a may be near zero: the differences carry
            // rounding of ε|Φ_a|/h ≈ 1e-10·scale, hence the floor 1e-4·scale.
            CHECK(sinew::test::relative_difference(dP, dP_of_dpsi, 1e-4 * scale) < kStressTolerance);
            nonzero += dP.cwiseAbs().maxCoeff() > 0.0;
        }
        CHECK(nonzero > 100);
    }
    // A model without activation: zeros.
    const MooneyRivlinMuscle passive({{"sigma_max", 0.0}});
    Stress dP;
    CHECK(passive.activation_derivative(Mat3::Identity() * 1.1, MaterialPoint<3>{}, &dP) == 0.0);
    CHECK(dP.isZero(0.0));
}

TEST_CASE("mooney-rivlin-muscle: repeated singular values", "[energies][muscle]")
{
    // The blocks have no (σ_i − σ_j) denominators (closed forms of §4.5.1.4,
    // divided differences of ℓ' in bounded form), so ties are ordinary points.
    const std::vector<Vec3> spectra = {{1.0, 1.0, 1.0},   {1.3, 1.3, 1.3},    {1.5, 1.5, 0.8},     {1.2, 0.7, 0.7},
                                       {0.5, 0.5, 0.5},   {1.0, 0.05, 0.05},  {0.06, 0.06, 0.06},  {2.0, 0.3, 0.3},
                                       {1.1, 1.1, -0.3},  {1.0, 0.5, 0.5 + 1e-9}};
    for (bool balanced : {false, true}) {
        for (FiberStretch stretch : kStretches) {
            const ParameterValues values = parameters(balanced, stretch);
            const MooneyRivlinMuscle model(values);
            const double scale = stress_scale(values);
            std::mt19937 rng(5 + 17 * balanced + 101 * static_cast<int>(stretch));
            for (const Vec3& sigma : spectra) {
                for (int trial = 0; trial < 20; ++trial) {
                    const Mat3 F = sinew::test::random_rotation<3>(rng) * sigma.asDiagonal() *
                                   sinew::test::random_rotation<3>(rng).transpose();
                    const MaterialPoint<3> point = random_point(rng);
                    if (near_a_kink(model, F, point.fiber))
                        continue;
                    CAPTURE(balanced, static_cast<int>(stretch), sigma, F, point.fiber, point.activation);
                    require_small(check_derivatives(model, F, point, scale));
                }
            }
        }
    }
}

TEST_CASE("mooney-rivlin-muscle: the block form equals the 9x9 dP/dF of differences", "[energies][muscle]")
{
    // Seed 000 §4.5: in the SVD frame Q = V ⊗ U the isotropic ∂P/∂F is block
    // diagonal, a 3×3 block A on (F̂₁₁, F̂₂₂, F̂₃₃) and 2×2 blocks
    // B_ij = [[α_ij, β_ij], [β_ij, α_ij]] on (F̂_ij, F̂_ji). Here the 9×9 of
    // central differences of P (nothing of the model's Hessian code) is
    // rotated into that frame: it has the block pattern, and equals the
    // model's assembled block form. Then with fibers on, the model's ∂P/∂F
    // (blocks + eq. 45) equals the differences in the same frame.
    const int diagonal_index[3] = {0, 4, 8};  // a + 3a
    for (bool balanced : {false, true}) {
        for (bool fibers : {false, true}) {
            for (FiberStretch stretch : kStretches) {
                const ParameterValues values =
                    fibers ? parameters(balanced, stretch) : without_fibers(parameters(balanced, stretch));
                const MooneyRivlinMuscle model(values);
                std::mt19937 rng(31 + 2 * balanced + fibers + 7 * static_cast<int>(stretch));
                for (sinew::test::Regime regime : sinew::test::all_regimes()) {
                    for (int trial = 0; trial < 100; ++trial) {
                        const Mat3 F = sinew::test::random_deformation<3, 3>(regime, rng);
                        const MaterialPoint<3> point = random_point(rng);
                        if (near_a_kink(model, F, point.fiber))
                            continue;
                        CAPTURE(balanced, fibers, static_cast<int>(stretch), sinew::test::regime_name(regime), F);
                        const sinew::RotationVariantSvd<3> svd = sinew::rotation_variant_svd<3>(F);
                        const Stiffness Q = svd_frame_basis(svd);
                        Stiffness K;
                        model.evaluate(F, point, nullptr, &K, Projection::none);
                        const Stiffness K_fd = sinew::test::finite_difference_stiffness(model, F, point, kStep);
                        const Stiffness blocks = Q.transpose() * K * Q;
                        const Stiffness blocks_fd = Q.transpose() * K_fd * Q;
                        const double size = K_fd.cwiseAbs().maxCoeff();
                        REQUIRE(size > 0.0);
                        // Same tolerance as the derivative test (rotation by Q is exact to rounding).
                        CHECK((blocks - blocks_fd).cwiseAbs().maxCoeff() < kStiffnessTolerance * size);
                        if (fibers)
                            continue;
                        // The block pattern of the differences: zero outside A and the B_ij ...
                        Stiffness outside = blocks_fd;
                        for (int r : diagonal_index)
                            for (int s : diagonal_index)
                                outside(r, s) = 0.0;
                        for (int i = 0; i < 3; ++i)
                            for (int j = i + 1; j < 3; ++j) {
                                const int ij = i + 3 * j, ji = j + 3 * i;
                                // ... and B_ij = [[α, β], [β, α]]
                                CHECK(std::abs(blocks_fd(ij, ij) - blocks_fd(ji, ji)) < kStiffnessTolerance * size);
                                CHECK(std::abs(blocks_fd(ij, ji) - blocks_fd(ji, ij)) < kStiffnessTolerance * size);
                                outside(ij, ij) = outside(ji, ji) = outside(ij, ji) = outside(ji, ij) = 0.0;
                            }
                        CHECK(outside.cwiseAbs().maxCoeff() < kStiffnessTolerance * size);
                    }
                }
            }
        }
    }
}

TEST_CASE("mooney-rivlin-muscle: projection clamps blocks and keeps PSD matrices", "[energies][muscle]")
{
    // Fibers off: ∂P/∂F is block diagonal in the SVD frame, so clamping each
    // block (§5.6) is the spectral clamp of the whole 9×9. Fibers on: the
    // result is PSD, equal to ∂P/∂F where that is PSD, and different where it
    // is not. Tolerances: rounding of two eigen-decompositions, 1e-10 of |K|∞.
    for (bool balanced : {false, true}) {
        for (FiberStretch stretch : kStretches) {
            const ParameterValues values = parameters(balanced, stretch);
            const MooneyRivlinMuscle matrix(without_fibers(values)), muscle(values);
            std::mt19937 rng(77 + 2 * balanced + static_cast<int>(stretch));
            int clamped_matrix = 0, clamped_muscle = 0;
            for (sinew::test::Regime regime : sinew::test::all_regimes()) {
                for (int trial = 0; trial < 300; ++trial) {
                    const Mat3 F = sinew::test::random_deformation<3, 3>(regime, rng);
                    const MaterialPoint<3> point = random_point(rng);
                    CAPTURE(balanced, static_cast<int>(stretch), sinew::test::regime_name(regime), F, point.fiber);
                    Stiffness K, K_projected;
                    matrix.evaluate(F, point, nullptr, &K, Projection::none);
                    matrix.evaluate(F, point, nullptr, &K_projected, Projection::clamp);
                    const double size = K.cwiseAbs().maxCoeff();
                    CHECK((K_projected - spectral_clamp(K)).cwiseAbs().maxCoeff() < 1e-10 * size);
                    clamped_matrix += smallest_eigenvalue(K) < -1e-8 * size;

                    muscle.evaluate(F, point, nullptr, &K, Projection::none);
                    muscle.evaluate(F, point, nullptr, &K_projected, Projection::clamp);
                    const double muscle_size = K.cwiseAbs().maxCoeff();
                    CHECK(smallest_eigenvalue(K_projected) > -kPsdTolerance * muscle_size);
                    if (smallest_eigenvalue(K) >= 0.0) {
                        CHECK((K_projected - K).cwiseAbs().maxCoeff() <= kUnchangedTolerance * muscle_size);
                    } else {
                        CHECK((K_projected - K).cwiseAbs().maxCoeff() > 0.0);
                        ++clamped_muscle;
                    }
                }
            }
            CAPTURE(clamped_matrix, clamped_muscle);
            CHECK(clamped_matrix > 50);  // the checks above were not vacuous
            CHECK(clamped_muscle > 50);
        }
    }
}

TEST_CASE("mooney-rivlin-muscle: projection keeps the fiber tension derivative non-negative", "[energies][muscle]")
{
    // §5.6 "force the tension derivative to be positive": a fiber stretched on
    // the descending limb (f' < 0) of a model whose matrix is too soft to
    // compensate. Along δF = δs n a₀ᵀ the exact second variation is
    // f' + (isotropic part); the projected one is ≥ 0.
    const MooneyRivlinMuscle model({{"A", 1.0}, {"B", 1.0}, {"K", 1.0}, {"sigma_max", 1e3}});
    MaterialPoint<3> point;
    point.fiber = Vec3(1.0, 2.0, -1.0).normalized();
    point.activation = 1.0;
    const Mat3 F = Mat3::Identity() + 0.25 * point.fiber * point.fiber.transpose();  // λ̃ = 1.25
    const double lambda = (F * point.fiber).norm();
    REQUIRE(model.active_curve().evaluate(lambda).stiffness < -100.0);
    Stiffness K, K_projected;
    model.evaluate(F, point, nullptr, &K, Projection::none);
    model.evaluate(F, point, nullptr, &K_projected, Projection::clamp);
    const Vec3 n = (F * point.fiber).normalized();
    const Mat3 direction = n * point.fiber.transpose();
    const Eigen::Map<const Vec9> d(direction.data());
    CHECK(d.dot(K * d) < 0.0);
    CHECK(d.dot(K_projected * d) >= 0.0);
    CHECK(smallest_eigenvalue(K_projected) > -kPsdTolerance * K.cwiseAbs().maxCoeff());
}

TEST_CASE("mooney-rivlin-muscle: frame indifference and material symmetry", "[energies][muscle]")
{
    // ψ(QF) = ψ(F), P(QF) = Q P(F), ∂P/∂F(QF) = (I ⊗ Q) ∂P/∂F(F) (I ⊗ Q)ᵀ; and the
    // matrix is isotropic: ψ(F R, Rᵀa₀) = ψ(F, a₀). Rounding of two SVDs: 1e-10.
    for (FiberStretch stretch : kStretches) {
        const MooneyRivlinMuscle model(parameters(true, stretch));
        std::mt19937 rng(11 + static_cast<int>(stretch));
        for (sinew::test::Regime regime : sinew::test::all_regimes()) {
            for (int trial = 0; trial < 200; ++trial) {
                const Mat3 F = sinew::test::random_deformation<3, 3>(regime, rng);
                const Mat3 Q = sinew::test::random_rotation<3>(rng);
                const Mat3 R = sinew::test::random_rotation<3>(rng);
                const MaterialPoint<3> point = random_point(rng);
                MaterialPoint<3> turned = point;
                turned.fiber = R.transpose() * point.fiber;
                CAPTURE(sinew::test::regime_name(regime), F, Q, point.fiber);
                Stress P, P_rotated;
                Stiffness K, K_rotated;
                const double psi = model.evaluate(F, point, &P, &K, Projection::none);
                const double psi_rotated = model.evaluate(Q * F, point, &P_rotated, &K_rotated, Projection::none);
                REQUIRE(std::isfinite(psi));
                REQUIRE(std::isfinite(psi_rotated));
                CHECK(std::abs(psi_rotated - psi) <= 1e-12 * std::max(1.0, std::abs(psi)));
                CHECK(sinew::test::relative_difference(P_rotated, Q * P, 1e-10) < 1e-10);
                Stiffness IQ = Stiffness::Zero();
                for (int b = 0; b < 3; ++b)
                    IQ.block<3, 3>(3 * b, 3 * b) = Q;
                CHECK(sinew::test::relative_difference(K_rotated, IQ * K * IQ.transpose(), 1e-10) < 1e-10);
                CHECK(std::abs(model.energy(F * R, turned) - psi) <= 1e-12 * std::max(1.0, std::abs(psi)));
            }
        }
    }
}

TEST_CASE("mooney-rivlin-muscle: rest state", "[energies][muscle]")
{
    std::mt19937 rng(3);
    for (bool balanced : {false, true}) {
        for (FiberStretch stretch : kStretches) {
            CAPTURE(balanced, static_cast<int>(stretch));
            const ParameterValues values = parameters(balanced, stretch);
            const double scale = stress_scale(values);
            const MooneyRivlinMuscle muscle(values), matrix(without_fibers(values));
            // λ_opt ≥ 1 in both sets, so the passive curve is zero at rest.
            REQUIRE(muscle.passive_curve().evaluate(1.0).stress == 0.0);
            for (int trial = 0; trial < 50; ++trial) {
                MaterialPoint<3> point = random_point(rng);
                CAPTURE(point.fiber, point.activation);
                Stress P;
                Stiffness K;

                // Fiber terms off: ψ(I) = 0, P(I) = 0, ∂P/∂F(I) PSD, ψ minimal at I.
                const double psi_rest = matrix.evaluate(Mat3::Identity(), point, &P, &K, Projection::none);
                CHECK(std::abs(psi_rest - 3.0 * (all_parameters(values).at("A") + all_parameters(values).at("B"))) <=
                      1e-14 * scale);
                CHECK(P.cwiseAbs().maxCoeff() <= 1e-12 * scale);
                CHECK(smallest_eigenvalue(K) >= -1e-12 * scale);
                std::normal_distribution<double> normal;
                for (double size : {1e-3, 1e-2, 1e-1}) {
                    Mat3 E;
                    for (int i = 0; i < 9; ++i)
                        E.data()[i] = normal(rng);
                    const Mat3 F = Mat3::Identity() + size * E / E.norm();
                    CAPTURE(size, F);
                    CHECK(matrix.energy(F, point) >= psi_rest);
                }

                // Fibers on, α = 0: the passive curve is zero at rest, so P(I) = 0.
                point.activation = 0.0;
                muscle.evaluate(Mat3::Identity(), point, &P, nullptr, Projection::none);
                CHECK(P.cwiseAbs().maxCoeff() <= 1e-12 * scale);

                // Fibers on, α > 0: P(I) is the fiber stress at λ = 1 alone,
                // f(1) a₀a₀ᵀ (λ̃) or f(1)(a₀a₀ᵀ − I/3) (deviatoric λ).
                point.activation = 0.7;
                muscle.evaluate(Mat3::Identity(), point, &P, nullptr, Projection::none);
                const double f1 = point.activation * muscle.active_curve().evaluate(1.0).stress;
                REQUIRE(f1 > 0.0);
                Mat3 expected = f1 * point.fiber * point.fiber.transpose();
                if (stretch == FiberStretch::deviatoric)
                    expected -= f1 / 3.0 * Mat3::Identity();
                CHECK((P - expected).cwiseAbs().maxCoeff() <= 1e-12 * scale);
            }
        }
    }
}

TEST_CASE("mooney-rivlin-muscle: closed forms (uniaxial and volumetric)", "[energies][muscle]")
{
    // Uniaxial, isochoric: F = diag(s, s^-½, s^-½), J = 1: Ī₁ = s² + 2/s,
    // Ī₂ = 2s + 1/s², P₁₁ = (4/3)[A(s − s⁻²) + B(1 − s⁻³)], P₂₂ = P₃₃. A fiber
    // along e₁ adds f(s) (λ̃) or (2/3) f(s) (deviatoric: λ = s,
    // P_fiber = f(λ)λ(e₁e₁ᵀ/s − F⁻ᵀ/3)) to P₁₁.
    // Volumetric: F = sI: Ī₁ = 3, Ī₂ = 3, ψ = 3A + 3B + (K/2)(3 ln s)², P = (3K ln s/s) I.
    const double A = 1.0, B = 0.6, K = 8.0;
    for (FiberStretch stretch : kStretches) {
        const ParameterValues values = parameters(true, stretch);
        const MooneyRivlinMuscle matrix(without_fibers(values)), muscle(values);
        MaterialPoint<3> point;
        point.fiber = Vec3::UnitX();
        point.activation = 0.7;
        for (double s : {0.5, 0.8, 1.0, 1.25, 1.5, 2.0, 3.0}) {
            CAPTURE(static_cast<int>(stretch), s);
            const Mat3 F = Vec3(s, 1.0 / std::sqrt(s), 1.0 / std::sqrt(s)).asDiagonal();
            Stress P;
            const double psi = matrix.evaluate(F, point, &P, nullptr, Projection::none);
            CHECK(psi == Approx(A * (s * s + 2.0 / s) + B * (2.0 * s + 1.0 / (s * s))).epsilon(1e-13));
            CHECK(P(0, 0) == Approx(4.0 / 3.0 * (A * (s - 1.0 / (s * s)) + B * (1.0 - 1.0 / (s * s * s))))
                                 .epsilon(1e-12)
                                 .margin(1e-13));
            CHECK(P(1, 1) == Approx(P(2, 2)).epsilon(1e-13).margin(1e-13));
            CHECK(std::abs(P(0, 1)) + std::abs(P(1, 2)) + std::abs(P(0, 2)) + std::abs(P(1, 0)) < 1e-13);

            Stress P_muscle;
            muscle.evaluate(F, point, &P_muscle, nullptr, Projection::none);
            const double f = point.activation * muscle.active_curve().evaluate(s).stress +
                             muscle.passive_curve().evaluate(s).stress;
            const double fiber_part = stretch == FiberStretch::physbam ? f : 2.0 / 3.0 * f;
            CHECK(P_muscle(0, 0) - P(0, 0) == Approx(fiber_part).epsilon(1e-12).margin(1e-13));

            const Mat3 F_volume = s * Mat3::Identity();
            const double psi_volume = matrix.evaluate(F_volume, point, &P, nullptr, Projection::none);
            const double log_J = 3.0 * std::log(s);
            CHECK(psi_volume == Approx(3.0 * A + 3.0 * B + 0.5 * K * log_J * log_J).epsilon(1e-13));
            CHECK((P - K * log_J / s * Mat3::Identity()).cwiseAbs().maxCoeff() < 1e-12 * K);
        }
    }
}

TEST_CASE("mooney-rivlin-muscle: fiber terms off equal the pure Mooney-Rivlin part", "[energies][muscle]")
{
    // sigma_max = 0 switches the fibers off entirely: ψ, P, ∂P/∂F equal the
    // Mooney-Rivlin formula written in F (§4.2, §4.3.5), whatever the fiber and
    // activation; so does a model with fibers but α = 0 and P1 = 0.
    for (FiberStretch stretch : kStretches) {
        for (bool balanced : {false, true}) {
            ParameterValues values = without_fibers(parameters(balanced, stretch));
            values["inversion_threshold"] = 0.0;  // pure ln J, also in the near-inversion regime
            const MooneyRivlinMuscle model(values);
            ParameterValues idle = parameters(balanced, stretch);
            idle["P1"] = 0.0;
            idle["inversion_threshold"] = 0.0;
            const MooneyRivlinMuscle idle_fibers(idle);
            const ParameterValues all = all_parameters(values);
            const double A = all.at("A"), B = all.at("B"), K = all.at("K");
            std::mt19937 rng(21 + balanced);
            for (sinew::test::Regime regime : sinew::test::all_regimes()) {
                for (int trial = 0; trial < 300; ++trial) {
                    const Mat3 F = sinew::test::random_deformation<3, 3>(regime, rng);
                    MaterialPoint<3> point = random_point(rng);
                    CAPTURE(sinew::test::regime_name(regime), F);
                    Stress P;
                    Stiffness dPdF;
                    const double psi = model.evaluate(F, point, &P, &dPdF, Projection::none);
                    REQUIRE(std::isfinite(psi));
                    // Rounding of the SVD and of F⁻¹ (condition ≤ 50 here).
                    CHECK(std::abs(psi - mooney_rivlin_energy(A, B, K, F)) <= 1e-12 * std::max(1.0, std::abs(psi)));
                    CHECK(sinew::test::relative_difference(P, mooney_rivlin_stress(A, B, K, F), 1e-10 * K) < 1e-10);
                    // Central differences of the reference P (h = 1e-6): as in the derivative test.
                    CHECK(sinew::test::relative_difference(dPdF, mooney_rivlin_stiffness(A, B, K, F, kStep), 1e-10 * K) <
                          kStiffnessTolerance);

                    point.activation = 0.0;
                    Stress P_idle;
                    Stiffness dPdF_idle;
                    CHECK(idle_fibers.evaluate(F, point, &P_idle, &dPdF_idle, Projection::none) == Approx(psi).epsilon(1e-14));
                    CHECK(sinew::test::relative_difference(P_idle, P, 1e-10 * K) < 1e-13);
                    CHECK(sinew::test::relative_difference(dPdF_idle, dPdF, 1e-10 * K) < 1e-13);
                }
            }
        }
    }
}

TEST_CASE("mooney-rivlin-muscle: finite and continuous through det F = 0 into inversion", "[energies][muscle]")
{
    // F(t) = R₁ diag(1.2, 0.9, t) R₂ᵀ, t from 0.4 to −0.4: σ₃ crosses c = 0.1,
    // det F crosses 0 at t = 0, and |t| < 0.9 keeps clear of the inverted tie.
    std::mt19937 rng(8);
    const Mat3 R1 = sinew::test::random_rotation<3>(rng), R2 = sinew::test::random_rotation<3>(rng);
    auto path = [&](double t) -> Mat3 { return R1 * Vec3(1.2, 0.9, t).asDiagonal() * R2.transpose(); };
    const Mat3 dF = R1 * Vec3(0.0, 0.0, 1.0).asDiagonal() * R2.transpose();  // dF/dt
    const Eigen::Map<const Vec9> rate_in(dF.data());
    REQUIRE(path(-0.4).determinant() < 0.0);
    for (bool balanced : {false, true}) {
        for (FiberStretch stretch : kStretches) {
            const ParameterValues values = parameters(balanced, stretch);
            const MooneyRivlinMuscle model(values);
            const double scale = stress_scale(values);
            MaterialPoint<3> point = random_point(rng);
            const int steps = 8000;
            const double h = 0.8 / steps;
            std::vector<double> psi(steps + 1);
            std::vector<Stress> P(steps + 1);
            double largest_rate = 0.0;  // max |dP/dt| = |∂P/∂F : dF/dt| along the path
            for (int k = 0; k <= steps; ++k) {
                const double t = 0.4 - k * h;
                Stiffness K;
                psi[k] = model.evaluate(path(t), point, &P[k], &K, Projection::none);
                CAPTURE(balanced, static_cast<int>(stretch), t);
                REQUIRE(std::isfinite(psi[k]));
                REQUIRE(P[k].allFinite());
                REQUIRE(K.allFinite());
                REQUIRE(model.energy(path(t), point) == psi[k]);
                largest_rate = std::max(largest_rate, (K * rate_in).cwiseAbs().maxCoeff());
            }
            for (int k = 1; k < steps; ++k) {
                CAPTURE(balanced, static_cast<int>(stretch), 0.4 - k * h);
                // ψ C¹: the central difference along the path is P : dF/dt to O(h²ψ''').
                const double slope_fd = (psi[k - 1] - psi[k + 1]) / (2 * h);
                const double slope = P[k].cwiseProduct(dF).sum();
                CHECK(std::abs(slope_fd - slope) <= 1e-3 * std::max(scale, std::abs(slope)));
                // P continuous: no step larger than the largest |dP/dt| allows.
                CHECK((P[k + 1] - P[k]).cwiseAbs().maxCoeff() <= 1.01 * h * largest_rate + 1e-12 * scale);
            }
        }
    }
}

TEST_CASE("mooney-rivlin-muscle: without threshold inverted F has infinite energy", "[energies][muscle]")
{
    const MooneyRivlinMuscle model({{"inversion_threshold", 0.0}});
    std::mt19937 rng(4);
    for (int trial = 0; trial < 100; ++trial) {
        const Mat3 F = random_inverted(rng);
        const MaterialPoint<3> point = random_point(rng);
        Stress P;
        Stiffness K;
        CHECK(model.evaluate(F, point, &P, &K, Projection::clamp) == std::numeric_limits<double>::infinity());
        CHECK(model.energy(F, point) == std::numeric_limits<double>::infinity());
        CHECK(P.isZero());
        CHECK(K.isZero());
    }
    const Mat3 singular = Vec3(1.0, 1.0, 0.0).asDiagonal();
    CHECK(model.energy(singular, MaterialPoint<3>()) == std::numeric_limits<double>::infinity());
    Mat3 not_finite = Mat3::Identity();
    not_finite(1, 2) = std::nan("");
    Stress P;
    CHECK(MooneyRivlinMuscle({}).energy(not_finite, MaterialPoint<3>()) == std::numeric_limits<double>::infinity());
    CHECK(MooneyRivlinMuscle({}).evaluate(not_finite, MaterialPoint<3>(), &P, nullptr, Projection::none) ==
          std::numeric_limits<double>::infinity());
    CHECK(P.isZero());
}
