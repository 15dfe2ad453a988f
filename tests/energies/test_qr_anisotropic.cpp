// The QR-based anisotropic model of seed 004 §3 in 2D and 3D: ψ → P → ∂P/∂F
// against central differences in every deformation regime; the seed's own QR
// route as an independent reference (§3.1 sign convention and ψ(R), §3.2
// P = Q A R⁻ᵀ, §3.3–3.4 δP through ∂Q/∂F and ∂R/∂F); bounded stress as
// rᵢᵢ → 0 (§3.5); damage (§3.6); the PSD projection; frame indifference and
// material symmetry; rest state, closed forms, degenerate F and parameters.
#include "sinew/energies/models/qr_anisotropic.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/rotation_qr.hpp"
#include "energies/deformation_regimes.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

namespace {

using sinew::InputError;
using sinew::MaterialPoint;
using sinew::ParameterValues;
using sinew::Projection;
using sinew::QrAnisotropic;
using sinew::test::all_regimes;
using sinew::test::finite_difference_stiffness;
using sinew::test::finite_difference_stress;
using sinew::test::random_deformation;
using sinew::test::random_rotation;
using sinew::test::random_unit_vector;
using sinew::test::regime_name;
using sinew::test::relative_difference;

template <int Dim>
using Mat = Eigen::Matrix<double, Dim, Dim>;
template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;
template <int Dim>
using Stiffness = Eigen::Matrix<double, Dim * Dim, Dim * Dim>;

using Dim2 = std::integral_constant<int, 2>;
using Dim3 = std::integral_constant<int, 3>;

constexpr int kSamplesPerRegime = 1000;

struct Parameters {
    double mu = 1e4, lambda = 1e5, kx = 1e5, ky = 0.0, residual = 0.0;

    ParameterValues values() const
    {
        return {{"mu", mu}, {"lambda", lambda}, {"kx", kx}, {"ky", ky}, {"residual", residual}};
    }
    /// g(d) = (1 − d)²(1 − r) + r (seed 004 §3.6 with the residual r).
    double degradation(double d) const { return (1.0 - d) * (1.0 - d) * (1.0 - residual) + residual; }
    /// Sum of the moduli: the stress and stiffness scale of the model.
    double scale() const { return mu + lambda + kx + ky; }
};

/// μ log-uniform in [1e3, 1e6] Pa; λ/μ in [0.4, 50] (3D needs λ > μ/3) or
/// [0.05, 50] (2D); kx/μ and (3D) ky/μ in [0, 20]; the residual r = 0 (the
/// seed's g) half the time, else uniform in [0, 1].
template <int Dim>
Parameters random_parameters(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    Parameters p;
    p.mu = std::pow(10.0, 3.0 + 3.0 * u01(rng));
    p.lambda = p.mu * ((Dim == 3 ? 0.4 : 0.05) + 49.6 * u01(rng));
    p.kx = p.mu * 20.0 * u01(rng);
    p.ky = Dim == 3 ? p.mu * 20.0 * u01(rng) : 0.0;
    p.residual = u01(rng) < 0.5 ? 0.0 : u01(rng);
    return p;
}

/// A random unit fiber, damage uniform in [0, 1], activation too (unread).
template <int Dim>
MaterialPoint<Dim> random_point(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    MaterialPoint<Dim> point;
    point.fiber = random_unit_vector<Dim>(rng);
    point.damage = u01(rng);
    point.activation = u01(rng);
    return point;
}

template <int Dim>
QrAnisotropic<Dim> make_model(const Parameters& p)
{
    return QrAnisotropic<Dim>(p.values());
}

double min_eigenvalue(const Eigen::MatrixXd& H)
{
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H, Eigen::EigenvaluesOnly).eigenvalues()[0];
}

/// Rounding of P: a sum of terms up to degree 5 in F times the moduli
/// (β (J − 1) cof F) that cancel near rest, so errors reach ~ε·scale·max(1, |F|∞)⁵
/// (measured up to 2.3e-15 of it); 1e-13 leaves a margin of ~40.
template <int Dim>
double stress_rounding(const Parameters& p, const Mat<Dim>& F)
{
    return 1e-13 * p.scale() * std::pow(std::max(1.0, F.cwiseAbs().maxCoeff()), 5);
}

/// Rounding of ∂P/∂F or of a difference of two of them: degree 4 in F
/// (β cof F ⊗ cof F), and at least the size of the matrices themselves.
template <int Dim>
double stiffness_rounding(const Parameters& p, const Mat<Dim>& F, double largest_entry)
{
    return 1e-13 * std::max(p.scale() * std::pow(std::max(1.0, F.cwiseAbs().maxCoeff()), 4), largest_entry);
}

/// The coefficients of the degraded energy (seed 004 §3.6): g μ on the shear
/// terms always, g λ on the volume term for J ≥ 1 and λ for J < 1, g = (1 − d)²(1 − r) + r.
struct Degraded {
    double alpha, beta;
};

Degraded degrade(const Parameters& p, double d, double J)
{
    const double g = p.degradation(d);
    return {g * p.mu, (J >= 1.0 ? g : 1.0) * p.lambda};
}

// ---------------------------------------------------------------------------
// The seed's QR route, written out independently of the model.

/// Householder QR (Eigen) followed by the sign flips of seed 004 §3.1.
/// 2D: negate the whole Q and R when r₁₁ < 0. 3D: when r₁₁ < 0 flip r₁₁, r₁₂,
/// r₁₃, q₁, r₃₃, q₃; then when r₂₂ < 0 flip r₂₂, r₂₃, q₂, r₃₃, q₃. These flips
/// keep det Q, so a reflection stays one: `reflection_left` reports it, and
/// the last column of Q and row of R are then negated (our completion of the
/// convention: det Q = +1, so that Π rᵢᵢ = det F).
template <int Dim>
sinew::RotationQr<Dim> seed_qr(const Mat<Dim>& F, bool* reflection_left)
{
    const Eigen::HouseholderQR<Mat<Dim>> householder(F);
    Mat<Dim> Q = householder.householderQ();
    Mat<Dim> R = householder.matrixQR().template triangularView<Eigen::Upper>();
    if constexpr (Dim == 2) {
        if (R(0, 0) < 0.0) {
            Q = -Q;
            R = -R;
        }
    } else {
        if (R(0, 0) < 0.0) {
            R.row(0) *= -1.0;
            Q.col(0) *= -1.0;
            R(2, 2) *= -1.0;
            Q.col(2) *= -1.0;
        }
        if (R(1, 1) < 0.0) {
            R.row(1) *= -1.0;
            Q.col(1) *= -1.0;
            R(2, 2) *= -1.0;
            Q.col(2) *= -1.0;
        }
    }
    *reflection_left = Q.determinant() < 0.0;
    if (*reflection_left) {
        Q.col(Dim - 1) *= -1.0;
        R.row(Dim - 1) *= -1.0;
    }
    return {Q, R};
}

