#pragma once
// A muscle-driven facial rig x̂(θ) (seed 000 §1–3): the quasistatic
// equilibrium of a tissue mesh under muscle activations and a jaw motion,
// carried by the cranium's affine map; its landmark positions and their
// derivatives in θ.
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"
#include "sinew/inverse/equilibrium_sensitivities.hpp"
#include "sinew/inverse/equilibrium_solve.hpp"
#include "sinew/inverse/rig_parameters.hpp"
#include "sinew/mesh/mesh.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sinew {

/// Collisions of the tissue with a rigid body fixed in the cranium frame (the
/// skull, the teeth), as the seed's penalty force (seed 000 §5.7,
/// ObstaclePenaltyPotential): E_c = Σ_i ε/2 max(0, −φ(x_i))² over `nodes`.
struct RigContact {
    std::shared_ptr<const CollisionBody> body;
    double stiffness = 0.0;  ///< ε, N/m per node
    std::vector<int> nodes;  ///< the nodes that can touch the body
};

/// What a rig is made of: a tet mesh with its group models (the muscles'
/// groups use a model with an activation, mooney-rivlin-muscle), the
/// muscles as element sets with one activation each, the bone-attached
/// nodes, and the landmark nodes the fit sees.
struct RigDefinition {
    Mesh mesh;
    std::vector<ElementModel> group_models;
    std::vector<std::string> muscle_names;
    std::vector<std::vector<int>> muscle_elements;
    std::vector<int> cranium_nodes;  ///< fixed in the cranium frame
    std::vector<int> jaw_nodes;      ///< placed by the jaw map, x = M_j X + t_j (§2.3)
    std::vector<int> landmarks;      ///< node of each landmark
    std::optional<RigContact> contact;  ///< none: the tissue passes through bone
    /// A body the jaw carries (the lower teeth): placed by the jaw map,
    /// x = M_j y + t_j (§2.3), so that moving the jaw moves it and the
    /// sensitivities see ∂(∇E_c)/∂θ_jaw. None: no such body.
    std::optional<RigContact> jaw_contact;
};

/// The outcome of one evaluation of x̂(θ).
struct RigEvaluation {
    bool ok = false;
    std::string failure;   ///< why not (the inner solve's message), empty when ok
    Result inner;          ///< the equilibrium solve's result
};

/// x̂(θ) = M_c x(θ) + t_c on every node (§2.2, §3.2), x(θ) the equilibrium in
/// the cranium frame with the activations of θ and the jaw nodes at
/// M_j X + t_j (§2.3), the cranium nodes at rest. Each solve starts from the
/// last equilibrium found (a warm start); an evaluation at the θ of the last
/// one is not repeated.
class MuscleRig {
public:
    /// The inner solves stop at tol × a force scale (solve_equilibrium), by
    /// default the muscles' force at full activation.
    /// InputError for an invalid mesh or model (ElasticPotential's), an
    /// element of a muscle or a node of a set or landmark out of range, a node
    /// both in the cranium and the jaw set, no landmark, or invalid settings.
    MuscleRig(RigDefinition definition, EquilibriumSolveSettings settings);

    int num_muscles() const { return static_cast<int>(definition_.muscle_elements.size()); }
    int num_parameters() const { return num_muscles() + 2 * RigParameters::kAffineParameters; }
    int num_landmarks() const { return static_cast<int>(definition_.landmarks.size()); }
    const RigDefinition& definition() const { return definition_; }
    /// The inner solves' settings, the force scale filled in.
    const EquilibriumSolveSettings& settings() const { return settings_; }
    /// The diagonal of the rest mesh's bounding box (m).
    double size() const { return size_; }

    /// Solves x(θ). InputError for activations outside [0, 1] or non-finite
    /// parameters (nothing is solved); a failed inner solve gives ok = false.
    RigEvaluation evaluate(const RigParameters& theta);

    /// After a successful evaluate(): x̂ on every node (node-major), and the
    /// landmarks' positions (3 per landmark). std::logic_error otherwise.
    Eigen::VectorXd positions() const;
    Eigen::VectorXd landmark_positions() const;

    /// ∂(S x̂)/∂θ, (3·landmarks) × num_parameters, at the last evaluated θ:
    /// forward sensitivities, one factorization, a solve per activation and
    /// jaw parameter (§3.1, §3.3–3.4); cranium columns in closed form (§3.2).
    Eigen::MatrixXd landmark_jacobian();
    /// wᵀ ∂(S x̂)/∂θ for weights w on the landmarks (3 per landmark) by one
    /// adjoint solve.
    Eigen::VectorXd landmark_gradient(const Eigen::VectorXd& w);

    /// After a successful evaluate(), the largest depth of a node in a
    /// contact body (m) and the force the bodies exert on the tissue (N, in
    /// the cranium frame); 0 without contact.
    double max_penetration() const;
    Eigen::Vector3d contact_force() const;

    /// Equilibrium solves and factorizations of sensitivities so far, and their times.
    int equilibrium_solves() const { return equilibrium_solves_; }
    int sensitivity_factorizations() const { return sensitivity_factorizations_; }
    double equilibrium_seconds() const { return equilibrium_seconds_; }
    double sensitivity_seconds() const { return sensitivity_seconds_; }

private:
    /// ‖Σ_i f_i‖∞ on the free coordinates at rest: the muscles' force at full
    /// activation, the force scale of the inner solves' tolerance
    /// (EquilibriumSolveSettings::force_scale) unless the settings give one.
    double full_activation_force() const;
    void require_evaluated() const;
    /// The factorization at the last equilibrium, made on first use.
    EquilibriumSensitivities& sensitivities();
    /// Columns for the activations and the 12 jaw parameters (the parameters
    /// that move the equilibrium), over all coordinates.
    ParameterDirections equilibrium_directions() const;

    RigDefinition definition_;
    EquilibriumSolveSettings settings_;
    std::shared_ptr<ElasticPotential> elastic_;
    std::shared_ptr<ObstaclePenaltyPotential> contact_;  ///< null without contact
    std::shared_ptr<PlacedBody> jaw_body_;                   ///< null without a body carried by the jaw
    std::shared_ptr<ObstaclePenaltyPotential> jaw_contact_;  ///< its penalty
    std::unique_ptr<QuasistaticProblem> problem_;
    double size_ = 1.0;
    std::optional<Eigen::VectorXd> last_theta_;
    RigParameters theta_;
    Eigen::VectorXd equilibrium_;  ///< x(θ), cranium frame, all coordinates
    Eigen::VectorXd warm_start_;   ///< the last equilibrium found
    std::unique_ptr<EquilibriumSensitivities> sensitivities_;
    int equilibrium_solves_ = 0;
    int sensitivity_factorizations_ = 0;
    double equilibrium_seconds_ = 0.0;
    double sensitivity_seconds_ = 0.0;
};

} // namespace sinew
