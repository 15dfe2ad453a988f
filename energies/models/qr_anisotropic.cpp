#include "sinew/energies/models/qr_anisotropic.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/determinant_derivatives.hpp"
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/isotropic_stiffness_modes.hpp"
#include "sinew/energies/models/svd_batch.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace sinew {
namespace {

constexpr const char* kModelName = "qr-anisotropic";

template <int Dim>
using Mat = Eigen::Matrix<double, Dim, Dim>;
template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;
template <int Dim>
using Hessian = Eigen::Matrix<double, Dim * Dim, Dim * Dim>;

/// Smallest stretch a fiber term divides by: below it a fiber has no length
/// left and its bending stiffness k(1 − 1/r) is kept finite.
constexpr double kMinFiberStretch = std::numeric_limits<double>::epsilon();

/// a₀/‖a₀‖; InputError for a zero or non-finite a₀.
template <int Dim>
Vec<Dim> unit_fiber(const Vec<Dim>& fiber)
{
    const double length = fiber.norm();
    if (!(length > 0.0) || !std::isfinite(length))
        throw InputError(std::string("model ") + kModelName + ": fiber direction a0 must be finite and non-zero");
    return fiber / length;
}

/// One fiber term k/2 (‖F a‖ − 1)² of seed 004 §3.1 at one F. With F̃ = F B = QR:
/// a = a₀ = B e₁ gives r = ‖F̃ e₁‖ = r₁₁ and q = Q e₁ (the kx term);
/// a = b₂ = B e₂ gives r = ‖F̃ e₂‖ = √(r₁₂² + r₂₂²) and q = Q R e₂/r (the ky term).
template <int Dim>
struct Fiber {
    double k = 0.0;                 ///< kx or ky, Pa
    Vec<Dim> a = Vec<Dim>::Zero();  ///< unit material direction
    Vec<Dim> q = Vec<Dim>::Zero();  ///< F a/r, the unit image (0 when r = 0, where it is undefined)
    double r = 1.0;                 ///< ‖F a‖, the stretch along a