/// The three parts of Ψ̂(R) before degradation (seed 004 §3.1, §3.6):
/// Ψ^μ = μ/2 (Σ rᵢⱼ² − n) − μ (J − 1), Ψ^λ = λ/2 (J − 1)², Ψ^f the kx (and 3D ky) terms.
struct SeedParts {
    double shear, volume, fiber;
};

template <int Dim>
SeedParts seed_parts(const Mat<Dim>& R, const Parameters& p)
{
    const double J = R.diagonal().prod();
    SeedParts parts;
    parts.shear = 0.5 * p.mu * (R.squaredNorm() - Dim) - p.mu * (J - 1.0);
    parts.volume = 0.5 * p.lambda * (J - 1.0) * (J - 1.0);
    parts.fiber = 0.5 * p.kx * (R(0, 0) - 1.0) * (R(0, 0) - 1.0);
    if (Dim == 3) {
        const double s = std::sqrt(R(0, 1) * R(0, 1) + R(1, 1) * R(1, 1));
        parts.fiber += 0.5 * p.ky * (s - 1.0) * (s - 1.0);
    }
    return parts;
}

/// A number with a derivative, to differentiate A(R) exactly along δR.
struct Dual {
    double v = 0.0, d = 0.0;
};
Dual operator+(Dual a, Dual b) { return {a.v + b.v, a.d + b.d}; }
Dual operator-(Dual a, Dual b) { return {a.v - b.v, a.d - b.d}; }
Dual operator*(Dual a, Dual b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }
Dual operator/(Dual a, Dual b) { return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)}; }
Dual sqrt(Dual a)
{
    const double r = std::sqrt(a.v);
    return {r, a.d / (2.0 * r)};
}
using std::sqrt;

template <typename T, int Dim>
using Square = std::array<std::array<T, Dim>, Dim>;

/// A of seed 004 §3.2: M = ∂Ψ̂/∂R Rᵀ with ∂Ψ̂/∂R as the seed writes it (3D:
/// K₁, K₂, K₃ and the off-diagonal entries; 2D its own matrix), degraded by
/// μ → α, λ → β (§3.6); A holds the upper triangle of M, mirrored.
template <typename T, int Dim>
Square<T, Dim> seed_A(const Square<T, Dim>& r, const Degraded& c, const Parameters& p)
{
    const T one{1.0};
    const auto k = [](double value) { return T{value}; };
    Square<T, Dim> G{};  // ∂Ψ̂/∂R, upper triangular
    if constexpr (Dim == 2) {
        const T J = r[0][0] * r[1][1];
        G[0][0] = k(c.alpha) * (r[0][0] - r[1][1]) + k(c.beta) * (J - one) * r[1][1] + k(p.kx) * (r[0][0] - one);
        G[0][1] = k(c.alpha) * r[0][1];
        G[1][1] = k(c.alpha) * (r[1][1] - r[0][0]) + k(c.beta) * (J - one) * r[0][0];
    } else {
        const T J = r[0][0] * r[1][1] * r[2][2];
        const T s = sqrt(r[0][1] * r[0][1] + r[1][1] * r[1][1]);
        const T ky_factor = k(p.ky) * (one - one / s);
        // K₁, μ r₁₂ + ky r₁₂ (1 − 1/s), μ r₁₃; K₂, μ r₂₃; K₃.
        G[0][0] = k(c.alpha) * (r[0][0] - r[1][1] * r[2][2]) + k(c.beta) * (J - one) * r[1][1] * r[2][2] +
                  k(p.kx) * (r[0][0] - one);
        G[0][1] = k(c.alpha) * r[0][1] + r[0][1] * ky_factor;
        G[0][2] = k(c.alpha) * r[0][2];
        G[1][1] = k(c.alpha) * (r[1][1] - r[0][0] * r[2][2]) + k(c.beta) * (J - one) * r[2][2] * r[0][0] +
                  r[1][1] * ky_factor;
        G[1][2] = k(c.alpha) * r[1][2];
        G[2][2] = k(c.alpha) * (r[2][2] - r[0][0] * r[1][1]) + k(c.beta) * (J - one) * r[0][0] * r[1][1];
    }
    Square<T, Dim> A{};
    for (int i = 0; i < Dim; ++i)
        for (int j = i; j < Dim; ++j) {
            T m{0.0};  // M_ij = Σ_l G_il R_jl
            for (int l = j; l < Dim; ++l)
                m = m + G[i][l] * r[j][l];
            A[i][j] = m;
            A[j][i] = m;
        }
    return A;
}

template <int Dim>
Mat<Dim> seed_A_value(const Mat<Dim>& R, const Degraded& c, const Parameters& p)
{
    Square<double, Dim> r{};
    for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j)
            r[i][j] = R(i, j);
    const Square<double, Dim> A = seed_A<double, Dim>(r, c, p);
    Mat<Dim> out;
    for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j)
            out(i, j) = A[i][j];
    return out;
}

/// δA = (∂A/∂R)[δR], exactly, by dual numbers.
template <int Dim>
Mat<Dim> seed_A_differential(const Mat<Dim>& R, const Mat<Dim>& dR, const Degraded& c, const Parameters& p)
{
    Square<Dual, Dim> r{};
    for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j)
            r[i][j] = Dual{R(i, j), dR(i, j)};
    const Square<Dual, Dim> A = seed_A<Dual, Dim>(r, c, p);
    Mat<Dim> out;
    for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j)
            out(i, j) = A[i][j].d;
    return out;
}

/// P = Q A R⁻ᵀ Bᵀ, literally as seed 004 §3.2 writes it (divides by the rᵢᵢ).
template <int Dim>
Mat<Dim> seed_stress(const Mat<Dim>& F, const MaterialPoint<Dim>& point, const Parameters& p)
{
    const Mat<Dim> B = QrAnisotropic<Dim>::material_frame(point.fiber);
    const sinew::RotationQr<Dim> qr = sinew::rotation_qr<Dim>(F * B);
    const Degraded c = degrade(p, point.damage, qr.R.diagonal().prod());
    return qr.Q * seed_A_value<Dim>(qr.R, c, p) * qr.R.inverse().transpose() * B.transpose();
}

