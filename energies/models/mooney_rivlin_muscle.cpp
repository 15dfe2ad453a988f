#include "sinew/energies/models/mooney_rivlin_muscle.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/determinant_derivatives.hpp"
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/psd_projection.hpp"
#include "sinew/energies/models/svd_frame_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew {
namespace {

// Every evaluation runs kSimdLanes deformation gradients side by side, one
// per lane of Wide (lanes.hpp); a branch on the data is a selection.
using Wide = Lanes<kSimdLanes>;
using WideMask = decltype(Wide() < Wide());

// The pairs (i, j) of the 2×2 blocks B_ij (seed 000 §4.5), pair k the one without k
// (the order of svd_frame_stiffness.hpp).
constexpr int kPairs[3][2] = {{1, 2}, {0, 2}, {0, 1}};
// σ_i + σ_j divides the thresholded ln J block; it vanishes only where an
// inverted σ₃ = −σ₂, where P itself has a kink (docs: inversion). Floored
// there to stay finite.
constexpr double kPairSumFloor = 1e-9;
// Relative diagonal shift of the PSD test of the exact ∂P/∂F.
constexpr double kPsdTestShift = 1e-12;

/// f(x) lane by lane, for the scalar functions of <cmath> and the fiber curves.
template <typename Function>
Wide each_lane(const Wide& x, const Function& f)
{
    Wide result;
    for (int k = 0; k < kSimdLanes; ++k)
        result.set_lane(k, f(x.lane(k)));
    return result;
}

Wide log_of(const Wide& x)
{
    return each_lane(x, [](double value) { return std::log(value); });
}

Wide exp_of(const Wide& x)
{
    return each_lane(x, [](double value) { return std::exp(value); });
}

/// L = ln J with the inversion threshold c (seed 000 §5.5): L = Σ ℓ(σ_k),
/// ℓ(σ) = ln σ for σ ≥ c and ln c + (σ − c)/c below, the tangent of ln σ at
/// c. C¹ in σ, finite through σ = 0 and for σ₃ < 0.
struct LogVolume {
    Wide L;
    Vector3<Wide> slope;      ///< ℓ'(σ_k) = 1/max(σ_k, c): F̂⁻¹ in §4.3, the third column of F_base (§4.5.1)
    Vector3<Wide> curvature;  ///< ℓ''(σ_k) = −1/σ_k² at or above c, 0 below
    WideMask below[3];        ///< σ_k < c
};

/// L is ln J where no σ_k is below c; so it is where σ_min ≥ 2J/‖F‖² ≥ c
/// (σ₀σ₁ ≤ ½(σ₀² + σ₁²)), known without the SVD (`bound`), so that ψ is the
/// same number whether or not an SVD was computed. `sigma` is null when no
/// lane needs it (then only L is set).
LogVolume log_volume(const WideMask& bound, const Wide& J, const Vector3<Wide>* sigma, double c)
{
    LogVolume v;
    v.L = log_of(J);
    if (!sigma)
        return v;
    const Vector3<Wide>& s = *sigma;
    WideMask any_below = s[0] < c;
    for (int k = 0; k < 3; ++k) {
        v.below[k] = s[k] < c;
        any_below = any_below || v.below[k];
        v.slope[k] = 1.0 / max(s[k], Wide(c));
        v.curvature[k] = select(v.below[k], Wide(0.0), -v.slope[k] * v.slope[k]);
    }
    const WideMask continued = any_below && !bound;
    if (any(continued)) {
        const double log_c = std::log(c);
        Wide sum(0.0);
        for (int k = 0; k < 3; ++k)
            sum += select(v.below[k], log_c + (s[k] - c) / c, log_of(s[k]));
        v.L = select(continued, sum, v.L);
    }
    return v;
}

/// The 2×2 block [[a, b], [b, a]] of ∂²L on (δF̂_ij, δF̂_ji), from g = ℓ':
/// a = (D⁻ + S⁺)/2, b = (D⁻ − S⁺)/2 with the divided differences
/// D⁻ = (g_i − g_j)/(σ_i − σ_j) = −r g_i g_j, r = (σ̂_i − σ̂_j)/(σ_i − σ_j) ∈ [0, 1]
/// (σ̂ = max(σ, c): r = 1 when neither is below c, 0 when both are, so ties
/// need no division) and S⁺ = (g_i + g_j)/(σ_i + σ_j). With no σ below c:
/// a = 0, b = −1/(σ_i σ_j), the ∂F⁻ᵀ/∂F term of §4.5.1.1 (eq. 26).
void log_volume_pair(const LogVolume& v, const Vector3<Wide>& sigma, double c, int i, int j, Wide& a, Wide& b)
{
    const Wide product = v.slope[i] * v.slope[j];
    const WideMask neither = !v.below[i] && !v.below[j];
    const WideMask one = (v.below[i] && !v.below[j]) || (v.below[j] && !v.below[i]);
    const Wide gap = select(one, sigma[i] - sigma[j], Wide(1.0));
    const Wide r = select(one, min(max((max(sigma[i], Wide(c)) - max(sigma[j], Wide(c))) / gap, Wide(0.0)), Wide(1.0)),
                          Wide(0.0));
    const Wide difference = -r * product;
    const Wide sum = (v.slope[i] + v.slope[j]) / max(sigma[i] + sigma[j], Wide(kPairSumFloor));
    a = select(neither, Wide(0.0), 0.5 * (difference + sum));
    b = select(neither, -product, 0.5 * (difference - sum));
}

/// The frame blocks of ∂P/∂F (svd_frame_stiffness.hpp), per lane.
struct FrameBlocks {
    Matrix3<Wide> A;      ///< the 3×3 block on (δF̂₀₀, δF̂₁₁, δF̂₂₂)
    Vector3<Wide> alpha;  ///< α of pair k
    Vector3<Wide> beta;   ///< β of pair k
};

FrameBlocks select(const WideMask& mask, const FrameBlocks& a, const FrameBlocks& b)
{
    FrameBlocks out;
    out.A = detail::select(mask, a.A, b.A);
    out.alpha = select(mask, a.alpha, b.alpha);
    out.beta = select(mask, a.beta, b.beta);
    return out;
}

/// The fiber at F (seed 000 §4.5.2): n = F a₀/μ, μ = |F a₀|, and the
/// coefficients of its ∂²Φ/∂F² (0 in lanes without fiber force).
struct FiberState {
    Vector3<Wide> a0;          ///< the fiber a₀ (material)
    Vector3<Wide> n;           ///< F a₀/μ (0 where μ = 0)
    Wide inverse_mu;           ///< 1/μ (0 where μ = 0)
    Wide G[9];                 ///< G = ∂ln λ/∂F = x − vec(S)/3 (deviatoric stretch only), x = vec(n a₀ᵀ)/μ
};

/// K += fiber part of ∂P/∂F for tension t = f'λ² + fλ and s = fλ:
/// ∂²Φ = t GGᵀ − 2s xxᵀ + (s/μ²)(a₀a₀ᵀ ⊗ I₃) (G = x for λ̃: eq. 45,
/// (f' − c₁) NNᵀ + c₁ (a₀a₀ᵀ ⊗ I), c₁ = f/λ̃), the xx and I terms as
/// (a₀a₀ᵀ ⊗ (c_n nnᵀ + c_I I))/μ², block (j, l) scaled by a₀_j a₀_l.
void add_fiber_stiffness(const FiberState& fiber, bool deviatoric, const Wide& t, const Wide& s, Wide* K)
{
    const Wide inverse_mu2 = fiber.inverse_mu * fiber.inverse_mu;
    const Wide c_n = (deviatoric ? -2.0 * s : t - 2.0 * s) * inverse_mu2, c_I = s * inverse_mu2;
    Wide core[3][3];
    for (int m = 0; m < 3; ++m)
        for (int i = 0; i < 3; ++i)
            core[i][m] = c_n * fiber.n[i] * fiber.n[m] + (i == m ? c_I : Wide(0.0));
    for (int l = 0; l < 3; ++l)
        for (int j = 0; j < 3; ++j) {
            const Wide weight = fiber.a0[j] * fiber.a0[l];
            for (int m = 0; m < 3; ++m)
                for (int i = 0; i < 3; ++i)
                    K[(i + 3 * j) + 9 * (m + 3 * l)] += weight * core[i][m];
        }
    if (deviatoric)
        for (int q = 0; q < 9; ++q) {
            const Wide tG = t * fiber.G[q];
            for (int p = 0; p < 9; ++p)
                K[p + 9 * q] += fiber.G[p] * tG;
        }
}

/// For the deviatoric λ, K −= the negative eigenpart of the rank-2 term
/// t GGᵀ − s xxᵀ (t, s ≥ 0) where `mask`. In span{G, x} the term is
/// [G x] diag(t, −s) [G x]ᵀ, so its eigenvalues are those of diag(t, −s)·Gram;
/// ν₋ ≤ 0 since the Gram determinant is ≥ 0, and y = t(G·x) G + (ν₋ − t|G|²) x
/// solves the G row.
void remove_negative_pair(const FiberState& fiber, const Wide& t, const Wide& s, const WideMask& mask, Wide* K)
{
    Wide x[9];
    for (int l = 0; l < 3; ++l)
        for (int i = 0; i < 3; ++i)
            x[i + 3 * l] = fiber.a0[l] * fiber.inverse_mu * fiber.n[i];
    Wide gg(0.0), xx(0.0), gx(0.0);
    for (int p = 0; p < 9; ++p) {
        gg += fiber.G[p] * fiber.G[p];
        xx += x[p] * x[p];
        gx += fiber.G[p] * x[p];
    }
    const Wide mean = 0.5 * (t * gg - s * xx);
    const Wide spread = 0.5 * (t * gg + s * xx);
    const Wide negative = mean - sqrt(max(spread * spread - t * s * gx * gx, Wide(0.0)));
    Wide y[9], yy(0.0);
    for (int p = 0; p < 9; ++p) {
        y[p] = (t * gx) * fiber.G[p] + (negative - t * gg) * x[p];
        yy += y[p] * y[p];
    }
    const WideMask removed = mask && negative < 0.0 && yy > 0.0;
    const Wide coefficient = select(removed, negative / select(removed, yy, Wide(1.0)), Wide(0.0));
    for (int q = 0; q < 9; ++q)
        for (int p = 0; p < 9; ++p)
            K[p + 9 * q] -= coefficient * y[p] * y[q];
}

/// The fiber in the SVD frame: n̂ = Uᵀn, f_m = Vᵀa₀ (§4.3), for quadratic
/// forms of the exact ∂P/∂F along SVD-frame directions.
struct FrameFiber {
    Vector3<Wide> n_hat;
    Vector3<Wide> fm;
};

/// zᵀ K z for the exact ∂P/∂F and z = vec(U Ẑ Vᵀ): the blocks give
/// Σ_kl A_kl Ẑ_kk Ẑ_ll + Σ_ij α_ij(Ẑ_ij² + Ẑ_ji²) + 2β_ij Ẑ_ij Ẑ_ji, the fiber
/// t(G·z)² − 2s(x·z)² + (s/μ²)|Ẑ f_m|² with x·z = n̂ᵀẐ f_m/μ and
/// G·z = x·z − (Σ_k Ẑ_kk ℓ'_k)/3 for the deviatoric λ (G = x otherwise).
Wide exact_quadratic_form(const FrameBlocks& frame, const FrameFiber& fiber, const FiberState& state,
                          const LogVolume& volume, bool deviatoric, const Wide& t, const Wide& s, const Matrix3<Wide>& Z)
{
    const Vector3<Wide> d{{Z(0, 0), Z(1, 1), Z(2, 2)}};
    Wide value = dot(d, frame.A * d);
    for (int m = 0; m < 3; ++m) {
        const int i = kPairs[m][0], j = kPairs[m][1];
        value += frame.alpha[m] * (Z(i, j) * Z(i, j) + Z(j, i) * Z(j, i)) + 2.0 * frame.beta[m] * Z(i, j) * Z(j, i);
    }
    const Vector3<Wide> Zf = Z * fiber.fm;
    const Wide xz = dot(fiber.n_hat, Zf) * state.inverse_mu;
    const Wide Gz = deviatoric ? xz - dot(d, volume.slope) * (1.0 / 3.0) : xz;
    return value + t * Gz * Gz - 2.0 * s * xz * xz + s * state.inverse_mu * state.inverse_mu * dot(Zf, Zf);
}

/// exact_quadratic_form along the mode (E_ij + sign E_ji)/√2 of pair m, in
/// closed form: Ẑ has no diagonal (G·z = x·z), Ẑ_ij² + Ẑ_ji² = 1, 2Ẑ_ijẐ_ji = sign
/// and Ẑ f_m = (f_m,j e_i + sign f_m,i e_j)/√2, so the form is
/// α + sign β + (t − 2s)(x·z)² + (s/μ²)(f_m,i² + f_m,j²)/2.
Wide pair_mode_quadratic_form(const FrameBlocks& frame, const FrameFiber& fiber, const FiberState& state, int m,
                              double sign, const Wide& t, const Wide& s)
{
    const int i = kPairs[m][0], j = kPairs[m][1];
    const Wide xz = std::sqrt(0.5) * (fiber.n_hat[i] * fiber.fm[j] + sign * fiber.n_hat[j] * fiber.fm[i]) * state.inverse_mu;
    return frame.alpha[m] + sign * frame.beta[m] + (t - 2.0 * s) * xz * xz +
           (0.5 * s) * state.inverse_mu * state.inverse_mu * (fiber.fm[i] * fiber.fm[i] + fiber.fm[j] * fiber.fm[j]);
}

/// The SVD-frame blocks of the Mooney-Rivlin and volume terms of ∂P/∂F
/// (§4.5.1), with w₁ = 2J_cc A, w₂ = 2J_cc² B and p − p_f as in P.
FrameBlocks frame_blocks(const Vector3<Wide>& sigma, const LogVolume& volume, const Wide& w1, const Wide& w2,
                         const Wide& I1, const Wide& trC2, const Wide& pressure, double K, double c)
{
    const Wide w12 = w1 + I1 * w2;
    // §4.5.1.4: η from the second partials of ψ(tr C, tr C², L); γ = F_base η F_baseᵀ
    // with F_base rows (σ_k, σ_k³, ℓ'_k). η₁₃ is −(4/3)AJ_cc − (8/3)BJ_cc² tr C
    // (the summary's first line has 8/9: see docs).
    const Wide eta02 = -2.0 / 3.0 * w1 - 4.0 / 3.0 * w2 * I1, eta12 = 4.0 / 3.0 * w2;
    const Wide eta22 = K + 2.0 / 9.0 * w1 * I1 + 4.0 / 9.0 * w2 * (I1 * I1 - trC2);
    const Matrix3<Wide> eta{{{{2.0 * w2, Wide(0.0), eta02}}, {{Wide(0.0), Wide(0.0), eta12}}, {{eta02, eta12, eta22}}}};
    Vector3<Wide> base[3];  // the rows of F_base
    for (int k = 0; k < 3; ++k)
        base[k] = {{sigma[k], sigma[k] * sigma[k] * sigma[k], volume.slope[k]}};
    FrameBlocks frame;
    for (int l = 0; l < 3; ++l) {
        const Vector3<Wide> eta_base = eta * base[l];
        for (int k = 0; k < 3; ++k)
            frame.A(k, l) = dot(base[k], eta_base);
    }
    // A = diag(α_kk + β_kk) + γ: α_kk = w₁₂ − 2w₂σ_k², β_kk = (p − p_f) ℓ''_k − w₂σ_k²
    // (−(p − p_f)/σ_k² above the threshold).
    for (int k = 0; k < 3; ++k)
        frame.A(k, k) += w12 - 3.0 * w2 * sigma[k] * sigma[k] + pressure * volume.curvature[k];
    // B_ij: α_ij = w₁₂ − w₂(σ_i² + σ_j²) + (p − p_f) a_ij,
    //       β_ij = −w₂σ_iσ_j + (p − p_f) b_ij (−(p − p_f)/(σ_iσ_j) above the threshold).
    for (int m = 0; m < 3; ++m) {
        const int i = kPairs[m][0], j = kPairs[m][1];
        Wide a, b;
        log_volume_pair(volume, sigma, c, i, j, a, b);
        frame.alpha[m] = w12 - w2 * (sigma[i] * sigma[i] + sigma[j] * sigma[j]) + pressure * a;
        frame.beta[m] = -w2 * sigma[i] * sigma[j] + pressure * b;
    }
    return frame;
}

/// §5.6 on the SVD-frame blocks: the 3×3 block less its negative part (where
/// Sylvester's criterion does not prove it positive definite), each B_ij's
/// eigenvalues α ± β clamped at zero; and where something changed.
struct ClampedFrame {
    FrameBlocks projected;
    WideMask block_clamped;        ///< the 3×3 block had a negative eigenvalue
    Vector3<Wide> block_negative;  ///< then a unit eigenvector of one
    WideMask plus_negative[3];     ///< α + β < 0 for pair m
    WideMask minus_negative[3];    ///< α − β < 0 for pair m
    WideMask clamped;              ///< any of these
};

ClampedFrame clamp_frame(const FrameBlocks& frame)
{
    ClampedFrame out;
    out.projected = frame;
    const WideMask block_definite = detail::positive_definite_3x3(frame.A);
    out.block_clamped = !block_definite;
    out.block_negative = {{1.0, 0.0, 0.0}};
    if (any(out.block_clamped)) {
        const detail::NegativePart<Wide> negative = detail::negative_part(frame.A);
        WideMask changed = negative.part(0, 0) < 0.0 || negative.part(0, 0) > 0.0;
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                changed = changed || negative.part(i, j) < 0.0 || negative.part(i, j) > 0.0;
                out.projected.A(i, j) = select(block_definite, frame.A(i, j), frame.A(i, j) - negative.part(i, j));
            }
        out.block_clamped = out.block_clamped && changed;
        out.block_negative = negative.direction;
    }
    out.clamped = out.block_clamped;
    for (int m = 0; m < 3; ++m) {
        const Wide plus = frame.alpha[m] + frame.beta[m], minus = frame.alpha[m] - frame.beta[m];
        out.plus_negative[m] = plus < 0.0;
        out.minus_negative[m] = minus < 0.0;
        const WideMask pair_clamped = out.plus_negative[m] || out.minus_negative[m];
        const Wide plus_clamped = max(plus, Wide(0.0)), minus_clamped = max(minus, Wide(0.0));
        out.projected.alpha[m] = select(pair_clamped, 0.5 * (plus_clamped + minus_clamped), frame.alpha[m]);
        out.projected.beta[m] = select(pair_clamped, 0.5 * (plus_clamped - minus_clamped), frame.beta[m]);
        out.clamped = out.clamped || pair_clamped;
    }
    return out;
}

