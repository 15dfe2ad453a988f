#include "sinew/energies/models/qr_anisotropic.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/determinant_derivatives.hpp"
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/isotropic_batch.hpp"
#include "sinew/energies/models/plane_derivatives.hpp"
#include "sinew/energies/models/psd_projection.hpp"
#include "sinew/energies/models/svd_frame_stiffness.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
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

/// g(d) = (1 − d)²(1 − r) + r (seed 004 §3.6, with AnisoMPM's residual
/// stiffness r: g(0) = 1, g(1) = r; r = 0 is the seed's (1 − d)²).
double degradation(double d, double residual)
{
    return (1.0 - d) * (1.0 - d) * (1.0 - residual) + residual;
}

/// The damage d of a material point; InputError outside [0, 1].
double checked_damage(double d)
{
    if (!(d >= 0.0 && d <= 1.0)) {
        std::ostringstream out;
        out << "model " << kModelName << ": damage d = " << d << " is outside [0, 1]";
        throw InputError(out.str());
    }
    return d;
}

// ---- Plane elements (Dim = 2), one F at a time in Eigen's types. ----

/// What ψ, P and ∂P/∂F share at one F.
struct PlaneState {
    Mat<2> cof;          ///< cof F = ∂J/∂F (= Q cof R Bᵀ)
    double J = 1.0;      ///< det F = r₁₁ r₂₂ (§3.2: the sign convention makes them equal)
    double alpha = 0.0;  ///< g μ: the shear terms Ψ^μ are always degraded (§3.6)
    double beta = 0.0;   ///< g_λ λ: Ψ^λ degraded for J ≥ 1 only (§3.6)
    double c = 0.0;      ///< β (J − 1) − α: the coefficient of ∂J/∂F in P
    Fiber<2> fiber;      ///< kx along a₀
};

PlaneState make_plane_state(const Mat<2>& F, const MaterialPoint<2>& point, double mu, double lambda, double kx,
                            double residual)
{
    const double d = checked_damage(point.damage);
    PlaneState st;
    st.cof << F(1, 1), -F(1, 0), -F(0, 1), F(0, 0);
    st.J = F.col(0).dot(st.cof.col(0));
    const double g = degradation(d, residual);   // g(d), §3.6
    st.alpha = g * mu;                           // g Ψ^μ
    st.beta = (st.J >= 1.0 ? g : 1.0) * lambda;  // Ψ⁺ holds Ψ^λ for J ≥ 1, Ψ⁻ for J < 1
    st.c = st.beta * (st.J - 1.0) - st.alpha;
    st.fiber = make_fiber<2>(kx, unit_fiber<2>(point.fiber), F);
    return st;
}

/// ψ = g Ψ^μ + g_λ Ψ^λ + Ψ^f (seed 004 §3.1, §3.6), with Σᵢⱼ rᵢⱼ² = ‖R‖² = ‖F‖²
/// (Q, B rotations) and Π rᵢᵢ = det F. The seed's "Σ rᵢⱼ² − d" subtracts the
/// dimension n (not the damage d).
double plane_energy(const PlaneState& st, const Mat<2>& F)
{
    const double Jm1 = st.J - 1.0;
    return 0.5 * st.alpha * (F.squaredNorm() - 2.0) - st.alpha * Jm1  // g Ψ^μ
           + 0.5 * st.beta * Jm1 * Jm1                                // g_λ Ψ^λ
           + 0.5 * st.fiber.k * (st.fiber.r - 1.0) * (st.fiber.r - 1.0);  // Ψ^f = kx/2 (r₁₁ − 1)²
}