/// ∂P/∂F by the seed's chain (§3.3–3.4): for each direction δF = E_kl, with
/// F̃ = F B, δQ and δR from rotation_qr_differential (∂Q/∂F through Ω,
/// ∂R/∂F = ∂Qᵀ/∂F F + Qᵀ ∂F/∂F), δA from A(R) exactly, and the three terms
/// δP̃ = −Q δQᵀ P̃ + Q δA R⁻ᵀ − P̃ δRᵀ R⁻ᵀ.
template <int Dim>
Stiffness<Dim> seed_stiffness(const Mat<Dim>& F, const MaterialPoint<Dim>& point, const Parameters& p)
{
    const Mat<Dim> B = QrAnisotropic<Dim>::material_frame(point.fiber);
    const sinew::RotationQr<Dim> qr = sinew::rotation_qr<Dim>(F * B);
    const Degraded c = degrade(p, point.damage, qr.R.diagonal().prod());
    const Mat<Dim> A = seed_A_value<Dim>(qr.R, c, p);
    const Mat<Dim> R_inverse_transpose = qr.R.inverse().transpose();
    const Mat<Dim> P_tilde = qr.Q * A * R_inverse_transpose;
    Stiffness<Dim> H;
    for (int column = 0; column < Dim * Dim; ++column) {
        Mat<Dim> dF = Mat<Dim>::Zero();
        dF.data()[column] = 1.0;
        const sinew::RotationQrDifferential<Dim> dqr = sinew::rotation_qr_differential<Dim>(qr, dF * B);
        const Mat<Dim> dA = seed_A_differential<Dim>(qr.R, dqr.dR, c, p);
        const Mat<Dim> dP_tilde = -qr.Q * dqr.dQ.transpose() * P_tilde + qr.Q * dA * R_inverse_transpose -
                                  P_tilde * dqr.dR.transpose() * R_inverse_transpose;
        const Mat<Dim> dP = dP_tilde * B.transpose();
        H.col(column) = Eigen::Map<const Vec<Dim * Dim>>(dP.data());
    }
    return H;
}

/// The kx (and ky) part of the model in closed form from its definition,
/// k/2 (‖F a‖ − 1)²: value, P = k (r − 1) q aᵀ and ∂P/∂F = (a aᵀ) ⊗ k[q qᵀ + (1 − 1/r)(I − q qᵀ)].
template <int Dim>
struct FiberReference {
    double psi = 0.0;
    Mat<Dim> P = Mat<Dim>::Zero();
    Stiffness<Dim> H = Stiffness<Dim>::Zero();

    void add(double k, const Vec<Dim>& a, const Mat<Dim>& F)
    {
        const Vec<Dim> image = F * a;
        const double r = image.norm();
        const Vec<Dim> q = image / r;
        psi += 0.5 * k * (r - 1.0) * (r - 1.0);
        P += k * (r - 1.0) * q * a.transpose();
        const Mat<Dim> block = k * (q * q.transpose() + (1.0 - 1.0 / r) * (Mat<Dim>::Identity() - q * q.transpose()));
        for (int j = 0; j < Dim; ++j)
            for (int l = 0; l < Dim; ++l)
                H.template block<Dim, Dim>(Dim * j, Dim * l) += a(j) * a(l) * block;
    }
};

template <int Dim>
FiberReference<Dim> fiber_reference(const Mat<Dim>& F, const MaterialPoint<Dim>& point, const Parameters& p)
{
    const Mat<Dim> B = QrAnisotropic<Dim>::material_frame(point.fiber);
    FiberReference<Dim> out;
    out.add(p.kx, B.col(0), F);
    if (Dim == 3)
        out.add(p.ky, B.col(1), F);
    return out;
}

/// Where a central difference with step h ~ 1e-6 is valid: ∂P/∂F jumps at
/// J = 1 when 0 < d (seed §3.6 switches the degradation of Ψ^λ there; ψ is
/// C¹ but not C²), so F with |J − 1| < 1e-4 and d > 0 are skipped.
template <int Dim>
bool near_degradation_switch(const Mat<Dim>& F, double damage)
{
    return damage > 0.0 && std::abs(F.determinant() - 1.0) < 1e-4;
}

// Tolerances of the central-difference checks, relative to max(|FD|∞, 1e-8·scale)
// (scale = μ + λ + kx + ky, a floor for entries that vanish). Step h = 1e-6·max(1, |F|∞):
// truncation O(h²) times a third derivative that the fiber terms make as large as
// k/r³ (r ≥ 0.02 here) stays ≲ 1e-7 relative; rounding ε·|terms of ψ|/h relative to
// |P| ≈ modulus × strain is ≲ 2e-7 for strains ≥ 1e-3. Observed worst over 6000
// samples per shape: 7e-8 (P, 2D near rest), 1.2e-9 (∂P/∂F). A wrong term is an
// O(1) relative error.
constexpr double kStressTolerance = 1e-6;
constexpr double kStiffnessTolerance = 1e-6;

template <int Dim>
void check_derivatives(const QrAnisotropic<Dim>& model, const Mat<Dim>& F, const MaterialPoint<Dim>& point,
                       double scale)
{
    Mat<Dim> P;
    Stiffness<Dim> H;
    const double psi = model.evaluate(F, point, &P, &H, Projection::none);
    REQUIRE(std::isfinite(psi));
    REQUIRE(P.allFinite());
    REQUIRE(H.allFinite());
    const Mat<Dim> P_fd = finite_difference_stress<Dim, Dim>(model, F, point, 1e-6);
    const Stiffness<Dim> H_fd = finite_difference_stiffness<Dim, Dim>(model, F, point, 1e-6);
    REQUIRE(P_fd.allFinite());
    REQUIRE(H_fd.allFinite());
    REQUIRE(H_fd.norm() > 0.0);
    CHECK(relative_difference(P, P_fd, 1e-8 * scale) < kStressTolerance);
    CHECK(relative_difference(H, H_fd, 1e-8 * scale) < kStiffnessTolerance);
}

} // namespace

TEMPLATE_TEST_CASE("qr anisotropic: P and dP/dF match central differences in every regime",
                   "[energies][qr-anisotropic]", Dim2, Dim3)
{
    constexpr int Dim = TestType::value;
    std::mt19937 rng(400 + Dim);
    int skipped = 0;
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Parameters p = random_parameters<Dim>(rng);
            const MaterialPoint<Dim> point = random_point<Dim>(rng);
            const Mat<Dim> F = random_deformation<Dim, Dim>(regime, rng);
            CAPTURE(regime_name(regime), sample, p.mu, p.lambda, p.kx, p.ky, point.fiber, point.damage, F);
            if (near_degradation_switch<Dim>(F, point.damage)) {
                ++skipped;
                continue;
            }
            check_derivatives<Dim>(make_model<Dim>(p), F, point, p.scale());
        }
    }
    CHECK(skipped < 60);  // 1% of the samples at most
}

