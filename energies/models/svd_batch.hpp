#pragma once
// The batched evaluation (ConstitutiveModel::evaluate_batch) of the 3×3 models
// whose ψ, P or ∂P/∂F need F = U Σ Vᵀ: the SVDs of the whole batch first,
// side by side in SIMD lanes (fast_rotation_variant_svd), then each
// evaluation with its SVD, then the rotations of the stiffnesses the
// evaluations left in the SVD frame, side by side again
// (add_rotated_frame_stiffness). A single evaluation is a batch of one.
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/svd_frame_stiffness.hpp"

#include <algorithm>

namespace sinew {

/// A stiffness in the SVD frame that an evaluation adds to its ∂P/∂F, left to
/// evaluate_with_svds to rotate to vec(F) with the others of the batch.
struct DeferredRotation {
    bool active = false;
    SvdFrameStiffness frame;

    /// ∂P/∂F += (V ⊗ U) K̂ (V ⊗ U)ᵀ once the evaluation is done (the rotation is
    /// linear in K̂: several calls add up).
    void add(const SvdFrameStiffness& stiffness)
    {
        frame.diagonal_block += stiffness.diagonal_block;
        frame.alpha += stiffness.alpha;
        frame.beta += stiffness.beta;
        active = true;
    }
};

/// psi[k] = evaluate(F[k], svd_k, points[k], P + k or null, dPdF + k or null,
/// deferred_k) for k < count, with svd_k = &(F[k] = U Σ Vᵀ) when `needs_svd`,
/// else null; then dPdF[k] += the rotation of deferred_k.
template <typename EvaluateWithSvd>
void evaluate_with_svds(int count, const Model3d::Deformation* F, const Model3d::Point* points, double* psi,
                        Model3d::Stress* P, Model3d::Stiffness* dPdF, bool needs_svd, const EvaluateWithSvd& evaluate)
{
    constexpr int kChunk = 4 * kSimdLanes;
    RotationVariantSvd<3> svd[kChunk];
    for (int first = 0; first < count; first += kChunk) {
        const int size = std::min(kChunk, count - first);
        if (needs_svd)
            fast_rotation_variant_svd(F + first, size, svd);
        DeferredRotation deferred[kChunk];
        FrameRotation rotations[kChunk];
        int pending = 0;
        for (int k = 0; k < size; ++k) {
            const int i = first + k;
            psi[i] = evaluate(F[i], needs_svd ? &svd[k] : nullptr, points[i], P ? P + i : nullptr,
                              dPdF ? dPdF + i : nullptr, deferred[k]);
            if (deferred[k].active && dPdF)
                rotations[pending++] = {&svd[k].U, &svd[k].V, &deferred[k].frame, dPdF + i};
        }
        add_rotated_frame_stiffness(rotations, pending);
    }
}

} // namespace sinew