ParameterSpec number(const std::string& name, double default_value, const std::string& unit,
                     const std::string& description, double lower, double upper, bool lower_exclusive)
{
    ParameterSpec spec;
    spec.name = name;
    spec.default_value = default_value;
    spec.unit = unit;
    spec.description = description;
    spec.lower = lower;
    spec.upper = upper;
    spec.lower_exclusive = lower_exclusive;
    return spec;
}

ParameterValues validated_parameters(const ParameterValues& given)
{
    ParameterValues values = resolve_parameters(MooneyRivlinMuscle::kName, MooneyRivlinMuscle::parameter_specs(), given);
    if (values.at("lambda_star") < values.at("lambda_opt"))
        throw InputError(std::string("model ") + MooneyRivlinMuscle::kName +
                         ": parameter lambda_star must be >= lambda_opt (the passive curve turns linear after slack)");
    return values;
}

} // namespace

MooneyRivlinMuscle::MooneyRivlinMuscle(const ParameterValues& parameters)
    : MooneyRivlinMuscle(Validated{}, validated_parameters(parameters))
{
}

MooneyRivlinMuscle::MooneyRivlinMuscle(Validated, const ParameterValues& checked)
    : A_(checked.at("A")),
      B_(checked.at("B")),
      K_(checked.at("K")),
      active_(checked.at("sigma_max"), checked.at("lambda_opt")),
      passive_(checked.at("sigma_max"), checked.at("P1"), checked.at("P2"), checked.at("lambda_opt"),
               checked.at("lambda_star")),
      stretch_(checked.at("fiber_stretch") == 0.0 ? FiberStretch::physbam : FiberStretch::deviatoric),
      threshold_(checked.at("inversion_threshold")),
      fibers_on_(checked.at("sigma_max") > 0.0)
{
}