TEMPLATE_TEST_CASE("qr anisotropic: the seed's QR route gives the same psi, P and dP/dF",
                   "[energies][qr-anisotropic]", Dim2, Dim3)
{
    // ψ from §3.1 on a Householder QR with the §3.1 flips; P = Q A R⁻ᵀ Bᵀ (§3.2)
    // with the seed's ∂Ψ̂/∂R; ∂P/∂F by the §3.3–3.4 chain. All three divide by
    // the rᵢᵢ, which are ≥ ~0.005 in these regimes: rounding ≲ 1e-13 relative.
    constexpr int Dim = TestType::value;
    std::mt19937 rng(410 + Dim);
    int reflections = 0;
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Parameters p = random_parameters<Dim>(rng);
            const MaterialPoint<Dim> point = random_point<Dim>(rng);
            const Mat<Dim> F = random_deformation<Dim, Dim>(regime, rng);
            CAPTURE(regime_name(regime), sample, p.mu, p.lambda, p.kx, p.ky, point.fiber, point.damage, F);
            const QrAnisotropic<Dim> model = make_model<Dim>(p);
            const Mat<Dim> B = QrAnisotropic<Dim>::material_frame(point.fiber);
            bool reflection_left = false;
            const sinew::RotationQr<Dim> reference = seed_qr<Dim>(F * B, &reflection_left);
            reflections += reflection_left;
            const double J = reference.R.diagonal().prod();
            const Degraded c = degrade(p, point.damage, J);
            const SeedParts parts = seed_parts<Dim>(reference.R, p);
            const double g = p.degradation(point.damage);
            const double psi_seed = g * parts.shear + c.beta / p.lambda * parts.volume + parts.fiber;
            Mat<Dim> P;
            Stiffness<Dim> H;
            const double psi = model.evaluate(F, point, &P, &H, Projection::none);
            const double energy_scale = p.scale() * std::pow(std::max(1.0, F.norm()), 6);
            CHECK(std::abs(psi - psi_seed) <= 1e-12 * energy_scale);
            const Mat<Dim> P_seed = seed_stress<Dim>(F, point, p);
            CHECK(relative_difference(P, P_seed, 1e-8 * p.scale()) < 1e-9);
            const Stiffness<Dim> H_seed = seed_stiffness<Dim>(F, point, p);
            CHECK(relative_difference(H, H_seed, 1e-8 * p.scale()) < 1e-9);
        }
    }
    // The seed's flips keep det Q: a Householder QR in 2D is one reflection, so the
    // rule alone leaves det Q = −1 (and Π rᵢᵢ = −det F); the completion is needed.
    if (Dim == 2)
        CHECK(reflections == 6 * kSamplesPerRegime);
}

TEMPLATE_TEST_CASE("qr anisotropic: rotation_qr follows the seed's sign convention and its differential is right",
                   "[energies][qr-anisotropic]", Dim2, Dim3)
{
    constexpr int Dim = TestType::value;
    std::mt19937 rng(420 + Dim);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Mat<Dim> F = random_deformation<Dim, Dim>(regime, rng);
            CAPTURE(regime_name(regime), sample, F);
            const sinew::RotationQr<Dim> qr = sinew::rotation_qr<Dim>(F);
            const double scale = std::max(1.0, F.cwiseAbs().maxCoeff());
            CHECK((qr.Q * qr.R - F).cwiseAbs().maxCoeff() <= 1e-14 * scale);
            CHECK((qr.Q.transpose() * qr.Q - Mat<Dim>::Identity()).cwiseAbs().maxCoeff() <= 1e-14);
            CHECK(std::abs(qr.Q.determinant() - 1.0) <= 1e-14);
            for (int j = 0; j < Dim; ++j)
                for (int i = j + 1; i < Dim; ++i)
                    CHECK(qr.R(i, j) == 0.0);
            CHECK(qr.R(0, 0) >= 0.0);
            if (Dim == 3)
                CHECK(qr.R(1, 1) >= 0.0);
            CHECK(std::abs(qr.R.diagonal().prod() - F.determinant()) <= 1e-13 * std::pow(scale, Dim));
            bool reflection_left = false;
            const sinew::RotationQr<Dim> reference = seed_qr<Dim>(F, &reflection_left);
            CHECK((qr.R - reference.R).cwiseAbs().maxCoeff() <= 1e-12 * scale);
            CHECK((qr.Q - reference.Q).cwiseAbs().maxCoeff() <= 1e-10);
            // δQ, δR against central differences of rotation_qr (step 1e-6; the
            // truncation error is O(h²/r²) with r ≥ ~0.005 here).
            Mat<Dim> dF;
            for (int k = 0; k < Dim * Dim; ++k)
                dF.data()[k] = std::normal_distribution<double>()(rng);
            const sinew::RotationQrDifferential<Dim> d = sinew::rotation_qr_differential<Dim>(qr, dF);
            const double h = 1e-6;
            const sinew::RotationQr<Dim> plus = sinew::rotation_qr<Dim>(F + h * dF);
            const sinew::RotationQr<Dim> minus = sinew::rotation_qr<Dim>(F - h * dF);
            const Mat<Dim> dQ_fd = (plus.Q - minus.Q) / (2.0 * h);
            const Mat<Dim> dR_fd = (plus.R - minus.R) / (2.0 * h);
            CHECK(relative_difference(d.dQ, dQ_fd, 1.0) < 1e-5);
            CHECK(relative_difference(d.dR, dR_fd, 1.0) < 1e-5);
            CHECK((qr.Q.transpose() * d.dQ + d.dQ.transpose() * qr.Q).cwiseAbs().maxCoeff() <= 1e-10 * d.dQ.norm());
            CHECK((d.dQ * qr.R + qr.Q * d.dR - dF).cwiseAbs().maxCoeff() <= 1e-12 * dF.norm() * scale / qr.R(0, 0));
        }
    }
}

TEMPLATE_TEST_CASE("qr anisotropic: dP/dF is symmetric and its projection is PSD, equal to it when PSD",
                   "[energies][qr-anisotropic]", Dim2, Dim3)
{
    constexpr int Dim = TestType::value;
    std::mt19937 rng(430 + Dim);
    int projected = 0, unchanged = 0;
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Parameters p = random_parameters<Dim>(rng);
            const MaterialPoint<Dim> point = random_point<Dim>(rng);
            const Mat<Dim> F = random_deformation<Dim, Dim>(regime, rng);
            CAPTURE(regime_name(regime), sample, p.mu, p.lambda, p.kx, p.ky, point.fiber, point.damage, F);
            const QrAnisotropic<Dim> model = make_model<Dim>(p);
            Stiffness<Dim> H, H_clamped;
            Mat<Dim> P, P_clamped;
            const double psi = model.evaluate(F, point, &P, &H, Projection::none);
            const double psi_clamped = model.evaluate(F, point, &P_clamped, &H_clamped, Projection::clamp);
            REQUIRE(H_clamped.allFinite());
            CHECK(psi_clamped == psi);
            CHECK(P_clamped == P);
            const double scale = H.cwiseAbs().maxCoeff();
            REQUIRE(scale > 0.0);
            // Symmetric up to the rounding of the assembled sums.
            CHECK((H - H.transpose()).cwiseAbs().maxCoeff() <= 1e-13 * scale);
            CHECK((H_clamped - H_clamped.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale);
            // PSD up to rounding of the SVD-based modes.
            CHECK(min_eigenvalue(H_clamped) >= -1e-9 * scale);
            // The projection only adds stiffness: H_clamped − H is PSD.
            CHECK(min_eigenvalue(H_clamped - H) >= -1e-9 * scale);
            if (min_eigenvalue(H) >= 0.0) {
                ++unchanged;
                CHECK(H_clamped == H);
            } else {
                ++projected;
                if (Dim == 2) {
                    // 2D: the nearest PSD matrix, as a reference eigen-decomposition gives it.
                    const Eigen::SelfAdjointEigenSolver<Stiffness<Dim>> eigen(H);
                    const Stiffness<Dim> nearest =
                        eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
                    CHECK(relative_difference(H_clamped, nearest, scale) < 1e-12);
                }
            }
        }
    }
    // Both branches were exercised.
    CHECK(projected > 100);
    CHECK(unchanged > 100);
}

