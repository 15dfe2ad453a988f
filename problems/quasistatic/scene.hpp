#pragma once
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/gravity_potential.hpp"
#include "sinew/energies/potentials/inertia_potential.hpp"
#include "sinew/energies/potentials/point_load_potential.hpp"
#include "sinew/energies/potentials/stiffness_damping_potential.hpp"
#include "sinew/mesh/mesh.hpp"
#include "sinew/mpm/mpm_scene.hpp"
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/time/dynamics_settings.hpp"

#include <Eigen/Core>

#include <any>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sinew {

/// The motion a Dirichlet set reaches at load factor 1, x = M X + t, and how
/// it is scaled for a load step s ∈ [0, 1]: a rotation R(θ) about a centre c
/// turns by s·θ (x = R(sθ)(X − c) + c + s·t); a general map blends linearly,
/// M(s) = I + s(M − I), t(s) = s·t. s = 0 holds the set at rest.
struct PrescribedMotion {
    bool rotation = false;
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< rotation axis (3D), unit
    double angle = 0.0;                               ///< θ, radians
    Eigen::VectorXd center;                           ///< c, m
    Eigen::MatrixXd map;                              ///< M, for a general map
    Eigen::VectorXd translation;                      ///< t, m

    /// M(s) and t(s) in `dimension` (2 or 3) dimensions.
    Eigen::MatrixXd map_at(double s, int dimension) const;
    Eigen::VectorXd translation_at(double s, int dimension) const;
};

struct Scene;

/// Something a load factor scales: gravity, one entry of "loads", the motion
/// of a Dirichlet set, the activation of a mesh group. In a scene stepped in
/// time it follows its own curve s(t) when the scene gives it one
/// (docs/dynamics.md, "Loads over time"), dynamics.load_curve otherwise.
struct ScaledQuantity {
    std::string name;  ///< for messages: "gravity", "loads[0]", "boundary 'left'", …
    std::optional<KeyframeCurve> curve;
    /// Sets the quantity in `scene` to (1 − w)·(its value at s₀) + w·(its
    /// value at s₁).
    std::function<void(Scene& scene, double s0, double s1, double w)> set;
    /// Why the factors s ∈ [lowest, highest] are not admissible ("" when
    /// they are): an activation leaving [0, 1], a map blend turning singular.
    std::function<std::string(double lowest, double highest)> refusal;
};

/// A quasistatic scene built from its description (scene_reader.hpp): the
/// mesh, the potentials, the NLP, and what a load factor s scales. Load
/// stepping solves at s = k/N, k = 1…N, each step starting from the previous
/// solution; s scales gravity, point loads, the prescribed motions of the
/// Dirichlet sets and the muscle activations together.
struct Scene {
    std::string name;
    std::string description;
    Mesh mesh;
    std::shared_ptr<ElasticPotential> elastic;
    std::shared_ptr<GravityPotential> gravity;     ///< null when the scene has no gravity
    std::shared_ptr<PointLoadPotential> loads;     ///< null when it has no point loads
    std::unique_ptr<QuasistaticProblem> problem;
    /// The constraint sets of the scene's "constraints" (inextensible fibers,
    /// threads), in the problem's constraint order after any Dirichlet set.
    std::vector<std::shared_ptr<ConstraintSet>> constraints;
    std::vector<PrescribedMotion> motions;         ///< one per Dirichlet set of `problem`
    std::vector<ScaledQuantity> scaled;            ///< what a load factor scales
    int load_steps = 1;                            ///< N
    /// What the run parts (runs/: "solver", "output") read, by their key;
    /// problems/ knows neither their types nor how a scene is run.
    std::map<std::string, std::any> run_settings;
    double size = 1.0;  ///< the diagonal of the rest mesh's bounding box, m

    /// A scene with a "dynamics" object is integrated in time (runs/time_stepping.hpp):
    /// its settings, the lumped node masses, and the step's inertia and
    /// damping terms, which are among the problem's potentials (null when
    /// the scene has no dynamics or no such damping).
    std::optional<DynamicsSettings> dynamics;
    Eigen::VectorXd node_masses;
    std::shared_ptr<InertiaPotential> inertia;
    std::shared_ptr<InertiaPotential> mass_damping;
    std::shared_ptr<StiffnessDampingPotential> stiffness_damping;

    /// A scene with an "mpm" section is particles on a grid (runs/mpm_run.hpp):
    /// it has no mesh and no `problem`, only this.
    std::shared_ptr<const MpmScene> mpm;

    /// Sets every scaled quantity to its value at load factor s (above).
    void apply_load_factor(double s);
    /// Sets every scaled quantity to its value at time t: s(t) of its own
    /// curve, else of dynamics.load_curve (1 without dynamics).
    void apply_time(double t);
    /// The same for forces that act between two instants: every scaled
    /// quantity is (1 − w)·(its value at t₀) + w·(its value at t₁), the
    /// prescribed maps and translations included (a time step whose forces
    /// act at its midpoint takes w = ½).
    void apply_time(double t0, double t1, double w);
    /// The nodes of every Dirichlet set, flagged: 1 prescribed, 0 free.
    Eigen::VectorXd fixed_flags() const;
};

} // namespace sinew
