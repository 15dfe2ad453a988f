#include "sinew/energies/models/mooney_rivlin_muscle.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/psd_projection.hpp"
#include "sinew/energies/models/svd_batch.hpp"
#include "sinew/energies/models/svd_frame_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew {
namespace {

using Vec3 = Eigen::Vector3d;
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat3 = Eigen::Matrix3d;
using Mat9 = Eigen::Matrix<double, 9, 9>;

// The pairs (i, j) of the 2×2 blocks B_ij (seed 000 §4.5), pair k the one without k
// (the order of SvdFrameStiffness).
constexpr int kPairs[3][2] = {{1, 2}, {0, 2}, {0, 1}};
// σ_i + σ_j divides the thresholded ln J block; it vanishes only where an
// inverted σ₃ = −σ₂, where P itself has a kink (docs: inversion). Floored
// there to stay finite.
constexpr double kPairSumFloor = 1e-9;
// Relative diagonal shift of the PSD test of the exact ∂P/∂F.
constexpr double kPsdTestShift = 1e-12;

/// L = ln J with the inversion threshold c (seed 000 §5.5): L = Σ ℓ(σ_k),
/// ℓ(σ) = ln σ for σ ≥ c and ln c + (σ − c)/c below, the tangent of ln σ at
/// c. C¹ in σ, finite through σ = 0 and for σ₃ < 0.
struct LogVolume {
    double L = 0.0;
    Vec3 slope;      ///< ℓ'(σ_k) = 1/max(σ_k, c): F̂⁻¹ in §4.3, the third column of F_base (§4.5.1)
    Vec3 curvature;  ///< ℓ''(σ_k) = −1/σ_k² at or above c, 0 below
    Vec3 below;      ///< 1 where σ_k < c, else 0
};

/// J = det F is used as is when no σ_k is below c, so that ψ is the same
/// number whether or not an SVD was computed.
LogVolume log_volume(const Vec3& sigma, double c, double J)
{
    LogVolume v;
    bool clamped = false;
    for (int k = 0; k < 3; ++k) {
        const bool below = sigma[k] < c;
        clamped = clamped || below;
        v.below[k] = below ? 1.0 : 0.0;
        v.slope[k] = 1.0 / std::max(sigma[k], c);
        v.curvature[k] = below ? 0.0 : -v.slope[k] * v.slope[k];
    }
    if (!clamped) {
        v.L = std::log(J);
        return v;
    }
    for (int k = 0; k < 3; ++k)
        v.L += sigma[k] < c ? std::log(c) + (sigma[k] - c) / c : std::log(sigma[k]);
    return v;
}

/// The 2×2 block [[a, b], [b, a]] of ∂²L on (δF̂_ij, δF̂_ji), from g = ℓ':
/// a = (D⁻ + S⁺)/2, b = (D⁻ − S⁺)/2 with the divided differences
/// D⁻ = (g_i − g_j)/(σ_i − σ_j) = −r g_i g_j, r = (σ̂_i − σ̂_j)/(σ_i − σ_j) ∈ [0, 1]
/// (σ̂ = max(σ, c): r = 1 when neither is below c, 0 when both are, so ties
/// need no division) and S⁺ = (g_i + g_j)/(σ_i + σ_j). With no σ below c:
/// a = 0, b = −1/(σ_i σ_j), the ∂F⁻ᵀ/∂F term of §4.5.1.1 (eq. 26).
struct PairBlock {
    double a;
    double b;
};

PairBlock log_volume_pair(const LogVolume& v, const Vec3& sigma, double c, int i, int j)
{
    const double product = v.slope[i] * v.slope[j];
    if (v.below[i] + v.below[j] == 0.0)
        return {0.0, -product};
    double r = 0.0;
    if (v.below[i] != v.below[j])
        r = std::clamp((std::max(sigma[i], c) - std::max(sigma[j], c)) / (sigma[i] - sigma[j]), 0.0, 1.0);
    const double difference = -r * product;
    const double sum = (v.slope[i] + v.slope[j]) / std::max(sigma[i] + sigma[j], kPairSumFloor);
    return {0.5 * (difference + sum), 0.5 * (difference - sum)};
}

/// Clamps the negative eigenvalues of the symmetric 3×3 A to zero (§5.6),
/// A ← A − A₋ (negative_part_3x3); false, A untouched, when it has none
/// (Sylvester's criterion first). `negative` receives a unit eigenvector q of
/// a negative eigenvalue (qᵀAq < 0): only the eigenpairs whose sign differs
/// from the others enter A₋, and they are well conditioned, their error
/// ~ε|A|/gap weighted by |ν| ≤ gap.
bool clamp_block(Mat3& A, Vec3& negative)
{
    if (A(0, 0) > 0.0 && A(0, 0) * A(1, 1) - A(0, 1) * A(0, 1) > 0.0 && A.determinant() > 0.0)
        return false;
    const NegativePart3 part = negative_part_3x3(A);
    if (part.part.isZero(0.0))
        return false;
    A -= part.part;
    negative = part.direction;
    return true;
}

/// Clamps the eigenvalues α ± β of each B_ij to zero (§5.6); false when none is negative.
bool clamp_pairs(SvdFrameStiffness& frame)
{
    bool changed = false;
    for (int m = 0; m < 3; ++m) {
        const double plus = frame.alpha[m] + frame.beta[m], minus = frame.alpha[m] - frame.beta[m];
        if (plus >= 0.0 && minus >= 0.0)
            continue;
        const double plus_clamped = std::max(plus, 0.0), minus_clamped = std::max(minus, 0.0);
        frame.alpha[m] = 0.5 * (plus_clamped + minus_clamped);
        frame.beta[m] = 0.5 * (plus_clamped - minus_clamped);
        changed = true;
    }
    return changed;
}

/// The fiber's ∂²Φ/∂F² in vec(F) (seed 000 §4.5.2). With n = F a₀/μ,
/// x = ∂ln μ/∂F = vec(n a₀ᵀ)/μ and G = ∂ln λ/∂F (= x for λ̃; x − S/3 for the
/// deviatoric λ, S = ∂L/∂F = vec(U diag(ℓ') Vᵀ)), ∂Φ/∂F = fλG and
///   ∂²Φ = (f'λ² + fλ) GGᵀ − 2fλ xxᵀ + (fλ/μ²)(a₀a₀ᵀ ⊗ I₃)   [− (fλ/3)∂²L, in p_f].
/// For λ̃ this is eq. 45: (f' − c₁) vec(n a₀ᵀ)vec(n a₀ᵀ)ᵀ + c₁ (a₀a₀ᵀ ⊗ I₃),
/// c₁ = f/λ̃, i.e. δP₄ = (c₁ δF a₀ + c₂ (δF a₀ · F a₀) F a₀) a₀ᵀ, c₂ = (f' − c₁)/λ̃².
struct FiberStiffness {
    Vec3 n = Vec3::Zero();
    Vec3 a0 = Vec3::Zero();
    Vec9 G = Vec9::Zero();  ///< used for the deviatoric λ only
    double mu = 0.0;
    double lambda = 0.0;
    bool deviatoric = false;