/// P = Q A R⁻ᵀ Bᵀ (seed 004 §3.2) in the division-free form §3.5 shows
/// exists. A R⁻ᵀ is, term by term, the gradient at X = R of ψ written in
/// X = Qᵀ F B: ½Σrᵢⱼ² → R, J → cof R = J R⁻ᵀ, r₁₁ = ‖X e₁‖ → e₁e₁ᵀ (and in 3D
/// s = ‖X e₂‖ → (R e₂/s) e₂ᵀ); mapped back by Q(·)Bᵀ these are F, cof F and
/// q₁ a₀ᵀ, q₁ = F a₀/r₁₁ (and q_b b₂ᵀ, q_b = F b₂/s). Bounded as any rᵢᵢ → 0:
/// polynomial in F plus fiber forces of size k|r − 1|.
Mat<2> plane_stress(const PlaneState& st, const Mat<2>& F)
{
    const Fiber<2>& fiber = st.fiber;
    // g Ψ^μ + g_λ Ψ^λ, then k (r − 1) q aᵀ
    return st.alpha * F + st.c * st.cof + (fiber.k * (fiber.r - 1.0)) * fiber.q * fiber.a.transpose();
}

/// ∂P/∂F. The isotropic part g Ψ^μ + g_λ Ψ^λ = α/2 ‖F‖² − α(J − 1) + β/2 (J − 1)²
/// is a polynomial in F: α 𝕀 + β vec(cof F) vec(cof F)ᵀ + c ∂²J/∂F² (in the
/// seed's chain, §3.3, the δQ terms of this rotation-invariant part cancel
/// against those of δ(A R⁻ᵀ); this is what is left, with no division by rᵢᵢ).
/// The fiber term by the seed's chain (§3.3–3.4) δP̃ = δQ (A R⁻ᵀ) + Q δ(A R⁻ᵀ)
/// for T = k (r − 1) e₁e₁ᵀ: δQ turns the image, δq = Q Ω e₁ = (I − q qᵀ) δF a/r
/// (§3.4.2), δT changes the length, δr = q·δF a (§3.4.1). Together
/// (a aᵀ) ⊗ k [q qᵀ + (1 − 1/r)(I − q qᵀ)].
Hessian<2> plane_stiffness(const PlaneState& st)
{
    const Eigen::Map<const Vec<4>> cof(st.cof.data());  // vec(∂J/∂F)
    Hessian<2> H = st.beta * cof * cof.transpose();
    H.diagonal().array() += st.alpha;
    // ∂²J/∂F²: J = F₀₀F₁₁ − F₀₁F₁₀, vec indices F₀₀ 0, F₁₀ 1, F₀₁ 2, F₁₁ 3.
    H(0, 3) += st.c;
    H(3, 0) += st.c;
    H(1, 2) -= st.c;
    H(2, 1) -= st.c;
    const Fiber<2>& fiber = st.fiber;
    if (fiber.k != 0.0) {
        const double bending = fiber.bending();
        const Mat<2> block = fiber.k * (bending * Mat<2>::Identity() + (1.0 - bending) * (fiber.q * fiber.q.transpose()));
        for (int l = 0; l < 2; ++l)
            for (int j = 0; j < 2; ++j)
                H.block<2, 2>(2 * j, 2 * l) += (fiber.a(j) * fiber.a(l)) * block;
    }
    return H;
}

// ---- Volume elements (Dim = 3), kSimdLanes deformation gradients side by side. ----

using L = Lanes<kSimdLanes>;

/// A fiber term k/2 (‖F a‖ − 1)² per lane, as Fiber<Dim>.
struct FiberLanes {
    double k = 0.0;   ///< kx or ky, Pa
    Vector3<L> a;     ///< unit material direction
    Vector3<L> q;     ///< F a/r, the unit image (0 where r = 0)
    L r;              ///< ‖F a‖
    L bending;        ///< 1 − 1/r (r floored at kMinFiberStretch): ∂P/∂F across q, divided by k
};

FiberLanes fiber_lanes(double k, const Vector3<L>& a, const Matrix3<L>& F)
{
    FiberLanes fiber;
    fiber.k = k;
    fiber.a = a;
    const Vector3<L> image = F * a;
    fiber.r = sqrt(dot(image, image));
    const auto stretched = fiber.r > 0.0;
    fiber.q = select(stretched, (L(1.0) / select(stretched, fiber.r, L(1.0))) * image, Vector3<L>{{0.0, 0.0, 0.0}});
    fiber.bending = 1.0 - 1.0 / max(fiber.r, L(kMinFiberStretch));
    return fiber;
}

