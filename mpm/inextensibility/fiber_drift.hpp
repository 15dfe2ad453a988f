#pragma once
// The positional constraint the grid inextensibility's rate rows let drift.
#include "sinew/mpm/inextensibility/inextensibility_settings.hpp"
#include "sinew/mpm/particles.hpp"

namespace sinew {

/// a₀ᵀ C a₀ − 1 = |F a₀|² − 1 over the inextensible particles (C = FᵀF).
struct FiberDrift {
    int particles = 0;
    double max = 0.0;  ///< max |a₀ᵀ C a₀ − 1|
    double rms = 0.0;  ///< its root mean square
};

template <int Dim>
FiberDrift fiber_drift(const Particles<Dim>& particles, const InextensibilitySettings& settings);

/// The positional projection (FiberDriftCorrection::projection) of every
/// inextensible particle: F ← F + (1/|F a₀| − 1)(F a₀) a₀ᵀ/|a₀|², after
/// which F a₀ = F a₀/|F a₀| and F b is unchanged for b ⊥ a₀.
template <int Dim>
void project_fiber_lengths(Particles<Dim>& particles, const InextensibilitySettings& settings);

} // namespace sinew