    /// 1 − 1/r: the fiber's ∂P/∂F across q, divided by k; negative when compressed.
    double bending() const { return 1.0 - 1.0 / std::max(r, kMinFiberStretch); }
    bool has_negative_part() const { return k > 0.0 && bending() < 0.0; }
};

template <int Dim>
Fiber<Dim> make_fiber(double k, const Vec<Dim>& a, const Mat<Dim>& F)
{
    Fiber<Dim> fiber;
    fiber.k = k;
    fiber.a = a;
    const Vec<Dim> image = F * a;
    fiber.r = image.norm();
    if (fiber.r > 0.0)
        fiber.q = image / fiber.r;
    return fiber;
}

/// What ψ, P and ∂P/∂F share at one F.
template <int Dim>
struct QrState {
    Mat<Dim> cof;        ///< cof F = ∂J/∂F (= Q cof R Bᵀ)
    double J = 1.0;      ///< det F = Π rᵢᵢ (§3.2: the sign convention makes them equal)
    double alpha = 0.0;  ///< g μ: the shear terms Ψ^μ are always degraded (§3.6)
    double beta = 0.0;   ///< g_λ λ: Ψ^λ degraded for J ≥ 1 only (§3.6)
    double c = 0.0;      ///< β (J − 1) − α: the coefficient of ∂J/∂F in P
    Fiber<Dim> fiber;    ///< kx along a₀
    Fiber<Dim> second;   ///< ky along b₂ (3D with ky > 0; k = 0 otherwise)
};

template <int Dim>
QrState<Dim> make_state(const Mat<Dim>& F, const MaterialPoint<Dim>& point, double mu, double lambda, double kx,
                        double ky)
{
    const double d = point.damage;
    if (!(d >= 0.0 && d <= 1.0)) {
        std::ostringstream out;
        out << "model " << kModelName << ": damage d = " << d << " is outside [0, 1]";
        throw InputError(out.str());
    }
    QrState<Dim> st;
    if constexpr (Dim == 2)
        st.cof << F(1, 1), -F(1, 0), -F(0, 1), F(0, 0);
    else
        st.cof = determinant_gradient(F);
    st.J = F.col(0).dot(st.cof.col(0));
    const double g = (1.0 - d) * (1.0 - d);      // g(d) = (1 − d)², §3.6
    st.alpha = g * mu;                           // g Ψ^μ
    st.beta = (st.J >= 1.0 ? g : 1.0) * lambda;  // Ψ⁺ holds Ψ^λ for J ≥ 1, Ψ⁻ for J < 1
    st.c = st.beta * (st.J - 1.0) - st.alpha;
    if (Dim == 3 && ky > 0.0) {
        const Mat<Dim> B = QrAnisotropic<Dim>::material_frame(point.fiber);
        st.fiber = make_fiber<Dim>(kx, B.col(0), F);
        st.second = make_fiber<Dim>(ky, B.col(1), F);
    } else {
        st.fiber = make_fiber<Dim>(kx, unit_fiber<Dim>(point.fiber), F);
    }
    return st;
}

/// ψ = g Ψ^μ + g_λ Ψ^λ + Ψ^f (seed 004 §3.1, §3.6), with Σᵢⱼ rᵢⱼ² = ‖R‖² = ‖F‖²
/// (Q, B rotations) and Π rᵢᵢ = det F. The seed's "Σ rᵢⱼ² − d" subtracts the
/// dimension n = Dim (not the damage d).
template <int Dim>
double energy_of(const QrState<Dim>& st, const Mat<Dim>& F)
{
    const double Jm1 = st.J - 1.0;
    double psi = 0.5 * st.alpha * (F.squaredNorm() - Dim) - st.alpha * Jm1  // g Ψ^μ
                 + 0.5 * st.beta * Jm1 * Jm1;                                // g_λ Ψ^λ
    // Ψ^f = kx/2 (r₁₁ − 1)² + ky/2 (√(r₁₂² + r₂₂²) − 1)², never degraded
    for (const Fiber<Dim>* fiber : {&st.fiber, &st.second})
        psi += 0.5 * fiber->k * (fiber->r - 1.0) * (fiber->r - 1.0);
    return psi;
}

/// P = Q A R⁻ᵀ Bᵀ (seed 004 §3.2) in the division-free form §3.5 shows
/// exists. A R⁻ᵀ is, term by term, the gradient at X = R of ψ written in
/// X = Qᵀ F B: ½Σrᵢⱼ² → R, J → cof R = J R⁻ᵀ, r₁₁ = ‖X e₁‖ → e₁e₁ᵀ,
/// s = ‖X e₂‖ → (R e₂/s) e₂ᵀ; mapped back by Q(·)Bᵀ these are F, cof F,
/// q₁ a₀ᵀ (q₁ = F a₀/r₁₁) and q_b b₂ᵀ (q_b = F b₂/s). Bounded as any rᵢᵢ → 0:
/// polynomial in F plus fiber forces of size k|r − 1|.
template <int Dim>
Mat<Dim> stress_of(const QrState<Dim>& st, const Mat<Dim>& F)
{
    Mat<Dim> P = st.alpha * F + st.c * st.cof;  // g Ψ^μ + g_λ Ψ^λ
    for (const Fiber<Dim>* fiber : {&st.fiber, &st.second})
        P.noalias() += (fiber->k * (fiber->r - 1.0)) * fiber->q * fiber->a.transpose();  // k (r − 1) q aᵀ
    return P;
}

/// H += coefficient · (a aᵀ) ⊗ M on column-major vec(F): the block of
/// columns (j, l) of F is coefficient a_j a_l M.
template <int Dim>
void add_fiber_product(double coefficient, const Vec<Dim>& a, const Mat<Dim>& M, Hessian<Dim>& H)
{
    for (int l = 0; l < Dim; ++l)
        for (int j = 0; j < Dim; ++j)
            H.template block<Dim, Dim>(Dim * j, Dim * l) += (coefficient * a(j) * a(l)) * M;
}

/// ∂P/∂F of one fiber term, the seed's chain (§3.3–3.4) δP̃ = δQ (A R⁻ᵀ) + Q δ(A R⁻ᵀ)
/// for T = k (r − 1) e₁e₁ᵀ (the kx term; ky alike in its column): δQ turns the
/// image, δq = Q Ω e₁ = ω₃ q₂ − ω₂ q₃ = (I − q qᵀ) δF a/r (ω₃ r₁₁ = X₂₁,
/// −ω₂ r₁₁ = X₃₁, §3.4.2); δT changes the length, δr = q·δF a (∂R/∂F, §3.4.1).
/// Together (a aᵀ) ⊗ k [q qᵀ + (1 − 1/r)(I − q qᵀ)].
template <int Dim>
void add_fiber_stiffness(const Fiber<Dim>& fiber, Hessian<Dim>& H)
{
    if (fiber.k == 0.0)
        return;
    const double bending = fiber.bending();
    add_fiber_product<Dim>(fiber.k, fiber.a,
                           bending * Mat<Dim>::Identity() + (1.0 - bending) * (fiber.q * fiber.q.transpose()), H);
}

/// ∂P/∂F of g Ψ^μ + g_λ Ψ^λ = α/2 ‖F‖² − α(J − 1) + β/2 (J − 1)², a polynomial
/// in F: α 𝕀 + β vec(cof F) vec(cof F)ᵀ + c ∂²J/∂F². In the seed's chain (§3.3)
/// the δQ terms of this rotation-invariant part cancel against those of δ(A R⁻ᵀ);
/// this is what is left, with no division by rᵢᵢ.
template <int Dim>
void set_isotropic_stiffness(const QrState<Dim>& st, const Mat<Dim>& F, Hessian<Dim>& H)
{
    const Eigen::Map<const Vec<Dim * Dim>> cof(st.cof.data());  // vec(∂J/∂F)
    H.noalias() = st.beta * cof * cof.transpose();
    H.diagonal().array() += st.alpha;
    if constexpr (Dim == 2) {
        // ∂²J/∂F²: J = F₀₀F₁₁ − F₀₁F₁₀, vec indices F₀₀ 0, F₁₀ 1, F₀₁ 2, F₁₁ 3.
        H(0, 3) += st.c;
        H(3, 0) += st.c;
        H(1, 2) -= st.c;
        H(2, 1) -= st.c;
    } else {
        add_determinant_hessian(st.c, F, H);
    }
}

/// True when H + 1e-12 max|Hᵢⱼ| I has a Cholesky factorization: H is PSD up
/// to rounding (its smallest eigenvalue is above about −1e-12 max|Hᵢⱼ|).
template <int N>
bool is_positive_semidefinite(const Eigen::Matrix<double, N, N>& H)
{
    Eigen::Matrix<double, N, N> shifted = H;
    shifted.diagonal().array() += 1e-12 * H.cwiseAbs().maxCoeff();
    return Eigen::LLT<Eigen::Matrix<double, N, N>>(shifted).info() == Eigen::Success;
}

/// The spectrum of the isotropic part in F = U Σ Vᵀ (rotation-variant, signed
/// σ), as for stable Neo-Hookean (Smith et al. 2018 §4–5): with
/// ψᵢ = α σᵢ + c Jᵢ, twist α + c σₖ, flip α − c σₖ and the scaling block
/// α I + β ∇J ∇Jᵀ + c ∂²J/∂σ² (∂²J/∂σᵢ∂σⱼ = σₖ off the diagonal). No
/// division: exact at repeated and vanishing σ.
IsotropicStiffnessSpectrum isotropic_spectrum(const QrState<3>& st, const Eigen::Vector3d& sigma)
{
    IsotropicStiffnessSpectrum spectrum;
    spectrum.twist = Eigen::Vector3d::Constant(st.alpha) + st.c * sigma;
    spectrum.flip = Eigen::Vector3d::Constant(st.alpha) - st.c * sigma;
    const Eigen::Vector3d dJ(sigma[1] * sigma[2], sigma[0] * sigma[2], sigma[0] * sigma[1]);
    spectrum.scaling = st.beta * dJ * dJ.transpose();
    spectrum.scaling.diagonal().array() += st.alpha;
    spectrum.scaling(0, 1) += st.c * sigma[2];
    spectrum.scaling(0, 2) += st.c * sigma[1];
    spectrum.scaling(1, 2) += st.c * sigma[0];
    spectrum.scaling(1, 0) = spectrum.scaling(0, 1);
    spectrum.scaling(2, 0) = spectrum.scaling(0, 2);
    spectrum.scaling(2, 1) = spectrum.scaling(1, 2);
    return spectrum;
}

/// wᵀ K w for the fiber's block K = k [q qᵀ + (1 − 1/r)(I − q qᵀ)]: the
/// fiber term's quadratic form on vec(Y) is (Y a)ᵀ K (Y a).
double fiber_quadratic_form(const Fiber<3>& fiber, const Vec<3>& w)
{
    const double bending = fiber.bending(), along = fiber.q.dot(w);
    return fiber.k * (bending * w.squaredNorm() + (1.0 - bending) * along * along);
}

/// True when a cheap direction m proves H indefinite, mᵀ H m < −shift (then
/// H + shift·I has no Cholesky factorization either). Directions tried:
///  · per compressed fiber, m = vec(e aᵀ) with e a unit vector across q and
///    across cof F·a. On this rank-one direction ∂²J vanishes (det is affine
///    along F + t e aᵀ), so mᵀ H m = α + β (e·cof F a)² + Σ fibers (Y a_f)ᵀ K_f (Y a_f)
///    with Y a_f = (a·a_f) e, no product with H: the isotropic part gives
///    α (e·cof F a = 0 but for the fallback e), the fiber its bending k(1 − 1/r);
///  · each negative twist or flip mode Y = (uᵢvⱼᵀ ∓ uⱼvᵢᵀ)/√2 of the isotropic
///    part, an eigenvector of it: mᵀ H m = its eigenvalue + Σ fibers (Y a)ᵀ K (Y a).
bool proven_indefinite(double shift, const QrState<3>& st, const RotationVariantSvd<3>& svd,
                       const IsotropicStiffnessSpectrum& spectrum)
{
    const std::array<const Fiber<3>*, 2> fibers{&st.fiber, &st.second};
    for (const Fiber<3>* fiber : fibers) {
        if (!fiber->has_negative_part())
            continue;
        const Vec<3> image = st.cof * fiber->a;  // cof F a
        Vec<3> e = fiber->q.cross(image);
        if (!(e.squaredNorm() > 1e-24))
            e = detail::unit_orthogonal(fiber->q);
        e.normalize();
        const double along_cofactor = e.dot(image);
        double rayleigh = st.alpha + st.beta * along_cofactor * along_cofactor;
        for (const Fiber<3>* other : fibers)
            if (other->k != 0.0)
                rayleigh += fiber_quadratic_form(*other, fiber->a.dot(other->a) * e);
        if (rayleigh < -shift)
            return true;
    }
    for (int k = 0; k < 3; ++k) {
        int i = 0, j = 0;
        pair_of(k, i, j);
        for (const double sign : {-1.0, 1.0}) {  // twist, flip
            double rayleigh = sign < 0.0 ? spectrum.twist[k] : spectrum.flip[k];
            if (rayleigh >= 0.0)
                continue;
            for (const Fiber<3>* fiber : fibers) {
                if (fiber->k == 0.0)
                    continue;
                const Vec<3> Ya = std::sqrt(0.5) * (svd.V.col(j).dot(fiber->a) * svd.U.col(i) +
                                                    sign * svd.V.col(i).dot(fiber->a) * svd.U.col(j));
                rayleigh += fiber_quadratic_form(*fiber, Ya);
            }
            if (rayleigh < -shift)
                return true;
        }
    }
    return false;
}

/// Projection::clamp in 3D: H unchanged when it is PSD, otherwise the sum of
/// each term's PSD part: the isotropic part with its negative eigenvalues
/// clamped (clamp_correction), each fiber with its negative bending dropped.
/// PSD-ness is settled cheaply when possible: no term has a negative part
/// (then H is PSD), or a direction proves H indefinite; otherwise by a
/// Cholesky test of H + shift·I, shift = 1e-12 max|Hᵢⱼ|.
void clamp_3d(const QrState<3>& st, const RotationVariantSvd<3>& svd, Hessian<3>& H, DeferredRotation& deferred)
{
    const IsotropicStiffnessSpectrum spectrum = isotropic_spectrum(st, svd.sigma);
    const ModeCorrection correction = clamp_correction(spectrum);
    const bool isotropic_negative = correction.twist.any() || correction.flip.any() || correction.has_scaling;
    if (!isotropic_negative && !st.fiber.has_negative_part() && !st.second.has_negative_part())
        return;
    const double shift = 1e-12 * H.cwiseAbs().maxCoeff();
    if (!proven_indefinite(shift, st, svd, spectrum) && is_positive_semidefinite(H))
        return;
    deferred.add(frame_of(correction));
    // A fiber's negative part: k(1 − 1/r)(a aᵀ) ⊗ (I − q qᵀ), the bending of a compressed fiber.
    for (const Fiber<3>* fiber : {&st.fiber, &st.second})
        if (fiber->has_negative_part())
            add_fiber_product<3>(-fiber->k * fiber->bending(), fiber->a,
                                 Mat<3>::Identity() - fiber->q * fiber->q.transpose(), H);
}

/// Projection::clamp in 2D: H unchanged when it is PSD, otherwise the nearest
/// PSD matrix, V diag(max(λ, 0)) Vᵀ from the eigen-decomposition of the 4×4.
void clamp_2d(Hessian<2>& H)
{
    if (is_positive_semidefinite(H))
        return;
    const Eigen::SelfAdjointEigenSolver<Hessian<2>> eigen(H);
    H = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
}

ParameterSpec pascal_parameter(const std::string& name, double default_value, bool positive,
                               const std::string& description)
{
    // {name, default, unit, description, lower, upper, lower_exclusive, choices}
    return ParameterSpec{name, default_value, "Pa", description, 0.0, 1e300, positive, {}};
}

} // namespace