/// H += (coefficient a aᵀ) ⊗ M on column-major vec(F): the 3×3 block of the
/// columns (j, l) of F is coefficient a_j a_l M, with M = m_I I + m_q q qᵀ.
void add_fiber_product(const L& coefficient, const Vector3<L>& a, const L& m_I, const L& m_q, const Vector3<L>& q,
                       L* H)
{
    L M[3][3];
    for (int m = 0; m < 3; ++m)
        for (int i = 0; i < 3; ++i)
            M[i][m] = (i == m ? m_I : L(0.0)) + m_q * q[i] * q[m];
    for (int l = 0; l < 3; ++l)
        for (int j = 0; j < 3; ++j) {
            const L weight = coefficient * a[j] * a[l];
            for (int m = 0; m < 3; ++m)
                for (int i = 0; i < 3; ++i)
                    H[(i + 3 * j) + 9 * (m + 3 * l)] += weight * M[i][m];
        }
}

/// The model's coefficients (Pa).
struct VolumeCoefficients {
    double mu, lambda, kx, ky, residual;
};

/// ψ, P and ∂P/∂F (each may be skipped by a null pointer) of F[k] for
/// k < count (ψ as plane_energy, P as plane_stress, ∂P/∂F as plane_stiffness,
/// with the ky fiber along b₂). ∂P/∂F of the isotropic part is
/// α 𝕀 + β vec(cof F) vec(cof F)ᵀ + c ∂²J/∂F², of a fiber
/// (a aᵀ) ⊗ k [q qᵀ + (1 − 1/r)(I − q qᵀ)].
///
/// Projection::clamp: ∂P/∂F unchanged where it is PSD (a Cholesky test of
/// ∂P/∂F + shift I, shift = 1e-12 max|Hᵢⱼ|, so that PSD matrices with zero
/// modes such as the rest state pass); elsewhere the sum of each term's own PSD
/// part: the isotropic part with its negative eigenvalues clamped through its
/// analytic eigensystem in F = U Σ Vᵀ (rotation-variant, signed σ, as for
/// stable Neo-Hookean, Smith et al. 2018 §4–5: with ψᵢ = α σᵢ + c Jᵢ, twist
/// α + c σₖ, flip α − c σₖ, scaling block α I + β ∇J ∇Jᵀ + c ∂²J/∂σ²,
/// ∂²J/∂σᵢ∂σⱼ = σₖ off the diagonal; no division, exact at repeated and
/// vanishing σ), added as (V ⊗ U)(clamped − exact)(V ⊗ U)ᵀ; each fiber with its
/// negative bending k(1 − 1/r)(a aᵀ) ⊗ (I − q qᵀ) of a compressed fiber removed.
/// The Cholesky test runs only where a term has a negative part.
void evaluate_volume_batch(const VolumeCoefficients& coefficients, int count, const Mat<3>* F,
                           const MaterialPoint<3>* points, double* psi, Mat<3>* P, Hessian<3>* dPdF,
                           Projection projection)
{
    const bool second_fiber = coefficients.ky > 0.0;
    for (int first = 0; first < count; first += kSimdLanes) {
        const int lanes = std::min(kSimdLanes, count - first);
        const Matrix3<L> Fl = detail::packed_in_lanes<kSimdLanes>(F + first, lanes);
        Vector3<L> a0{{1.0, 0.0, 0.0}}, b2{{0.0, 1.0, 0.0}};
        L g(1.0);
        for (int k = 0; k < lanes; ++k) {
            const MaterialPoint<3>& point = points[first + k];
            const double d = checked_damage(point.damage);
            g.set_lane(k, degradation(d, coefficients.residual));  // g(d), §3.6
            // The ky term needs the frame's second axis b₂, the kx term a₀ alone.
            const Mat<3> B = second_fiber ? QrAnisotropic<3>::material_frame(point.fiber) : Mat<3>::Zero();
            const Vec<3> a = second_fiber ? Vec<3>(B.col(0)) : unit_fiber<3>(point.fiber);
            for (int i = 0; i < 3; ++i) {
                a0[i].set_lane(k, a[i]);
                b2[i].set_lane(k, B(i, 1));
            }
        }
        // cof F = ∂J/∂F, columns f₁ × f₂, f₂ × f₀, f₀ × f₁; J = det F = f₀ · (f₁ × f₂).
        const Matrix3<L> cof = determinant_gradient(Fl);
        const L J = dot(Fl.col[0], cof.col[0]), Jm1 = J - 1.0;
        const L alpha = g * coefficients.mu;                                // g Ψ^μ
        const L beta = select(J >= 1.0, g, L(1.0)) * coefficients.lambda;  // g_λ Ψ^λ: degraded for J ≥ 1 only
        const L c = beta * Jm1 - alpha;                                     // the coefficient of ∂J/∂F in P
        FiberLanes fibers[2] = {fiber_lanes(coefficients.kx, a0, Fl), fiber_lanes(coefficients.ky, b2, Fl)};
        const int fiber_count = second_fiber ? 2 : 1;

        // ψ = α/2 (‖F‖² − 3) − α (J − 1) + β/2 (J − 1)² + Σ k/2 (r − 1)²  (seed 004 §3.1, §3.6)
        L energy = (0.5 * alpha) * (dot(Fl.col[0], Fl.col[0]) + dot(Fl.col[1], Fl.col[1]) + dot(Fl.col[2], Fl.col[2]) - 3.0) -
                   alpha * Jm1 + (0.5 * beta) * Jm1 * Jm1;
        for (int f = 0; f < fiber_count; ++f)
            energy += (0.5 * fibers[f].k) * (fibers[f].r - 1.0) * (fibers[f].r - 1.0);
        for (int k = 0; k < lanes; ++k)
            psi[first + k] = energy.lane(k);
        double* destinations[kSimdLanes];
        if (P) {
            L stress[9];  // P = α F + c cof F + Σ k (r − 1) q aᵀ (§3.2 in the form of §3.5), column-major
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i) {
                    stress[i + 3 * j] = alpha * Fl(i, j) + c * cof(i, j);
                    for (int f = 0; f < fiber_count; ++f)
                        stress[i + 3 * j] += (fibers[f].k * (fibers[f].r - 1.0)) * fibers[f].q[i] * fibers[f].a[j];
                }
            for (int k = 0; k < lanes; ++k)
                destinations[k] = P[first + k].data();
            copy_lanes_to(stress, 9, destinations, lanes);
        }
        if (!dPdF)
            continue;

        L H[81];  // column-major, as ∂P/∂F (§3.3–3.4, worked out per term as in plane_stiffness)
        // α 𝕀 + β vec(cof F) vec(cof F)ᵀ
        for (int column = 0; column < 9; ++column)
            for (int row = 0; row < 9; ++row)
                H[row + 9 * column] = beta * cof(row % 3, row / 3) * cof(column % 3, column / 3) +
                                      (row == column ? alpha : L(0.0));
        add_determinant_hessian(c, Fl, H);  // + c ∂²J/∂F²
        // + Σ (a aᵀ) ⊗ k [(1 − 1/r) I + (1/r) q qᵀ]
        for (int f = 0; f < fiber_count; ++f)
            add_fiber_product(L(fibers[f].k), fibers[f].a, fibers[f].bending, 1.0 - fibers[f].bending, fibers[f].q, H);

        if (projection == Projection::clamp) {
            const detail::Svd3<L> svd = detail::rotation_variant_svd_of(Fl);
            const Vector3<L>& s = svd.sigma;
            const Matrix3<L> scaling = scaling_block(alpha, beta, c, s);
            const Matrix3<L> clamped = detail::clamp_symmetric_3x3(scaling);
            Vector3<L> twist_raise, flip_raise;  // clamped − exact eigenvalue: max(λ, 0) − λ
            // Where a term has a negative part: a compressed fiber, a negative twist or
            // flip eigenvalue, a scaling block the clamp changes.
            auto negative = L(fibers[0].k) > 0.0 && fibers[0].bending < 0.0;
            for (int f = 1; f < fiber_count; ++f)
                negative = negative || (L(fibers[f].k) > 0.0 && fibers[f].bending < 0.0);
            for (int k = 0; k < 3; ++k) {
                const L twist = alpha + c * s[k], flip = alpha - c * s[k];
                twist_raise[k] = max(twist, L(0.0)) - twist;
                flip_raise[k] = max(flip, L(0.0)) - flip;
                negative = negative || twist < 0.0 || flip < 0.0;
                for (int i = 0; i < 3; ++i)
                    negative = negative || clamped(i, k) < scaling(i, k) || clamped(i, k) > scaling(i, k);
            }
            if (any(negative)) {
                L size(0.0);
                for (const L& entry : H)
                    size = max(size, abs(entry));
                const auto project = negative && !detail::cholesky_succeeds<9>(H, 1e-12 * size);
                if (any(project)) {
                    // The frame blocks of the correction: α − β the twist, α + β the flip raise.
                    Matrix3<L> scaling_raise;
                    Vector3<L> alpha_raise, beta_raise;
                    for (int k = 0; k < 3; ++k) {
                        for (int i = 0; i < 3; ++i)
                            scaling_raise(i, k) = select(project, clamped(i, k) - scaling(i, k), L(0.0));
                        alpha_raise[k] = select(project, 0.5 * (twist_raise[k] + flip_raise[k]), L(0.0));
                        beta_raise[k] = select(project, 0.5 * (flip_raise[k] - twist_raise[k]), L(0.0));
                    }
                    detail::rotate_frame_stiffness(svd.U, svd.V, scaling_raise, alpha_raise, beta_raise,
                                                   [&](int row, int column, const L& value) { H[row + 9 * column] += value; });
                    for (int f = 0; f < fiber_count; ++f) {
                        const FiberLanes& fiber = fibers[f];
                        const L removed = select(project && fiber.bending < 0.0, -fiber.k * fiber.bending, L(0.0));
                        add_fiber_product(removed, fiber.a, L(1.0), L(-1.0), fiber.q, H);
                    }
                }
            }
        }
        for (int k = 0; k < lanes; ++k)
            destinations[k] = dPdF[first + k].data();
        copy_lanes_to(H, 81, destinations, lanes);
    }
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
        // {name, default, unit, description, lower, upper, lower_exclusive, choices}
        ParameterSpec{"residual", 0.0, "1",
                      "residual stiffness r of the degradation g(d) = (1 - d)^2 (1 - r) + r: the share of the tension "
                      "part a fully damaged point keeps (AnisoMPM; 0 is seed 004 §3.6's g)",
                      0.0, 1.0, false, {}},
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
    residual_ = p.at("residual");
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
    return evaluate(F, point, nullptr, nullptr, Projection::none);
}

template <int Dim>
double QrAnisotropic<Dim>::evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                                    Projection projection) const
{
    double psi = 0.0;
    evaluate_batch(1, &F, &point, &psi, P, dPdF, projection);
    return psi;
}

template <int Dim>
void QrAnisotropic<Dim>::evaluate_batch(int count, const Deformation* F, const Point* points, double* psi, Stress* P,
                                        Stiffness* dPdF, Projection projection) const
{
    if constexpr (Dim == 3) {
        evaluate_volume_batch({mu_, lambda_, kx_, ky_, residual_}, count, F, points, psi, P, dPdF, projection);
    } else {
        for (int k = 0; k < count; ++k) {
            const PlaneState st = make_plane_state(F[k], points[k], mu_, lambda_, kx_, residual_);
            if (P)
                P[k] = plane_stress(st, F[k]);
            if (dPdF) {
                dPdF[k] = plane_stiffness(st);
                if (projection == Projection::clamp)
                    clamp_plane_stiffness(dPdF[k]);
            }
            psi[k] = plane_energy(st, F[k]);
        }
    }
}

template class QrAnisotropic<2>;
template class QrAnisotropic<3>;

} // namespace sinew
