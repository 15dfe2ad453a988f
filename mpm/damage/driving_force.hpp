#pragma once
// AnisoMPM's driving force of damage (seed 004 Alg. 5 lines 4–11, Alg. 8):
// from the positive part of the undegraded Cauchy stress, weighted by the
// structural tensor, against the critical stress.
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/damage/phase_field_point.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <optional>

namespace sinew {

template <int Dim>
struct DrivingForce {
    Eigen::Matrix<double, Dim, Dim> tension;  ///< σ⁺ = Σ_a ⟨σ_a⟩ n_a n_aᵀ
    double phi = 0.0;                         ///< Φ = (Aσ⁺):(σ⁺A)/σ_c²
    double current = 0.0;                     ///< ζ⟨Φ − 1⟩, before the history's max
};

/// σ = P Fᵀ / J of `model` at F with the point's damage set to 0 (the
/// undegraded stress the seed asks for, whatever the model's degradation);
/// nullopt where J ≤ 0 or σ is not finite.
template <int Dim>
std::optional<Eigen::Matrix<double, Dim, Dim>> undegraded_cauchy_stress(const ConstitutiveModel<Dim, Dim>& model,
                                                                        const Eigen::Matrix<double, Dim, Dim>& F,
                                                                        MaterialPoint<Dim> point);

/// σ⁺ by a symmetric eigen-decomposition of σ (Eigen's SelfAdjointEigenSolver,
/// σ = Σ_a σ_a n_a n_aᵀ, ⟨x⟩ = (x + |x|)/2), Φ with A = structural_tensor(F),
/// and ζ⟨Φ − 1⟩; nullopt where the stress is (undegraded_cauchy_stress).
template <int Dim>
std::optional<DrivingForce<Dim>> driving_force(const ConstitutiveModel<Dim, Dim>& model,
                                               const Eigen::Matrix<double, Dim, Dim>& F,
                                               const MaterialPoint<Dim>& point, const PhaseFieldPoint<Dim>& field);

/// D̃ = max(ζ⟨Φ − 1⟩, D̃ᴴ): the driving force never decreases (the
/// damage's irreversibility rests on it, seed 004 §2.2).
inline double driving_force_with_history(double current, double history) { return std::max(current, history); }

/// The σ_c for which Φ = 1 exactly at the uniform stretch F = (1 + p) I
/// (R = I there): σ_c = √((Aσ⁺):(σ⁺A)) of the undegraded model, the point's
/// own structural tensor included, so that damage starts at the stretch p
/// for this material. The seed leaves σ_c to tuning ("a stress
/// corresponding to some uniform stretch", seed 004 Alg. 1); this is the
/// precise form sinew gives it. InputError for p not finite or ≤ 0, or
/// when that stress has no tension A sees.
template <int Dim>
double critical_stress_from_stretch(const ConstitutiveModel<Dim, Dim>& model, const MaterialPoint<Dim>& point,
                                    const PhaseFieldPoint<Dim>& field, double p);

} // namespace sinew