std::vector<ParameterSpec> MooneyRivlinMuscle::parameter_specs()
{
    const double none = 1e300;
    ParameterSpec stretch = number("fiber_stretch", 0.0, "", "fiber stretch: physbam |F a0| or deviatoric J^(-1/3)|F a0|",
                                   0.0, none, false);
    stretch.choices = {"physbam", "deviatoric"};
    return {
        number("A", 125.0, "Pa", "Mooney-Rivlin coefficient of the deviatoric invariant I1", 0.0, none, false),
        number("B", 125.0, "Pa", "Mooney-Rivlin coefficient of the deviatoric invariant I2", 0.0, none, false),
        number("K", 1e7, "Pa", "volume term K/2 ln(J)^2, the bulk modulus at rest", 0.0, none, false),
        number("sigma_max", 3e5, "Pa", "peak isometric fiber stress; 0 turns the fibers off", 0.0, none, false),
        number("lambda_opt", 1.0, "1", "optimal fiber stretch: peak of the active curve, slack of the passive one",
               0.0, 10.0, true),
        number("P1", 0.05, "1", "passive fiber stress scale, in units of sigma_max", 0.0, none, false),
        number("P2", 6.6, "1", "passive fiber exponential rate", 0.0, 100.0, true),
        number("lambda_star", 1.4, "1", "fiber stretch where the passive curve turns linear (>= lambda_opt)", 0.0,
               30.0, true),
        stretch,
        number("inversion_threshold", 0.1, "1", "singular values below it see ln continued linearly; 0 = none",
               0.0, 0.5, false),
    };
}