TEMPLATE_TEST_CASE("qr anisotropic: frame indifference and independence of the material frame's completion",
                   "[energies][qr-anisotropic]", Dim2, Dim3)
{
    constexpr int Dim = TestType::value;
    std::mt19937 rng(440 + Dim);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            Parameters p = random_parameters<Dim>(rng);
            const MaterialPoint<Dim> point = random_point<Dim>(rng);
            const Mat<Dim> F = random_deformation<Dim, Dim>(regime, rng);
            const Mat<Dim> Q = random_rotation<Dim>(rng);
            CAPTURE(regime_name(regime), sample, p.mu, p.lambda, p.kx, p.ky, point.fiber, point.damage, F, Q);
            const double energy_scale = p.scale() * std::pow(std::max(1.0, F.norm()), 6);
            // ψ(QF) = ψ(F), P(QF) = Q P(F).
            {
                const QrAnisotropic<Dim> model = make_model<Dim>(p);
                Mat<Dim> P, P_rotated;
                const double psi = model.evaluate(F, point, &P, nullptr, Projection::none);
                const double psi_rotated = model.evaluate(Q * F, point, &P_rotated, nullptr, Projection::none);
                CHECK(std::abs(psi_rotated - psi) <= 1e-13 * energy_scale);
                CHECK((P_rotated - Q * P).cwiseAbs().maxCoeff() <= stress_rounding<Dim>(p, F));
            }
            // Transverse isotropy when ky = 0: only a₀ matters, not how B completes it.
            // Re-describing the body by a rotation G of material space, F → F G with the
            // fiber Gᵀa₀, changes nothing (and ±a₀ is the same fiber).
            p.ky = 0.0;
            const QrAnisotropic<Dim> model = make_model<Dim>(p);
            const Mat<Dim> G = random_rotation<Dim>(rng);
            MaterialPoint<Dim> turned = point, reversed = point;
            turned.fiber = G.transpose() * point.fiber;
            reversed.fiber = -point.fiber;
            Mat<Dim> P, P_turned;
            const double psi = model.evaluate(F, point, &P, nullptr, Projection::none);
            const double psi_turned = model.evaluate(F * G, turned, &P_turned, nullptr, Projection::none);
            CHECK(std::abs(psi_turned - psi) <= 1e-13 * energy_scale);
            CHECK((P_turned - P * G).cwiseAbs().maxCoeff() <= stress_rounding<Dim>(p, F));
            CHECK(std::abs(model.energy(F, reversed) - psi) <= 1e-13 * energy_scale);
        }
    }
}

TEST_CASE("qr anisotropic: in 3D the ky term reads the frame's second axis b2", "[energies][qr-anisotropic]")
{
    // ψ's ky term is ky/2 (‖F b₂‖ − 1)² with b₂ = material_frame(a₀) e₂: a stretch
    // along b₂ costs it, one along b₃ = a₀ × b₂ does not. So with ky > 0 the
    // model is orthotropic and depends on the frame convention, not on a₀ alone.
    std::mt19937 rng(450);
    const Parameters p{1e4, 1e5, 2e5, 3e5};
    const QrAnisotropic<3> model = make_model<3>(p);
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        MaterialPoint<3> point;
        point.fiber = random_unit_vector<3>(rng);
        const Mat<3> B = QrAnisotropic<3>::material_frame(point.fiber);
        CAPTURE(sample, point.fiber);
        const double t = 1.5;
        const Mat<3> along_b2 = Mat<3>::Identity() + (t - 1.0) * B.col(1) * B.col(1).transpose();
        const Mat<3> along_b3 = Mat<3>::Identity() + (t - 1.0) * B.col(2) * B.col(2).transpose();
        // Uniaxial stretch t across the fiber: J = t, ‖F‖² = t² + 2, so the isotropic
        // part is (μ + λ)/2 (t − 1)² either way; only b₂ adds ky/2 (t − 1)².
        const double isotropic = 0.5 * (p.mu + p.lambda) * (t - 1.0) * (t - 1.0);
        CHECK(model.energy(along_b2, point) == Approx(isotropic + 0.5 * p.ky * (t - 1.0) * (t - 1.0)).epsilon(1e-12));
        CHECK(model.energy(along_b3, point) == Approx(isotropic).epsilon(1e-12));
    }
}

TEST_CASE("qr anisotropic: the material frame", "[energies][qr-anisotropic]")
{
    std::mt19937 rng(460);
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const Vec<3> a = random_unit_vector<3>(rng);
        CAPTURE(sample, a);
        const Mat<3> B = QrAnisotropic<3>::material_frame(2.5 * a);  // normalized first
        // Rounding only: normalizing moves a unit vector by an ulp or two.
        CHECK((B.transpose() * B - Mat<3>::Identity()).cwiseAbs().maxCoeff() <= 1e-15);
        CHECK(std::abs(B.determinant() - 1.0) <= 1e-15);
        CHECK((B.col(0) - a).cwiseAbs().maxCoeff() <= 4e-16);
        // The smallest rotation taking e₁ to a: its axis e₁ × a is fixed by B.
        const Vec<3> axis = Vec<3>::UnitX().cross(a);
        CHECK((B * axis - axis).cwiseAbs().maxCoeff() <= 1e-15);
        const Vec<2> a2 = random_unit_vector<2>(rng);
        const Mat<2> B2 = QrAnisotropic<2>::material_frame(a2);
        CHECK((B2.col(0) - a2).cwiseAbs().maxCoeff() <= 4e-16);
        CHECK((B2.col(1) - Vec<2>(-a2.y(), a2.x())).cwiseAbs().maxCoeff() <= 4e-16);
    }
    CHECK(QrAnisotropic<3>::material_frame(Vec<3>::UnitX()) == Mat<3>::Identity());
    const Mat<3> flipped = QrAnisotropic<3>::material_frame(-Vec<3>::UnitX());
    CHECK(flipped == Vec<3>(-1.0, 1.0, -1.0).asDiagonal().toDenseMatrix());  // half turn about e₂
    // Near a₀ = −e₁ (a_x ≤ 0 branch) the frame stays orthonormal.
    const Mat<3> near = QrAnisotropic<3>::material_frame(Vec<3>(-1.0, 1e-9, -2e-9));
    CHECK((near.transpose() * near - Mat<3>::Identity()).cwiseAbs().maxCoeff() <= 1e-15);
    CHECK_THROWS_AS(QrAnisotropic<3>::material_frame(Vec<3>::Zero()), InputError);
    CHECK_THROWS_AS(QrAnisotropic<2>::material_frame(Vec<2>(std::nan(""), 1.0)), InputError);
}

