#pragma once

namespace sinew {

/// PSD projection of a second derivative, chosen per call and never applied
/// silently: of ∂P/∂F in a constitutive model, of each term of a potential's
/// Hessian, of each constraint's curvature λᵢ∇²cᵢ in an NLP's Hessian of the
/// Lagrangian (seed 000 §5.6).
enum class Projection {
    none,   ///< the exact derivative (what Ipopt, KKT Newton and derivative tests want)
    clamp,  ///< each term's negative eigenvalues clamped to zero (what projected Newton wants)
};

/// "none" or "clamp".
inline const char* to_string(Projection projection) { return projection == Projection::none ? "none" : "clamp"; }

} // namespace sinew