double MooneyRivlinMuscle::energy(const Deformation& F, const Point& point) const
{
    return evaluate(F, point, nullptr, nullptr, Projection::none);
}

double MooneyRivlinMuscle::evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                                    Projection projection) const
{
    double psi = 0.0;
    evaluate_batch(1, &F, &point, &psi, P, dPdF, projection);
    return psi;
}

namespace {

/// L and ∂L/∂F = U diag(ℓ'(σ)) Vᵀ of one F for the thresholded L of
/// log_volume (seed 000 §5.5; ln J and F⁻ᵀ where no σ is below c).
struct VolumeOfOne {
    double L = 0.0;
    Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();
};

VolumeOfOne volume_of_one(const Eigen::Matrix3d& F, double c)
{
    const Matrix3<Wide> Fw = detail::packed_in_lanes<kSimdLanes>(&F, 1);
    const Wide J = dot(Fw.col[0], determinant_gradient(Fw).col[0]);
    const Wide I1 = dot(Fw.col[0], Fw.col[0]) + dot(Fw.col[1], Fw.col[1]) + dot(Fw.col[2], Fw.col[2]);
    const detail::Svd3<Wide> svd = detail::rotation_variant_svd_of(Fw);
    const LogVolume volume = log_volume(J > 0.0 && 2.0 * J >= c * I1, J, &svd.sigma, c);
    VolumeOfOne result;
    result.L = volume.L.lane(0);
    for (int l = 0; l < 3; ++l)
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                result.gradient(i, l) += volume.slope[k].lane(0) * svd.U(i, k).lane(0) * svd.V(l, k).lane(0);
    return result;
}

} // namespace