TEMPLATE_TEST_CASE("qr anisotropic: rest state is stress free, the tangent is linear elasticity plus fibers",
                   "[energies][qr-anisotropic]", Dim2, Dim3)
{
    constexpr int Dim = TestType::value;
    std::mt19937 rng(470 + Dim);
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const Parameters p = random_parameters<Dim>(rng);
        const MaterialPoint<Dim> point = random_point<Dim>(rng);
        const QrAnisotropic<Dim> model = make_model<Dim>(p);
        CAPTURE(sample, p.mu, p.lambda, p.kx, p.ky, point.fiber, point.damage);
        // ψ(Q) = 0 and P(Q) = 0 at every rotation Q, I included.
        const Mat<Dim> Q = sample == 0 ? Mat<Dim>::Identity() : random_rotation<Dim>(rng);
        Mat<Dim> P;
        const double psi_rest = model.evaluate(Q, point, &P, nullptr, Projection::none);
        CHECK(std::abs(psi_rest) <= 1e-14 * p.scale());
        CHECK(P.cwiseAbs().maxCoeff() <= 1e-14 * p.scale());
        // ∂P/∂F(I) = g[μ(δᵢₖδⱼₗ + δᵢₗδⱼₖ) + (λ − μ)δᵢⱼδₖₗ] + kx aᵢaⱼaₖaₗ + ky bᵢbⱼbₖbₗ:
        // Lamé parameters (μ, λ − μ) for the isotropic part (J = 1 counts as tension,
        // so λ is degraded too), the fiber stiffnesses along a₀ and b₂.
        Stiffness<Dim> H, H_clamped;
        model.evaluate(Mat<Dim>::Identity(), point, nullptr, &H, Projection::none);
        model.evaluate(Mat<Dim>::Identity(), point, nullptr, &H_clamped, Projection::clamp);
        const Mat<Dim> B = QrAnisotropic<Dim>::material_frame(point.fiber);
        const Vec<Dim> a = B.col(0), b = B.col(1);
        const double g = p.degradation(point.damage);
        const double ky = Dim == 3 ? p.ky : 0.0;
        Stiffness<Dim> C;
        for (int i = 0; i < Dim; ++i)
            for (int j = 0; j < Dim; ++j)
                for (int k = 0; k < Dim; ++k)
                    for (int l = 0; l < Dim; ++l)
                        C(i + Dim * j, k + Dim * l) =
                            g * (p.mu * ((i == k && j == l) + (i == l && j == k)) +
                                 (p.lambda - p.mu) * (i == j && k == l)) +
                            p.kx * a(i) * a(j) * a(k) * a(l) + ky * b(i) * b(j) * b(k) * b(l);
        CHECK(relative_difference(H, C, p.scale()) < 1e-14);
        // PSD at rest (rotations are its zero modes), and the projection leaves it.
        CHECK(min_eigenvalue(H) >= -1e-12 * p.scale());
        CHECK(relative_difference(H_clamped, H, p.scale()) < 1e-14);
    }
}

TEMPLATE_TEST_CASE("qr anisotropic: psi >= psi(I) = 0 when lambda >= mu", "[energies][qr-anisotropic]", Dim2, Dim3)
{
    // The isotropic part is α/2 ‖F‖² − α(J − 1) + β/2 (J − 1)². With ‖F‖² ≥ n|J|^(2/n)
    // it is ≥ 0 for β ≥ α in 3D (2D: for every β ≥ 0), and the fiber terms are
    // squares. In 3D with μ/3 < λ < μ the rest state is only a local minimum:
    // ψ(0) = (λ − μ)/2 < 0 (checked below).
    constexpr int Dim = TestType::value;
    std::mt19937 rng(480 + Dim);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            Parameters p = random_parameters<Dim>(rng);
            p.lambda = std::max(p.lambda, p.mu);
            const MaterialPoint<Dim> point = random_point<Dim>(rng);
            const Mat<Dim> F = random_deformation<Dim, Dim>(regime, rng);
            CAPTURE(regime_name(regime), sample, p.mu, p.lambda, p.kx, p.ky, point.fiber, point.damage, F);
            CHECK(make_model<Dim>(p).energy(F, point) >= -1e-14 * p.scale());
            CHECK(make_model<Dim>(p).energy(-F, point) >= 0.0);  // inverted in 3D
        }
    }
    if (Dim == 3) {
        const Parameters soft{1e4, 0.5e4, 0.0, 0.0};
        CHECK(make_model<3>(soft).energy(Mat<3>::Zero(), MaterialPoint<3>{}) == Approx(0.5 * (soft.lambda - soft.mu)));
    }
}

TEMPLATE_TEST_CASE("qr anisotropic: uniaxial stretch along the fiber matches the closed form",
                   "[energies][qr-anisotropic]", Dim2, Dim3)
{
    // F = I + (t − 1) a₀a₀ᵀ: r₁₁ = t, J = t, ‖F‖² = t² + n − 1, ‖F b₂‖ = 1, so
    //   ψ = (g μ + β + kx)/2 (t − 1)²,
    //   P = (g μ + β + kx)(t − 1) a₀a₀ᵀ + (t − 1)(β t − g μ)(I − a₀a₀ᵀ),
    // with β = g λ for t ≥ 1 and λ for t < 1 (seed §3.6): along the fiber the
    // full modulus, across it the lateral stress of the volume term.
    constexpr int Dim = TestType::value;
    std::mt19937 rng(490 + Dim);
    const Parameters p{2e4, 9e4, 3e5, Dim == 3 ? 5e4 : 0.0, 0.1};
    const QrAnisotropic<Dim> model = make_model<Dim>(p);
    for (const double damage : {0.0, 0.3, 1.0}) {
        for (const double t : {0.1, 0.5, 0.9, 1.0, 1.1, 2.0, 4.0}) {
            MaterialPoint<Dim> point;
            point.fiber = random_unit_vector<Dim>(rng);
            point.damage = damage;
            const Vec<Dim> a = point.fiber;
            const Mat<Dim> along = a * a.transpose();
            const Mat<Dim> F = Mat<Dim>::Identity() + (t - 1.0) * along;
            const double g = p.degradation(damage);
            const double beta = (t >= 1.0 ? g : 1.0) * p.lambda;
            const double modulus = g * p.mu + beta + p.kx;
            const double psi_expected = 0.5 * modulus * (t - 1.0) * (t - 1.0);
            const Mat<Dim> P_expected =
                modulus * (t - 1.0) * along + (t - 1.0) * (beta * t - g * p.mu) * (Mat<Dim>::Identity() - along);
            CAPTURE(damage, t, a);
            Mat<Dim> P;
            const double psi = model.evaluate(F, point, &P, nullptr, Projection::none);
            CHECK(std::abs(psi - psi_expected) <= 1e-12 * std::max(p.scale() * 1e-6, psi_expected));
            CHECK((P - P_expected).cwiseAbs().maxCoeff() <= stress_rounding<Dim>(p, F));
            // P₁₁ in the fiber frame.
            CHECK(std::abs(a.dot(P * a) - modulus * (t - 1.0)) <= stress_rounding<Dim>(p, F));
        }
    }
}