template <int Dim>
std::vector<ParameterSpec> QrAnisotropic<Dim>::parameter_specs()
{
    return {
        pascal_parameter("mu", 1.0e4, true,
                         "shear coefficient: multiplies (1/2)(sum r_ij^2 - n) - (J - 1) (seed 004 §3.1)"),
        pascal_parameter("lambda", 1.0e5, true,
                         "volume coefficient: multiplies (1/2)(J - 1)^2; small-strain Lame parameter is lambda - mu; "
                         "3D needs lambda > mu/3"),
        pascal_parameter("kx", 1.0e5, false, "fiber stiffness: multiplies (1/2)(r11 - 1)^2 = (1/2)(|F a0| - 1)^2"),
        pascal_parameter("ky", 0.0, false,
                         "3D only (0 in 2D): multiplies (1/2)(sqrt(r12^2 + r22^2) - 1)^2 = (1/2)(|F b2| - 1)^2, "
                         "b2 the material frame's second axis"),
    };
}

template <int Dim>
QrAnisotropic<Dim>::QrAnisotropic(const ParameterValues& values)
{
    const ParameterValues p = resolve_parameters(kName, parameter_specs(), values);
    mu_ = p.at("mu");
    lambda_ = p.at("lambda");
    kx_ = p.at("kx");
    ky_ = p.at("ky");
    std::ostringstream out;
    out << "model " << kName << ": ";
    if (Dim == 3 && !(lambda_ > mu_ / 3.0)) {
        // 3λ − μ is the eigenvalue of ∂P/∂F(I) on uniform dilation (d = 0).
        out << "parameter lambda = " << lambda_ << " must exceed mu/3 = " << mu_ / 3.0
            << " in 3D (the small-strain bulk modulus lambda - mu/3 must be positive)";
        throw InputError(out.str());
    }
    if (Dim == 2 && ky_ != 0.0) {
        out << "parameter ky = " << ky_ << " must be 0 in 2D (seed 004 §3.1: the 2D energy has only the kx term)";
        throw InputError(out.str());
    }
}