double MooneyRivlinMuscle::activation_derivative(const Deformation& F, const Point& point, Stress* dP_dalpha) const
{
    if (dP_dalpha)
        dP_dalpha->setZero();
    if (!(energy(F, point) < std::numeric_limits<double>::infinity()))
        return std::numeric_limits<double>::infinity();
    if (!fibers_on_)
        return 0.0;
    // λ̃ = |F a₀|; λ = λ̃ (physbam) or e^(−L/3) λ̃ (deviatoric, §4.2, J^(−1/3) above the threshold).
    const Eigen::Vector3d image = F * point.fiber;
    const double mu = image.norm();
    const bool deviatoric = stretch_ == FiberStretch::deviatoric;
    const VolumeOfOne volume = deviatoric ? volume_of_one(F, threshold_) : VolumeOfOne{};
    const double lambda = deviatoric ? mu * std::exp(-volume.L / 3.0) : mu;
    const FiberCurvePoint active = active_.evaluate(lambda);
    if (dP_dalpha && mu > 0.0) {
        // ∂P/∂α = f_a ∂λ/∂F, ∂λ/∂F = (λ/λ̃²)(F a₀)a₀ᵀ − (λ/3) ∂L/∂F (the second term deviatoric only).
        const Eigen::Matrix3d dlambda =
            (lambda / (mu * mu)) * image * point.fiber.transpose() - (lambda / 3.0) * volume.gradient;
        *dP_dalpha = active.stress * dlambda;
    }
    return active.energy;  // ∂ψ/∂α = Φ_a(λ)
}