TEMPLATE_TEST_CASE("qr anisotropic: damage degrades the tension part only, never the fibers",
                   "[energies][qr-anisotropic]", Dim2, Dim3)
{
    // Seed §3.6: ψ = g(d) Ψ⁺ + Ψ⁻ + Ψ^f, g = (1 − d)²(1 − r) + r, Ψ⁺ = Ψ^μ + Ψ^λ for J ≥ 1 and
    // Ψ^μ for J < 1, Ψ⁻ = Ψ^λ for J < 1 (0 for J ≥ 1). Checked against the seed
    // parts on the seed's QR, and: d = 0 is the undamaged energy; the fiber part
    // (ψ minus the same model with kx = ky = 0) does not depend on d, its P and
    // ∂P/∂F are the closed-form fiber ones; d = 1 leaves r Ψ⁺ + Ψ⁻ + Ψ^f.
    constexpr int Dim = TestType::value;
    std::mt19937 rng(500 + Dim);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Parameters p = random_parameters<Dim>(rng);
            Parameters no_fibers = p;
            no_fibers.kx = no_fibers.ky = 0.0;
            MaterialPoint<Dim> point = random_point<Dim>(rng);
            const Mat<Dim> F = random_deformation<Dim, Dim>(regime, rng);
            CAPTURE(regime_name(regime), sample, p.mu, p.lambda, p.kx, p.ky, point.fiber, point.damage, F);
            const QrAnisotropic<Dim> model = make_model<Dim>(p), isotropic = make_model<Dim>(no_fibers);
            const Mat<Dim> B = QrAnisotropic<Dim>::material_frame(point.fiber);
            bool reflection_left = false;
            const SeedParts parts = seed_parts<Dim>(seed_qr<Dim>(F * B, &reflection_left).R, p);
            const double J = F.determinant();
            const double tension = parts.shear + (J >= 1.0 ? parts.volume : 0.0);
            const double compression = J >= 1.0 ? 0.0 : parts.volume;
            const double energy_scale = p.scale() * std::pow(std::max(1.0, F.norm()), 6);
            const FiberReference<Dim> fiber = fiber_reference<Dim>(F, point, p);
            for (const double d : {point.damage, 0.0, 1.0}) {
                point.damage = d;
                const double g = p.degradation(d);
                CAPTURE(d);
                Mat<Dim> P, P_isotropic;
                Stiffness<Dim> H, H_isotropic;
                const double psi = model.evaluate(F, point, &P, &H, Projection::none);
                const double psi_isotropic = isotropic.evaluate(F, point, &P_isotropic, &H_isotropic, Projection::none);
                CHECK(std::abs(psi - (g * tension + compression + parts.fiber)) <= 1e-12 * energy_scale);
                if (d == 0.0)
                    CHECK(std::abs(psi - (parts.shear + parts.volume + parts.fiber)) <= 1e-12 * energy_scale);
                if (d == 1.0)  // g(1) = r: the residual share of the tension part
                    CHECK(std::abs(psi - (p.residual * tension + compression + parts.fiber)) <= 1e-12 * energy_scale);
                CHECK(std::abs((psi - psi_isotropic) - fiber.psi) <= 1e-12 * energy_scale);
                CHECK((P - P_isotropic - fiber.P).cwiseAbs().maxCoeff() <= stress_rounding<Dim>(p, F));
                CHECK((H - H_isotropic - fiber.H).cwiseAbs().maxCoeff() <=
                      stiffness_rounding<Dim>(p, F, H.cwiseAbs().maxCoeff()));
            }
        }
    }
}