template <int Dim>
typename QrAnisotropic<Dim>::Matrix QrAnisotropic<Dim>::material_frame(const Vector& fiber)
{
    const Vector a = unit_fiber<Dim>(fiber);
    Matrix B;
    if constexpr (Dim == 2) {
        B << a.x(), -a.y(), a.y(), a.x();
    } else {
        // Rodrigues rotation about e₁ × a by the angle between e₁ and a, applied to e₂:
        // b₂ = (−a_y, 1 − a_y² t, −a_y a_z t) with t = 1/(1 + a_x), written
        // t = (1 − a_x)/(a_y² + a_z²) for a_x ≤ 0 to avoid the cancellation in 1 + a_x.
        const double rho2 = a.y() * a.y() + a.z() * a.z();
        Vector b2 = Vector::UnitY();
        if (a.x() > 0.0 || rho2 > 0.0) {
            const double t = a.x() > 0.0 ? 1.0 / (1.0 + a.x()) : (1.0 - a.x()) / rho2;
            b2 << -a.y(), 1.0 - a.y() * a.y() * t, -a.y() * a.z() * t;
            b2.normalize();
        }
        B.col(0) = a;
        B.col(1) = b2;
        B.col(2) = a.cross(b2);
    }
    return B;
}

template <int Dim>
double QrAnisotropic<Dim>::energy(const Deformation& F, const Point& point) const
{
    return energy_of<Dim>(make_state<Dim>(F, point, mu_, lambda_, kx_, ky_), F);
}