    /// x = vec(n a₀ᵀ)/μ
    Vec9 x() const
    {
        Vec9 w;
        for (int l = 0; l < 3; ++l)
            w.segment<3>(3 * l) = (a0[l] / mu) * n;
        return w;
    }
};

/// K += (a₀a₀ᵀ ⊗ (c_n nnᵀ + c_I I₃))/μ², block (j, l) scaled by a₀_j a₀_l:
/// c_n xxᵀ + (c_I/μ²)(a₀a₀ᵀ ⊗ I₃).
void add_fiber_blocks(const FiberStiffness& fiber, double c_n, double c_I, Mat9& K)
{
    Mat3 core = c_n * fiber.n * fiber.n.transpose();
    core.diagonal().array() += c_I;
    core /= fiber.mu * fiber.mu;
    for (int l = 0; l < 3; ++l)
        for (int j = 0; j < 3; ++j)
            K.block<3, 3>(3 * j, 3 * l) += (fiber.a0[j] * fiber.a0[l]) * core;
}

void add_fiber_stiffness(const FiberStiffness& fiber, double f, double df, Mat9& K)
{
    const double tension = (df * fiber.lambda + f) * fiber.lambda;  // f'λ² + fλ
    const double s = f * fiber.lambda;
    if (fiber.deviatoric) {
        K.noalias() += tension * fiber.G * fiber.G.transpose();
        add_fiber_blocks(fiber, -2.0 * s, s, K);
    } else {
        add_fiber_blocks(fiber, tension - 2.0 * s, s, K);  // (f' − c₁) NNᵀ + c₁ (a₀a₀ᵀ ⊗ I)
    }
}

/// The rank-2 term t GGᵀ − s xxᵀ (t, s ≥ 0) with its negative eigenvalue ν₋
/// clamped to zero. In span{G, x} the term is [G x] diag(t, −s) [G x]ᵀ, so its
/// eigenvalues are those of diag(t, −s)·Gram; ν₋ ≤ 0 since the Gram
/// determinant is ≥ 0, and y = t(G·x) G + (ν₋ − t|G|²) x solves the G row.
void add_clamped_pair(double t, const Vec9& G, double s, const Vec9& x, Mat9& K)
{
    K.noalias() += t * G * G.transpose();
    K.noalias() -= s * x * x.transpose();
    const double gg = G.squaredNorm(), xx = x.squaredNorm(), gx = G.dot(x);
    const double mean = 0.5 * (t * gg - s * xx);
    const double radius = std::sqrt(std::max(0.25 * (t * gg + s * xx) * (t * gg + s * xx) - t * s * gx * gx, 0.0));
    const double negative = mean - radius;
    if (!(negative < 0.0))
        return;
    const Vec9 y = (t * gx) * G + (negative - t * gg) * x;
    const double yy = y.squaredNorm();
    if (yy > 0.0)
        K.noalias() -= (negative / yy) * y * y.transpose();
}

/// §5.6 for the fiber: f' and f raised to zero. For λ̃ the result,
/// f'₊ NNᵀ + (f₊/μ)(a₀a₀ᵀ ⊗ (I − nnᵀ)), is PSD as it stands; for the
/// deviatoric λ the rank-2 part (f'₊λ² + f₊λ) GGᵀ − f₊λ xxᵀ loses its
/// negative eigenvalue and the rest, (f₊λ/μ²)(a₀a₀ᵀ ⊗ (I − nnᵀ)), is PSD.
void add_projected_fiber_stiffness(const FiberStiffness& fiber, double f, double df, Mat9& K)
{
    const double f_plus = std::max(f, 0.0), df_plus = std::max(df, 0.0);
    if (!fiber.deviatoric) {
        add_fiber_stiffness(fiber, f_plus, df_plus, K);
        return;
    }
    const double s = f_plus * fiber.lambda;
    add_clamped_pair((df_plus * fiber.lambda + f_plus) * fiber.lambda, fiber.G, s, fiber.x(), K);
    add_fiber_blocks(fiber, -s, s, K);
}

/// The fiber in the SVD frame: n̂ = Uᵀn, f_m = Vᵀa₀ (§4.3), for quadratic
/// forms of the exact ∂P/∂F along SVD-frame directions.
struct FrameFiber {
    Vec3 n_hat = Vec3::Zero();
    Vec3 fm = Vec3::Zero();
    Vec3 slope = Vec3::Zero();  ///< ℓ': S = ∂L/∂F is diag(ℓ') in this frame
    double mu = 1.0;
    double tension = 0.0;  ///< f'λ² + fλ
    double s = 0.0;        ///< fλ
    bool deviatoric = false;
};

/// zᵀ K z for the exact ∂P/∂F and z = vec(U Ẑ Vᵀ), |Ẑ| = 1: the blocks give
/// Σ_kl A_kl Ẑ_kk Ẑ_ll + Σ_ij α_ij(Ẑ_ij² + Ẑ_ji²) + 2β_ij Ẑ_ij Ẑ_ji, the fiber
/// t(G·z)² − 2s(x·z)² + (s/μ²)|Ẑ f_m|² with x·z = n̂ᵀẐ f_m/μ and
/// G·z = x·z − (Σ_k Ẑ_kk ℓ'_k)/3 for the deviatoric λ (G = x otherwise).
double exact_quadratic_form(const SvdFrameStiffness& frame, const FrameFiber& fiber, const Mat3& Z)
{
    const Vec3 d = Z.diagonal();
    double value = d.dot(frame.diagonal_block * d);
    for (int m = 0; m < 3; ++m) {
        const int i = kPairs[m][0], j = kPairs[m][1];
        value += frame.alpha[m] * (Z(i, j) * Z(i, j) + Z(j, i) * Z(j, i)) + 2.0 * frame.beta[m] * Z(i, j) * Z(j, i);
    }
    const Vec3 Zf = Z * fiber.fm;
    const double xz = fiber.n_hat.dot(Zf) / fiber.mu;
    const double Gz = fiber.deviatoric ? xz - d.dot(fiber.slope) / 3.0 : xz;
    return value + fiber.tension * Gz * Gz - 2.0 * fiber.s * xz * xz + fiber.s / (fiber.mu * fiber.mu) * Zf.squaredNorm();
}

/// True when zᵀKz < 0 for the exact ∂P/∂F along a direction the §5.6 clamp
/// changes: the 3×3 block's negative direction (when clamped), the negative
/// modes (E_ij ± E_ji)/√2 of the B_ij, the fiber direction n̂ f_mᵀ (when f'
/// or f is clamped). Then K is indefinite without a 9×9 test.
bool indefinite_along_clamped_directions(const SvdFrameStiffness& frame, const FrameFiber& fiber,
                                         const Vec3* block_negative, bool fiber_clamped)
{
    if (block_negative && exact_quadratic_form(frame, fiber, block_negative->asDiagonal()) < 0.0)
        return true;
    for (int m = 0; m < 3; ++m) {
        const int i = kPairs[m][0], j = kPairs[m][1];
        for (const double sign : {1.0, -1.0}) {
            if (frame.alpha[m] + sign * frame.beta[m] >= 0.0)
                continue;
            Mat3 mode = Mat3::Zero();
            mode(i, j) = std::sqrt(0.5);
            mode(j, i) = sign * std::sqrt(0.5);
            if (exact_quadratic_form(frame, fiber, mode) < 0.0)
                return true;
        }
    }
    return fiber_clamped && exact_quadratic_form(frame, fiber, fiber.n_hat * fiber.fm.transpose()) < 0.0;
}

/// Cholesky of K + δI, δ = kPsdTestShift·max|K_ii|, succeeds: K is positive
/// semidefinite to that tolerance.
bool positive_semidefinite(const Mat9& K)
{
    const double shift = kPsdTestShift * K.diagonal().cwiseAbs().maxCoeff();
    Mat9 L = K;
    for (int j = 0; j < 9; ++j) {
        double pivot = L(j, j) + shift;
        for (int k = 0; k < j; ++k)
            pivot -= L(j, k) * L(j, k);
        if (!(pivot > 0.0))
            return false;
        const double inverse = 1.0 / std::sqrt(pivot);
        for (int i = j + 1; i < 9; ++i) {
            double value = L(i, j);
            for (int k = 0; k < j; ++k)
                value -= L(i, k) * L(j, k);
            L(i, j) = value * inverse;
        }
    }
    return true;
}

double undefined(Model3d::Stress* P, Model3d::Stiffness* dPdF)
{
    if (P)
        P->setZero();
    if (dPdF)
        dPdF->setZero();
    return std::numeric_limits<double>::infinity();
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

/// What ψ is made of at one F, shared by energy() and evaluate().
struct MooneyRivlinMuscle::Terms {
    double psi = 0.0;
    double I1 = 0.0;    ///< tr C = |F|², C = FᵀF (seed §4.3.4: C is not the deviatoric C̄)
    double trC2 = 0.0;  ///< tr C²
    double Jcc = 0.0;   ///< J_cc = e^(−2L/3) (= J^(−2/3) above the threshold)
    Vec3 image = Vec3::Zero();  ///< F a₀
    double mu = 0.0;            ///< |F a₀| = λ̃
    double lambda = 0.0;        ///< the fiber stretch of the chosen definition
    double f = 0.0;             ///< α f_a(λ) + f_p(λ) = ∂Φ/∂λ
    double df = 0.0;            ///< α f_a'(λ) + f_p'(λ)
};

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

MooneyRivlinMuscle::Terms MooneyRivlinMuscle::terms(const Deformation& F, double L, const Point& point) const
{
    Terms t;
    // §4.2, §4.3.4: Ī₁ = J_cc tr C, Ī₂ = J_cc² ½((tr C)² − tr C²).
    const Mat3 C = F.transpose() * F;
    t.I1 = C.trace();
    t.trC2 = C.squaredNorm();
    t.Jcc = std::exp(-2.0 / 3.0 * L);
    t.psi = A_ * t.Jcc * t.I1 + B_ * t.Jcc * t.Jcc * 0.5 * (t.I1 * t.I1 - t.trC2) + 0.5 * K_ * L * L;
    if (!fibers_on_)
        return t;
    // §4.3.3: λ̃ = |F a₀| (PhysBAM) or λ = J^(−1/3)|F a₀| (the note's §4.2).
    t.image = F * point.fiber;
    t.mu = t.image.norm();
    t.lambda = stretch_ == FiberStretch::physbam ? t.mu : t.mu * std::exp(-L / 3.0);
    const FiberCurvePoint active = active_.evaluate(t.lambda);
    const FiberCurvePoint passive = passive_.evaluate(t.lambda);
    const double alpha = point.activation;
    t.psi += alpha * active.energy + passive.energy;  // F₂ = α F_active + F_passive
    t.f = alpha * active.stress + passive.stress;
    t.df = alpha * active.stiffness + passive.stiffness;
    return t;
}

double MooneyRivlinMuscle::energy(const Deformation& F, const Point& point) const
{
    if (!F.allFinite())
        return std::numeric_limits<double>::infinity();
    const double J = F.determinant();
    // σ_min = J/(σ₀σ₁) ≥ 2J/|F|² (σ₀σ₁ ≤ ½(σ₀² + σ₁²)): when that bound is at
    // least c no singular value is below the threshold and L = ln J.
    if (J > 0.0 && 2.0 * J >= threshold_ * F.squaredNorm())
        return terms(F, std::log(J), point).psi;
    if (threshold_ == 0.0)
        return std::numeric_limits<double>::infinity();
    const RotationVariantSvd<3> svd = fast_rotation_variant_svd(F);
    return terms(F, log_volume(svd.sigma, threshold_, J).L, point).psi;
}

double MooneyRivlinMuscle::evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                                    Projection projection) const
{
    double psi = 0.0;
    evaluate_batch(1, &F, &point, &psi, P, dPdF, projection);
    return psi;
}

void MooneyRivlinMuscle::evaluate_batch(int count, const Deformation* F, const Point* points, double* psi,
                                        Stress* P, Stiffness* dPdF, Projection projection) const
{
    evaluate_with_svds(count, F, points, psi, P, dPdF, P || dPdF,
                       [&](const Deformation& Fk, const RotationVariantSvd<3>* svd, const Point& point, Stress* Pk,
                           Stiffness* dPdFk, DeferredRotation& deferred) {
                           return evaluate_with_svd(Fk, svd, point, Pk, dPdFk, projection, deferred);
                       });
}

double MooneyRivlinMuscle::evaluate_with_svd(const Deformation& F, const RotationVariantSvd<3>* known_svd,
                                             const Point& point, Stress* P, Stiffness* dPdF,
                                             Projection projection, DeferredRotation& deferred) const
{
    if (!P && !dPdF)
        return energy(F, point);
    if (!F.allFinite())
        return undefined(P, dPdF);
    // §4.3, §5.4: F = U F̂ Vᵀ, F̂ = diag(σ) with U, V rotations; an inversion
    // puts its sign on σ₃ (the smallest |σ|).
    const RotationVariantSvd<3>& svd = *known_svd;
    const Vec3& sigma = svd.sigma;
    const double c = threshold_;
    const double J = F.determinant();
    if (c == 0.0 && !(J > 0.0 && sigma[2] > 0.0))
        return undefined(P, dPdF);
    const LogVolume volume = log_volume(sigma, c, J);
    const Terms t = terms(F, volume.L, point);
    const Vec3 sq = sigma.cwiseAbs2();
    const Vec3 cube = sigma.cwiseProduct(sq);

    // §4.3.4 with C = F̂²: w₁ = 2J_cc A, w₂ = 2J_cc² B, w₁₂ = w₁ + I₁w₂, p = K ln J,
    // p_f = ⅓(w₁₂ tr C − w₂ tr C² + Tλ²); Tλ² = f λ (T = f/λ, see docs) only for
    // the deviatoric stretch, whose J^(−1/3) puts the fiber into the F̂⁻¹ term.
    const bool fiber_force = t.mu > 0.0 && (t.f != 0.0 || t.df != 0.0);
    const bool deviatoric = fiber_force && stretch_ == FiberStretch::deviatoric;
    const double w1 = 2.0 * t.Jcc * A_;
    const double w2 = 2.0 * t.Jcc * t.Jcc * B_;
    const double w12 = w1 + t.I1 * w2;
    const double p = K_ * volume.L;
    const double p_f = (w12 * t.I1 - w2 * t.trC2 + (deviatoric ? t.f * t.lambda : 0.0)) / 3.0;

    if (P) {
        // eq. 15: P̂ = w₁₂ F̂ − w₂ F̂³ + (p − p_f) F̂⁻¹ + fiber, F̂⁻¹ → diag(ℓ') (§5.5). The
        // fiber part J_cc T F̂ f_m f_mᵀ (deviatoric) or (T/λ̃) F̂ f_m f_mᵀ (§4.3.3
        // WARNING, PhysBAM) is (f λ/μ²) F̂ f_m f_mᵀ in both, μ = |F̂ f_m|.
        Mat3 P_hat = (w12 * sigma - w2 * cube + (p - p_f) * volume.slope).asDiagonal();
        if (fiber_force) {
            const Vec3 fm = svd.V.transpose() * point.fiber;  // §4.3: f_m = Vᵀa₀
            P_hat.noalias() += (t.f * t.lambda / (t.mu * t.mu)) * sigma.cwiseProduct(fm) * fm.transpose();
        }
        *P = svd.U * P_hat * svd.V.transpose();  // P = U P̂ Vᵀ
    }
    if (!dPdF)
        return t.psi;

    // §4.5.1.4: η from the second partials of ψ(tr C, tr C², L); γ = F_base η F_baseᵀ
    // with F_base rows (σ_k, σ_k³, ℓ'_k). η₁₃ is −(4/3)AJ_cc − (8/3)BJ_cc² tr C
    // (the summary's first line has 8/9: see docs).
    Mat3 eta;
    eta << 2.0 * w2, 0.0, -2.0 / 3.0 * w1 - 4.0 / 3.0 * w2 * t.I1,  //
        0.0, 0.0, 4.0 / 3.0 * w2,                                     //
        -2.0 / 3.0 * w1 - 4.0 / 3.0 * w2 * t.I1, 4.0 / 3.0 * w2,
        K_ + 2.0 / 9.0 * w1 * t.I1 + 4.0 / 9.0 * w2 * (t.I1 * t.I1 - t.trC2);
    Mat3 base;
    base.col(0) = sigma;
    base.col(1) = cube;
    base.col(2) = volume.slope;
    SvdFrameStiffness frame;
    frame.diagonal_block.noalias() = base * eta * base.transpose();
    // A = diag(α_kk + β_kk) + γ: α_kk = w₁₂ − 2w₂σ_k², β_kk = (p − p_f) ℓ''_k − w₂σ_k²
    // (−(p − p_f)/σ_k² above the threshold).
    frame.diagonal_block.diagonal() += Vec3::Constant(w12) - 3.0 * w2 * sq + (p - p_f) * volume.curvature;
    // B_ij: α_ij = w₁₂ − w₂(σ_i² + σ_j²) + (p − p_f) a_ij,
    //       β_ij = −w₂σ_iσ_j + (p − p_f) b_ij (−(p − p_f)/(σ_iσ_j) above the threshold).
    for (int m = 0; m < 3; ++m) {
        const int i = kPairs[m][0], j = kPairs[m][1];
        const PairBlock log_block = log_volume_pair(volume, sigma, c, i, j);
        frame.alpha[m] = w12 - w2 * (sq[i] + sq[j]) + (p - p_f) * log_block.a;
        frame.beta[m] = -w2 * sigma[i] * sigma[j] + (p - p_f) * log_block.b;
    }

    // §4.5.2, eq. 45 rotated back with U F̂ f_m = F a₀ and V f_m = a₀.
    FiberStiffness fiber;
    if (fiber_force) {
        fiber.n = t.image / t.mu;
        fiber.a0 = point.fiber;
        fiber.mu = t.mu;
        fiber.lambda = t.lambda;
        fiber.deviatoric = deviatoric;
        if (deviatoric) {
            const Mat3 dL = svd.U * volume.slope.asDiagonal() * svd.V.transpose();  // S = ∂L/∂F
            fiber.G = fiber.x() - Eigen::Map<const Vec9>(dL.data()) / 3.0;
        }
    }
    Stiffness& K = *dPdF;
    // The fiber part goes into K at once, the frame blocks to `deferred`
    // (rotated to vec(F) with the rest of the batch).
    const auto assemble_exact = [&] {
        K.setZero();
        if (fiber_force)
            add_fiber_stiffness(fiber, t.f, t.df, K);
        deferred.add(frame);
    };
    if (projection != Projection::clamp) {
        assemble_exact();
        return t.psi;
    }

    // §5.6: clamp each block's eigenvalues at zero, the fiber tension
    // derivative f' (and f) at zero. Without fibers ∂P/∂F is block diagonal in
    // the SVD frame and this is its spectral clamp. The fiber terms are not
    // block diagonal: the sum can be PSD while a block or f' is not, and then
    // the exact ∂P/∂F is kept.
    SvdFrameStiffness projected = frame;
    Vec3 block_negative;
    const bool block_clamped = clamp_block(projected.diagonal_block, block_negative);
    const bool pair_clamped = clamp_pairs(projected);
    const bool fiber_clamped = fiber_force && (t.f < 0.0 || t.df < 0.0 || deviatoric);
    if (!(block_clamped || pair_clamped || fiber_clamped)) {
        assemble_exact();
        return t.psi;
    }
    if (fiber_force) {
        FrameFiber frame_fiber;
        frame_fiber.n_hat = svd.U.transpose() * fiber.n;
        frame_fiber.fm = svd.V.transpose() * point.fiber;
        frame_fiber.slope = volume.slope;
        frame_fiber.mu = t.mu;
        frame_fiber.tension = (t.df * t.lambda + t.f) * t.lambda;
        frame_fiber.s = t.f * t.lambda;
        frame_fiber.deviatoric = deviatoric;
        const bool indefinite =
            indefinite_along_clamped_directions(frame, frame_fiber, block_clamped ? &block_negative : nullptr, fiber_clamped);
        if (!indefinite) {
            // The test needs the whole exact ∂P/∂F now.
            rotate_svd_frame_stiffness(svd.U, svd.V, frame, Accumulate::assign, K);
            add_fiber_stiffness(fiber, t.f, t.df, K);
            if (positive_semidefinite(K))
                return t.psi;
        }
    }
    K.setZero();
    if (fiber_force)
        add_projected_fiber_stiffness(fiber, t.f, t.df, K);
    deferred.add(projected);
    return t.psi;
}

} // namespace sinew