void MooneyRivlinMuscle::evaluate_batch(int count, const Deformation* F, const Point* points, double* psi,
                                        Stress* P, Stiffness* dPdF, Projection projection) const
{
    for (int first = 0; first < count; first += kSimdLanes)
        evaluate_lanes(std::min(kSimdLanes, count - first), F + first, points + first, psi + first,
                       P ? P + first : nullptr, dPdF ? dPdF + first : nullptr, projection);
}

void MooneyRivlinMuscle::evaluate_lanes(int lanes, const Deformation* F, const Point* points, double* psi,
                                        Stress* P, Stiffness* dPdF, Projection projection) const
{
    const Matrix3<Wide> Fw = detail::packed_in_lanes<kSimdLanes>(F, lanes);
    Vector3<Wide> a0{{1.0, 0.0, 0.0}};
    Wide activation(0.0);
    for (int k = 0; k < lanes; ++k) {
        for (int j = 0; j < 3; ++j)
            a0[j].set_lane(k, points[k].fiber[j]);
        activation.set_lane(k, points[k].activation);
    }
    const double c = threshold_;
    const bool derivatives = P || dPdF;
    WideMask finite = abs(Fw(0, 0)) <= std::numeric_limits<double>::max();
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            finite = finite && abs(Fw(i, j)) <= std::numeric_limits<double>::max();
    const Wide J = dot(Fw.col[0], determinant_gradient(Fw).col[0]);  // J = f₀ · (f₁ × f₂)
    // §4.2, §4.3.4: Ī₁ = J_cc tr C, Ī₂ = J_cc² ½((tr C)² − tr C²), C = FᵀF (not the deviatoric C̄).
    const Wide I1 = dot(Fw.col[0], Fw.col[0]) + dot(Fw.col[1], Fw.col[1]) + dot(Fw.col[2], Fw.col[2]);
    const Wide C01 = dot(Fw.col[0], Fw.col[1]), C02 = dot(Fw.col[0], Fw.col[2]), C12 = dot(Fw.col[1], Fw.col[2]);
    const Wide trC2 = dot(Fw.col[0], Fw.col[0]) * dot(Fw.col[0], Fw.col[0]) +
                      dot(Fw.col[1], Fw.col[1]) * dot(Fw.col[1], Fw.col[1]) +
                      dot(Fw.col[2], Fw.col[2]) * dot(Fw.col[2], Fw.col[2]) + 2.0 * (C01 * C01 + C02 * C02 + C12 * C12);
    // No singular value below c where σ_min ≥ 2J/‖F‖² ≥ c; with c = 0 ψ is defined for J > 0 only.
    const WideMask bound = J > 0.0 && 2.0 * J >= c * I1;
    WideMask defined = c > 0.0 ? finite : finite && bound;
    // §4.3, §5.4: F = U F̂ Vᵀ, F̂ = diag(σ) with U, V rotations; an inversion
    // puts its sign on σ₃ (the smallest |σ|).
    const bool needs_svd = derivatives || (c > 0.0 && any(finite && !bound));
    detail::Svd3<Wide> svd;
    if (needs_svd)
        svd = detail::rotation_variant_svd_of(Fw);
    const Vector3<Wide>& sigma = svd.sigma;
    if (c == 0.0 && derivatives)
        defined = defined && sigma[2] > 0.0;
    const LogVolume volume = log_volume(bound, J, needs_svd ? &sigma : nullptr, c);

    // ψ = A Ī₁ + B Ī₂ + K/2 L² + α Φ_a(λ) + Φ_p(λ) (§4.2, the volume term in the thresholded L).
    const Wide Jcc = exp_of(-2.0 / 3.0 * volume.L);  // J_cc = e^(−2L/3) (= J^(−2/3) above the threshold)
    Wide energy = A_ * Jcc * I1 + B_ * Jcc * Jcc * 0.5 * (I1 * I1 - trC2) + 0.5 * K_ * volume.L * volume.L;
    // §4.3.3: λ̃ = |F a₀| (PhysBAM) or λ = J^(−1/3)|F a₀| (the note's §4.2); f = ∂Φ/∂λ, f' its slope.
    const Vector3<Wide> image = Fw * a0;
    const Wide mu = sqrt(dot(image, image));
    const bool deviatoric = stretch_ == FiberStretch::deviatoric;
    Wide lambda(0.0), f(0.0), df(0.0);
    if (fibers_on_) {
        lambda = deviatoric ? mu * exp_of(-1.0 / 3.0 * volume.L) : mu;
        Wide fiber_energy;
        for (int k = 0; k < kSimdLanes; ++k) {
            const FiberCurvePoint active = active_.evaluate(lambda.lane(k));
            const FiberCurvePoint passive = passive_.evaluate(lambda.lane(k));
            const double alpha = activation.lane(k);
            fiber_energy.set_lane(k, alpha * active.energy + passive.energy);  // F₂ = α F_active + F_passive
            f.set_lane(k, alpha * active.stress + passive.stress);
            df.set_lane(k, alpha * active.stiffness + passive.stiffness);
        }
        energy += fiber_energy;
    }
    energy = select(defined, energy, Wide(std::numeric_limits<double>::infinity()));
    for (int k = 0; k < lanes; ++k)
        psi[k] = energy.lane(k);
    if (!derivatives)
        return;

    // §4.3.4 with C = F̂²: w₁ = 2J_cc A, w₂ = 2J_cc² B, w₁₂ = w₁ + I₁w₂, p = K ln J,
    // p_f = ⅓(w₁₂ tr C − w₂ tr C² + Tλ²); Tλ² = f λ (T = f/λ, see docs) only for
    // the deviatoric stretch, whose J^(−1/3) puts the fiber into the F̂⁻¹ term.
    const WideMask fiber_force = mu > 0.0 && (f < 0.0 || f > 0.0 || df < 0.0 || df > 0.0);
    const Wide w1 = 2.0 * A_ * Jcc;
    const Wide w2 = 2.0 * B_ * Jcc * Jcc;
    const Wide w12 = w1 + I1 * w2;
    const Wide p = K_ * volume.L;
    const Wide p_f = (w12 * I1 - w2 * trC2 + (deviatoric ? select(fiber_force, f * lambda, Wide(0.0)) : Wide(0.0))) *
                     (1.0 / 3.0);
    const Wide pressure = p - p_f;
    const Wide inverse_mu = select(mu > 0.0, 1.0 / select(mu > 0.0, mu, Wide(1.0)), Wide(0.0));
    double* destinations[kSimdLanes];

    if (P) {
        // eq. 15: P̂ = w₁₂ F̂ − w₂ F̂³ + (p − p_f) F̂⁻¹ + fiber, F̂⁻¹ → diag(ℓ') (§5.5); P = U P̂ Vᵀ. The
        // fiber part J_cc T F̂ f_m f_mᵀ (deviatoric) or (T/λ̃) F̂ f_m f_mᵀ (§4.3.3 WARNING,
        // PhysBAM) is (f λ/μ²) F̂ f_m f_mᵀ in both, μ = |F̂ f_m|, f_m = Vᵀa₀; rotated back,
        // U F̂ f_m = F a₀ and V f_m = a₀.
        Vector3<Wide> diagonal;
        for (int k = 0; k < 3; ++k)
            diagonal[k] = w12 * sigma[k] - w2 * sigma[k] * sigma[k] * sigma[k] + pressure * volume.slope[k];
        const Wide fiber_coefficient = select(fiber_force, f * lambda * inverse_mu * inverse_mu, Wide(0.0));
        Wide stress[9];  // column-major, as P
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                const Wide value = diagonal[0] * svd.U(i, 0) * svd.V(j, 0) + diagonal[1] * svd.U(i, 1) * svd.V(j, 1) +
                                   diagonal[2] * svd.U(i, 2) * svd.V(j, 2) + fiber_coefficient * image[i] * a0[j];
                stress[i + 3 * j] = select(defined, value, Wide(0.0));
            }
        for (int k = 0; k < lanes; ++k)
            destinations[k] = P[k].data();
        copy_lanes_to(stress, 9, destinations, lanes);
    }
    if (!dPdF)
        return;

    const FrameBlocks frame = frame_blocks(sigma, volume, w1, w2, I1, trC2, pressure, K_, c);

    // §4.5.2, eq. 45 rotated back with U F̂ f_m = F a₀ and V f_m = a₀: the fiber's
    // ∂²Φ/∂F² in vec(F) with t = f'λ² + fλ and s = fλ (0 without fiber force).
    FiberState fiber;
    fiber.a0 = a0;
    fiber.inverse_mu = inverse_mu;
    fiber.n = inverse_mu * image;
    if (deviatoric && fibers_on_) {
        // G = x − vec(S)/3, S = ∂L/∂F = U diag(ℓ') Vᵀ.
        for (int l = 0; l < 3; ++l)
            for (int i = 0; i < 3; ++i) {
                const Wide S = volume.slope[0] * svd.U(i, 0) * svd.V(l, 0) + volume.slope[1] * svd.U(i, 1) * svd.V(l, 1) +
                               volume.slope[2] * svd.U(i, 2) * svd.V(l, 2);
                fiber.G[i + 3 * l] = a0[l] * inverse_mu * fiber.n[i] - S * (1.0 / 3.0);
            }
    }
    const bool fiber_terms = fibers_on_;
    const Wide t = select(fiber_force, (df * lambda + f) * lambda, Wide(0.0));
    const Wide s = select(fiber_force, f * lambda, Wide(0.0));
    // ∂P/∂F = (V ⊗ U) K̂ (V ⊗ U)ᵀ + fiber part.
    const auto assemble = [&](const FrameBlocks& blocks, const Wide& tension, const Wide& stretch, Wide* K) {
        detail::rotate_frame_stiffness(svd.U, svd.V, blocks.A, blocks.alpha, blocks.beta,
                                       [&](int row, int column, const Wide& value) { K[row + 9 * column] = value; });
        if (fiber_terms)
            add_fiber_stiffness(fiber, deviatoric, tension, stretch, K);
    };

    Wide K[81];  // column-major, as ∂P/∂F
    if (projection != Projection::clamp) {
        assemble(frame, t, s, K);
    } else {
        // §5.6: clamp each block's eigenvalues at zero, the fiber tension derivative
        // f' (and f) at zero. Without fibers ∂P/∂F is block diagonal in the SVD frame
        // and this is its spectral clamp. The fiber terms are not block diagonal: the
        // sum can be PSD while a block or f' is not, and then the exact ∂P/∂F is kept.
        const ClampedFrame clamp = clamp_frame(frame);
        const WideMask fiber_clamped = deviatoric ? fiber_force : fiber_force && (f < 0.0 || df < 0.0);
        const WideMask clamped = clamp.clamped || fiber_clamped;
        // Where something is clamped and the fiber couples the blocks, the exact
        // ∂P/∂F is kept if it is PSD: proven indefinite by zᵀKz < 0 along a direction
        // the clamp changes (the block's negative direction, the negative modes
        // (E_ij ± E_ji)/√2, the fiber direction n̂ f_mᵀ), else by a Cholesky test.
        WideMask exact = !clamped;
        const WideMask coupled = clamped && fiber_force;
        if (any(coupled)) {
            FrameFiber frame_fiber;
            for (int k = 0; k < 3; ++k) {
                frame_fiber.n_hat[k] = dot(svd.U.col[k], fiber.n);
                frame_fiber.fm[k] = dot(svd.V.col[k], a0);
            }
            const auto negative_along = [&](const Matrix3<Wide>& Z) {
                return exact_quadratic_form(frame, frame_fiber, fiber, volume, deviatoric, t, s, Z) < 0.0;
            };
            Matrix3<Wide> Z;
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i)
                    Z(i, j) = i == j ? clamp.block_negative[i] : Wide(0.0);
            WideMask indefinite = clamp.block_clamped && negative_along(Z);
            for (int m = 0; m < 3; ++m)
                for (const double sign : {1.0, -1.0}) {
                    const Wide form = pair_mode_quadratic_form(frame, frame_fiber, fiber, m, sign, t, s);
                    indefinite = indefinite || ((sign > 0.0 ? clamp.plus_negative[m] : clamp.minus_negative[m]) && form < 0.0);
                }
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i)
                    Z(i, j) = frame_fiber.n_hat[i] * frame_fiber.fm[j];
            indefinite = indefinite || (fiber_clamped && negative_along(Z));
            const WideMask needs_test = coupled && !indefinite;
            if (any(needs_test)) {
                assemble(frame, t, s, K);
                Wide largest(0.0);
                for (int q = 0; q < 9; ++q)
                    largest = max(largest, abs(K[q + 9 * q]));
                exact = exact || (needs_test && detail::cholesky_succeeds<9>(K, kPsdTestShift * largest));
            }
        }
        // The projected fiber: f' and f raised to zero; for λ̃ the result,
        // f'₊ NNᵀ + (f₊/μ)(a₀a₀ᵀ ⊗ (I − nnᵀ)), is PSD as it stands; for the deviatoric
        // λ the rank-2 part (f'₊λ² + f₊λ) GGᵀ − f₊λ xxᵀ loses its negative eigenvalue
        // and the rest, (f₊λ/μ²)(a₀a₀ᵀ ⊗ (I − nnᵀ)), is PSD.
        const Wide f_plus = max(f, Wide(0.0)), df_plus = max(df, Wide(0.0));
        const Wide t_plus = select(fiber_force, (df_plus * lambda + f_plus) * lambda, Wide(0.0));
        const Wide s_plus = select(fiber_force, f_plus * lambda, Wide(0.0));
        assemble(select(exact, frame, clamp.projected), select(exact, t, t_plus), select(exact, s, s_plus), K);
        if (deviatoric && fiber_terms)
            remove_negative_pair(fiber, t_plus, s_plus, !exact && fiber_force, K);
    }
    if (any(!defined))
        for (Wide& entry : K)
            entry = select(defined, entry, Wide(0.0));
    for (int k = 0; k < lanes; ++k)
        destinations[k] = dPdF[k].data();
    copy_lanes_to(K, 81, destinations, lanes);
}

} // namespace sinew
