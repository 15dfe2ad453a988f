#pragma once
// Random deformation gradients in the regimes every model test covers, and
// the finite-difference checks of ψ → P → ∂P/∂F shared by all model tests.
#include "sinew/energies/models/constitutive_model.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace sinew::test {

enum class Regime { near_identity, moderate, large_stretch, compression, rotated, near_inversion };

inline std::vector<Regime> all_regimes()
{
    return {Regime::near_identity, Regime::moderate,  Regime::large_stretch,
            Regime::compression,   Regime::rotated,   Regime::near_inversion};
}

inline std::string regime_name(Regime r)
{
    switch (r) {
    case Regime::near_identity: return "near_identity";
    case Regime::moderate: return "moderate";
    case Regime::large_stretch: return "large_stretch";
    case Regime::compression: return "compression";
    case Regime::rotated: return "rotated";
    case Regime::near_inversion: return "near_inversion";
    }
    return "?";
}

template <int N>
Eigen::Matrix<double, N, N> random_rotation(std::mt19937& rng)
{
    std::normal_distribution<double> normal;
    Eigen::Matrix<double, N, N> A;
    for (int i = 0; i < N * N; ++i)
        A.data()[i] = normal(rng);
    Eigen::HouseholderQR<Eigen::Matrix<double, N, N>> qr(A);
    Eigen::Matrix<double, N, N> Q = qr.householderQ();
    if (Q.determinant() < 0)
        Q.col(0) *= -1.0;
    return Q;
}

/// Singular values drawn for the regime, then F = U diag(σ) Vᵀ (Rows × Cols,
/// Rows >= Cols) with random rotations U, V. Stretch up to ×4, compression
/// down to 0.1, near inversion: smallest σ in [0.02, 0.1].
template <int Rows, int Cols>
Eigen::Matrix<double, Rows, Cols> random_deformation(Regime regime, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    Eigen::Matrix<double, Cols, 1> sigma;
    for (int i = 0; i < Cols; ++i) {
        switch (regime) {
        case Regime::near_identity: sigma[i] = 1.0 + 0.02 * (2 * u01(rng) - 1); break;
        case Regime::moderate: sigma[i] = 0.7 + 0.6 * u01(rng); break;
        case Regime::large_stretch: sigma[i] = 1.0 + 3.0 * u01(rng); break;
        case Regime::compression: sigma[i] = 0.1 + 0.9 * u01(rng); break;
        case Regime::rotated: sigma[i] = 0.8 + 0.4 * u01(rng); break;
        case Regime::near_inversion: sigma[i] = (i == 0) ? 0.02 + 0.08 * u01(rng) : 0.5 + u01(rng); break;
        }
    }
    const Eigen::Matrix<double, Rows, Rows> U = random_rotation<Rows>(rng);
    const Eigen::Matrix<double, Cols, Cols> V = random_rotation<Cols>(rng);
    Eigen::Matrix<double, Rows, Cols> S = Eigen::Matrix<double, Rows, Cols>::Zero();
    for (int i = 0; i < Cols; ++i)
        S(i, i) = sigma[i];
    if (regime == Regime::near_identity)
        return Eigen::Matrix<double, Rows, Cols>::Identity() + 0.02 * (U * S * V.transpose() - Eigen::Matrix<double, Rows, Cols>::Identity());
    return U * S * V.transpose();
}

template <int Dim>
Eigen::Matrix<double, Dim, 1> random_unit_vector(std::mt19937& rng)
{
    std::normal_distribution<double> normal;
    Eigen::Matrix<double, Dim, 1> v;
    do {
        for (int i = 0; i < Dim; ++i)
            v[i] = normal(rng);
    } while (v.norm() < 1e-3);
    return v.normalized();
}

/// Relative difference used by every comparison: |a - b|∞ / max(scale, |b|∞).
template <typename A, typename B>
double relative_difference(const A& a, const B& b, double scale)
{
    return (a - b).cwiseAbs().maxCoeff() / std::max(scale, b.cwiseAbs().maxCoeff());
}

/// P by central differences of ψ, step h·max(1, |F|∞).
template <int Rows, int Cols>
typename ConstitutiveModel<Rows, Cols>::Stress
finite_difference_stress(const ConstitutiveModel<Rows, Cols>& model,
                         const typename ConstitutiveModel<Rows, Cols>::Deformation& F,
                         const MaterialPoint<Cols>& point, double h)
{
    typename ConstitutiveModel<Rows, Cols>::Stress P;
    const double step = h * std::max(1.0, F.cwiseAbs().maxCoeff());
    for (int k = 0; k < Rows * Cols; ++k) {
        auto Fp = F, Fm = F;
        Fp.data()[k] += step;
        Fm.data()[k] -= step;
        P.data()[k] = (model.energy(Fp, point) - model.energy(Fm, point)) / (2 * step);
    }
    return P;
}

/// ∂P/∂F by central differences of P, column k = vec index of F_kl.
template <int Rows, int Cols>
typename ConstitutiveModel<Rows, Cols>::Stiffness
finite_difference_stiffness(const ConstitutiveModel<Rows, Cols>& model,
                            const typename ConstitutiveModel<Rows, Cols>::Deformation& F,
                            const MaterialPoint<Cols>& point, double h)
{
    using M = ConstitutiveModel<Rows, Cols>;
    typename M::Stiffness K;
    const double step = h * std::max(1.0, F.cwiseAbs().maxCoeff());
    for (int k = 0; k < Rows * Cols; ++k) {
        auto Fp = F, Fm = F;
        Fp.data()[k] += step;
        Fm.data()[k] -= step;
        typename M::Stress Pp, Pm;
        model.evaluate(Fp, point, &Pp, nullptr, Projection::none);
        model.evaluate(Fm, point, &Pm, nullptr, Projection::none);
        const typename M::Stress dP = (Pp - Pm) / (2 * step);
        for (int r = 0; r < Rows * Cols; ++r)
            K(r, k) = dP.data()[r];
    }
    return K;
}

/// ∂ψ/∂α and ∂P/∂α by central differences in the activation of `point`
/// (steps α ± h, which may leave [0, 1]: the models are defined for any α).
template <int Rows, int Cols>
struct ActivationDifferences {
    double dpsi = 0.0;
    typename ConstitutiveModel<Rows, Cols>::Stress dP;
};

template <int Rows, int Cols>
ActivationDifferences<Rows, Cols>
finite_difference_activation(const ConstitutiveModel<Rows, Cols>& model,
                             const typename ConstitutiveModel<Rows, Cols>::Deformation& F,
                             const MaterialPoint<Cols>& point, double h)
{
    MaterialPoint<Cols> plus = point, minus = point;
    plus.activation += h;
    minus.activation -= h;
    typename ConstitutiveModel<Rows, Cols>::Stress Pp, Pm;
    const double psi_plus = model.evaluate(F, plus, &Pp, nullptr, Projection::none);
    const double psi_minus = model.evaluate(F, minus, &Pm, nullptr, Projection::none);
    ActivationDifferences<Rows, Cols> differences;
    differences.dpsi = (psi_plus - psi_minus) / (2 * h);
    differences.dP = (Pp - Pm) / (2 * h);
    return differences;
}

} // namespace sinew::test