TEMPLATE_TEST_CASE("qr anisotropic: P stays finite and bounded as r_ii -> 0 (seed 3.5)", "[energies][qr-anisotropic]",
                   Dim2, Dim3)
{
    // F = R upper triangular with one diagonal entry t → 0 (the last also −t,
    // through inversion), a₀ = e₁ so that B = I and F̃ = F = QR with Q = I exactly
    // (rotations change no norm; frame indifference is checked above). §3.5 shows
    // A R⁻ᵀ has no division left: P is a polynomial in R of degree ≤ 5 plus the
    // fiber forces k(r − 1) q aᵀ, whose direction q is fixed along these paths
    // (r₁₂ is kept away from 0 so that F b₂ keeps its direction as r₂₂ → 0).
    // So P(t) → P_limit linearly, |P(t) − P_limit| ≤ t · 10 (μ + λ + kx + ky)(1 + max|rᵢⱼ|)⁵.
    // At t = 0 exactly P is finite too; there, on the r₁₁ path, the fiber has no
    // direction (its force is −kx times any unit vector) and the model takes 0, so
    // P_limit = P(0) − kx e₁ e₁ᵀ on that path. The seed's literal Q A R⁻ᵀ agrees
    // where it can be evaluated and is not finite at t = 0.
    constexpr int Dim = TestType::value;
    std::mt19937 rng(510 + Dim);
    std::uniform_real_distribution<double> magnitude(0.2, 1.5), diagonal(0.3, 2.0), u01(0.0, 1.0);
    const std::vector<std::pair<int, double>> paths =
        Dim == 2 ? std::vector<std::pair<int, double>>{{0, 1.0}, {1, 1.0}, {1, -1.0}}
                 : std::vector<std::pair<int, double>>{{0, 1.0}, {1, 1.0}, {2, 1.0}, {2, -1.0}};
    for (int sample = 0; sample < 200; ++sample) {
        const Parameters p = random_parameters<Dim>(rng);
        MaterialPoint<Dim> point;
        point.damage = u01(rng);
        const QrAnisotropic<Dim> model = make_model<Dim>(p);
        Mat<Dim> R = Mat<Dim>::Zero();
        for (int j = 0; j < Dim; ++j) {
            R(j, j) = diagonal(rng);
            for (int i = 0; i < j; ++i)
                R(i, j) = (u01(rng) < 0.5 ? -1.0 : 1.0) * magnitude(rng);
        }
        const double bound_scale = 10.0 * p.scale() * std::pow(1.0 + R.cwiseAbs().maxCoeff(), 5);
        for (const auto& [index, sign] : paths) {
            const auto deformation = [&R, index = index, sign = sign](double t) {
                Mat<Dim> F = R;
                F(index, index) = sign * t;
                return F;
            };
            CAPTURE(sample, index, sign, p.mu, p.lambda, p.kx, p.ky, point.damage, R);
            Mat<Dim> P_limit;
            Stiffness<Dim> H0;
            REQUIRE(std::isfinite(model.evaluate(deformation(0.0), point, &P_limit, &H0, Projection::clamp)));
            REQUIRE(P_limit.allFinite());
            REQUIRE(H0.allFinite());
            CHECK(P_limit.cwiseAbs().maxCoeff() <= bound_scale);
            if (index == 0)
                P_limit(0, 0) -= p.kx;
            for (const double t : {1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
                CAPTURE(t);
                Mat<Dim> P;
                Stiffness<Dim> H;
                const double psi = model.evaluate(deformation(t), point, &P, &H, Projection::none);
                CHECK(std::isfinite(psi));
                CHECK(P.allFinite());
                CHECK(H.allFinite());  // finite, not bounded: a fiber's bending k(1 − 1/r) grows as r → 0
                CHECK((P - P_limit).cwiseAbs().maxCoeff() <= t * bound_scale);
                if (t >= 1e-4) {
                    // The seed's divisions amplify rounding like ε/t.
                    const Mat<Dim> P_seed = seed_stress<Dim>(deformation(t), point, p);
                    CHECK(relative_difference(P, P_seed, 1e-8 * p.scale()) < 1e-9);
                }
            }
            CHECK_FALSE(seed_stress<Dim>(deformation(0.0), point, p).allFinite());
        }
    }
}

TEMPLATE_TEST_CASE("qr anisotropic: finite for inverted and degenerate F", "[energies][qr-anisotropic]", Dim2, Dim3)
{
    constexpr int Dim = TestType::value;
    std::mt19937 rng(520 + Dim);
    const Parameters p{1e4, 1e5, 1e5, Dim == 3 ? 1e5 : 0.0};
    const QrAnisotropic<Dim> model = make_model<Dim>(p);
    MaterialPoint<Dim> point;
    point.fiber = random_unit_vector<Dim>(rng);
    point.damage = 0.4;
    const Mat<Dim> B = QrAnisotropic<Dim>::material_frame(point.fiber);
    // F = 0; rank one; the fiber image F a₀ = 0; (3D) F b₂ = 0; reflections; random.
    std::vector<Mat<Dim>> cases = {Mat<Dim>::Zero(), B.col(1) * B.col(1).transpose(),
                                   Mat<Dim>::Identity() - B.col(0) * B.col(0).transpose(), -Mat<Dim>::Identity()};
    if (Dim == 3)
        cases.push_back(Mat<Dim>::Identity() - B.col(1) * B.col(1).transpose());
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        Mat<Dim> F = random_deformation<Dim, Dim>(sinew::test::Regime::moderate, rng);
        F.col(0) *= -1.0;  // inverted
        cases.push_back(F);
    }
    for (const Mat<Dim>& F : cases) {
        CAPTURE(F);
        for (const auto projection : {Projection::none, Projection::clamp}) {
            Mat<Dim> P;
            Stiffness<Dim> H;
            CHECK(std::isfinite(model.evaluate(F, point, &P, &H, projection)));
            CHECK(std::isfinite(model.energy(F, point)));
            CHECK(P.allFinite());
            CHECK(H.allFinite());
        }
    }
}

TEMPLATE_TEST_CASE("qr anisotropic: parameters and invalid input", "[energies][qr-anisotropic]", Dim2, Dim3)
{
    constexpr int Dim = TestType::value;
    using Model = QrAnisotropic<Dim>;
    const auto specs = Model::parameter_specs();
    REQUIRE(specs.size() == 5);
    CHECK(specs[0].name == "mu");
    CHECK(specs[1].name == "lambda");
    CHECK(specs[2].name == "kx");
    CHECK(specs[3].name == "ky");
    CHECK(specs[4].name == "residual");
    for (size_t i = 0; i < 4; ++i)
        CHECK(specs[i].unit == "Pa");
    CHECK(specs[4].unit == "1");
    CHECK(specs[4].default_value == 0.0);
    CHECK(Model(ParameterValues{}).name() == "qr-anisotropic");
    CHECK(std::string(Model::kName) == "qr-anisotropic");
    // The same list in 2D and 3D, so that one model name serves both shapes.
    const auto other = QrAnisotropic<5 - Dim>::parameter_specs();
    for (size_t i = 0; i < specs.size(); ++i) {
        CHECK(other[i].name == specs[i].name);
        CHECK(other[i].default_value == specs[i].default_value);
    }
    const auto throws_naming = [](const ParameterValues& values, const std::string& name) {
        try {
            const Model model(values);
            (void)model;
        } catch (const InputError& error) {
            return std::string(error.what()).find(name) != std::string::npos;
        }
        return false;
    };
    CHECK(throws_naming({{"mu", 0.0}}, "mu"));
    CHECK(throws_naming({{"mu", -1.0}}, "mu"));
    CHECK(throws_naming({{"lambda", 0.0}}, "lambda"));
    CHECK(throws_naming({{"kx", -1.0}}, "kx"));
    CHECK(throws_naming({{"ky", -1.0}}, "ky"));
    CHECK(throws_naming({{"nu", 0.3}}, "nu"));
    CHECK(throws_naming({{"residual", -0.1}}, "residual"));
    CHECK(throws_naming({{"residual", 1.5}}, "residual"));
    CHECK(throws_naming({{"mu", std::numeric_limits<double>::infinity()}}, "mu"));
    if (Dim == 3) {
        CHECK(throws_naming({{"mu", 3e4}, {"lambda", 1e4}}, "lambda"));  // λ ≤ μ/3: no bulk modulus
        CHECK_NOTHROW(Model(ParameterValues{{"mu", 3e4}, {"lambda", 1.01e4}, {"ky", 1e5}}));
    } else {
        CHECK(throws_naming({{"ky", 1e4}}, "ky"));  // the seed's 2D energy has no ky term
        CHECK_NOTHROW(Model(ParameterValues{{"mu", 3e4}, {"lambda", 1e3}}));
    }
    const Model model(ParameterValues{});
    MaterialPoint<Dim> point;
    const Mat<Dim> F = Mat<Dim>::Identity();
    point.damage = 1.5;
    CHECK_THROWS_AS(model.energy(F, point), InputError);
    point.damage = -0.1;
    CHECK_THROWS_AS(model.energy(F, point), InputError);
    point.damage = 0.0;
    point.fiber.setZero();
    CHECK_THROWS_AS(model.energy(F, point), InputError);
    point.fiber = Vec<Dim>::Constant(2.0);  // not unit: normalized
    MaterialPoint<Dim> unit = point;
    unit.fiber.normalize();
    const Mat<Dim> G = Mat<Dim>::Identity() + 0.3 * Mat<Dim>::Ones();
    CHECK(model.energy(G, point) == Approx(model.energy(G, unit)).epsilon(1e-14));
}
