#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/damage/damage_update.hpp"
#include "sinew/mpm/inextensibility/inextensibility_settings.hpp"
#include "sinew/mpm/particles.hpp"
#include "sinew/mpm/step_settings.hpp"

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace sinew {

/// How an MPM run advances in time.
enum class MpmStepping {
    explicit_steps,  ///< symplectic Euler, below the CFL bound (or in sub-steps)
    implicit_steps   ///< the grid-velocity NLP solved every step
};

/// Particles, their models and the step settings, in one dimension.
template <int Dim>
struct MpmSetup {
    Particles<Dim> particles;
    /// By material index, as the particles' `material` refers to them.
    std::vector<std::shared_ptr<const ConstitutiveModel<Dim, Dim>>> models;
    MpmStepSettings<Dim> step;  ///< step.time_step is the run's Δt

    std::vector<const ConstitutiveModel<Dim, Dim>*> model_pointers() const
    {
        std::vector<const ConstitutiveModel<Dim, Dim>*> pointers;
        for (const auto& model : models)
            pointers.push_back(model.get());
        return pointers;
    }
};

/// An MPM run as a scene's "mpm" section describes it (docs/mpm.md,
/// "Scenes"); runs/mpm_run.hpp runs it.
struct MpmScene {
    int dimension = 2;
    double dx = 0.1;  ///< grid spacing, m
    std::variant<MpmSetup<2>, MpmSetup<3>> setup;
    std::vector<std::string> materials;  ///< names, by material index
    MpmStepping stepping = MpmStepping::explicit_steps;
    double duration = 1.0;  ///< s
    /// Explicit steps: the largest Δt taken is cfl · dx / max_p (c_p + |v_p|).
    double cfl = 0.5;
    /// Explicit steps: a step above that bound is split into equal sub-steps
    /// below it; without, the run refuses it (before it starts, or by ending).
    bool substeps = false;
    int frames = 50;  ///< output frames after t = 0, equally spaced in time
    bool grid_output = false;  ///< also the active grid as grid_k.vtu at every frame
    /// AnisoMPM's damage (scene part "mpm_damage"): when set, the particles
    /// carry phase-field points and d advances once before every step.
    std::optional<DamageSettings> damage;
    /// AnisoMPM's fibre inextensibility on the grid (scene part
    /// "mpm_inextensibility"): the materials it holds and how.
    std::optional<InextensibilitySettings> inextensibility;
};

} // namespace sinew
