#pragma once
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/gravity_potential.hpp"
#include "sinew/energies/potentials/inertia_potential.hpp"
#include "sinew/energies/potentials/point_load_potential.hpp"
#include "sinew/mesh/mesh.hpp"
#include "sinew/energies/potentials/stiffness_damping_potential.hpp"
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/time/dynamics_settings.hpp"

#include <Eigen/Core>

#include <any>
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
    Eigen::VectorXd target_activations;            ///< α_e at s = 1, per element
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

    /// Sets every scaled quantity to its value at load factor s (above).
    void apply_load_factor(double s);
    /// The same for forces that act between two load factors: every scaled
    /// quantity is (1 − w)·(its value at s₀) + w·(its value at s₁), the
    /// prescribed maps and translations included (a time step whose forces
    /// act at its midpoint takes w = ½).
    void apply_load_factors(double s0, double s1, double w);
    /// The nodes of every Dirichlet set, flagged: 1 prescribed, 0 free.
    Eigen::VectorXd fixed_flags() const;
};

} // namespace sinew