template <int Dim>
double QrAnisotropic<Dim>::evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                                    Projection projection) const
{
    if constexpr (Dim == 3) {
        double psi = 0.0;
        evaluate_batch(1, &F, &point, &psi, P, dPdF, projection);
        return psi;
    } else {
        return evaluate_with_svd(F, nullptr, point, P, dPdF, projection, nullptr);
    }
}

template <int Dim>
void QrAnisotropic<Dim>::evaluate_batch(int count, const Deformation* F, const Point* points, double* psi, Stress* P,
                                        Stiffness* dPdF, Projection projection) const
{
    if constexpr (Dim == 3)
        evaluate_with_svds(count, F, points, psi, P, dPdF, dPdF && projection == Projection::clamp,
                           [&](const Deformation& Fk, const RotationVariantSvd<3>* svd, const Point& point,
                               Stress* Pk, Stiffness* dPdFk, DeferredRotation& deferred) {
                               return evaluate_with_svd(Fk, svd, point, Pk, dPdFk, projection, &deferred);
                           });
    else
        Base::evaluate_batch(count, F, points, psi, P, dPdF, projection);
}

template <int Dim>
double QrAnisotropic<Dim>::evaluate_with_svd(const Deformation& F, const RotationVariantSvd<3>* svd,
                                             const Point& point, Stress* P, Stiffness* dPdF,
                                             Projection projection, DeferredRotation* deferred) const
{
    const QrState<Dim> st = make_state<Dim>(F, point, mu_, lambda_, kx_, ky_);
    if (P != nullptr)
        *P = stress_of<Dim>(st, F);
    if (dPdF != nullptr) {
        Stiffness& H = *dPdF;
        set_isotropic_stiffness<Dim>(st, F, H);
        add_fiber_stiffness<Dim>(st.fiber, H);
        add_fiber_stiffness<Dim>(st.second, H);
        if (projection == Projection::clamp) {
            if constexpr (Dim == 2)
                clamp_2d(H);
            else
                clamp_3d(st, *svd, H, *deferred);
        }
    }
    return energy_of<Dim>(st, F);
}

template class QrAnisotropic<2>;
template class QrAnisotropic<3>;

} // namespace sinew
