#pragma once
#include <vector>

namespace sinew {

/// How the grid inextensibility is enforced in a step.
enum class InextensibilityMethod {
    /// The seed's (seed 004 Alg. 11): the grid velocities after the grid
    /// update (explicit) or after the implicit solve, projected by CG on the
    /// Schur complement B M⁻¹ Bᵀ.
    schur_cg,
    /// Implicit steps: the rows as equality constraints of the grid-velocity
    /// NLP, solved by the run's solver (kkt-newton, relaxed-kkt, penalty,
    /// augmented-lagrangian, ipopt).
    nlp
};

/// What keeps the positional constraint a₀ᵀ C a₀ = 1 from drifting, the
/// velocity-level rows constraining only its rate.
enum class FiberDriftCorrection {
    none,
    /// After every step, F ← F + (1/|F a₀| − 1)(F a₀) a₀ᵀ/|a₀|²: |F a₀| = 1
    /// exactly, F b unchanged for b ⊥ a₀.
    projection
};

struct InextensibilitySettings {
    std::vector<char> inextensible;  ///< per material index: whether its particles carry the constraint
    InextensibilityMethod method = InextensibilityMethod::schur_cg;
    FiberDriftCorrection correction = FiberDriftCorrection::none;
    /// schur_cg: the Schur solve's relative residual and iteration cap, for
    /// the SpdSolve the layer above binds.
    double cg_tolerance = 1e-8;
    int cg_max_iterations = 5000;

    bool carries(int material) const
    {
        return material >= 0 && material < static_cast<int>(inextensible.size()) &&
               inextensible[static_cast<std::size_t>(material)] != 0;
    }
};

} // namespace sinew
