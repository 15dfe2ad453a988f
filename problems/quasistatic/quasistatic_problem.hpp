#pragma once
#include "sinew/energies/constraints/constraint_set.hpp"
#include "sinew/energies/constraints/prescribed_coordinates.hpp"
#include "sinew/energies/potentials/total_potential.hpp"
#include "sinew/problems/nlp.hpp"
#include "sinew/problems/quasistatic/dirichlet_set.hpp"

#include <memory>
#include <string>
#include <vector>

namespace sinew {

/// How prescribed (Dirichlet) coordinates enter the NLP.
enum class DirichletStrategy {
    /// The variables are the free coordinates only; prescribed coordinates
    /// are held at their values inside the problem. Unconstrained NLP.
    eliminate,
    /// The variables are all coordinates, with one linear equality
    /// c_k(x) = x_{i_k} − x̄_{i_k} = 0 per prescribed coordinate (a unit row of
    /// the Jacobian): the constraint set PrescribedCoordinates, the first of
    /// the problem's sets. For comparing constraint strategies on the same problem.
    equality_constraints,
};

/// "eliminate" or "equality_constraints".
std::string to_string(DirichletStrategy strategy);

struct QuasistaticOptions {
    DirichletStrategy dirichlet = DirichletStrategy::eliminate;
    std::string name = "quasistatic";
    /// Further equality constraints on the node positions (inextensibility,
    /// threads, …), after the Dirichlet set when there is one. Under
    /// elimination their Jacobian columns and Hessian entries on prescribed
    /// coordinates are dropped (those coordinates are constants).
    std::vector<std::shared_ptr<ConstraintSet>> constraints;
};

/// Quasistatic equilibrium as an NLP (seed 000 §3, §4.5: zero net force is
/// stationarity of the total potential):
///
///     minimize E(x) over the free coordinates,   x_i = M_s X_i + t_s on Dirichlet set s,
///     subject to c(x) = 0 for each constraint set,
///
/// E the total potential (elastic + gravity + loads + obstacle penalties).
/// The Hessian of the Lagrangian is σ∇²E + Σ_sets Σᵢ λᵢ∇²cᵢ, each term
/// projected under Projection::clamp.
/// The Hessian pattern is E's pattern restricted to the variables (mapped
/// once at construction); the objective's PSD-projected Hessian is offered
/// (supports(Projection::clamp)) for projected Newton.
///
/// Starting point: rest positions for the free nodes, prescribed values for
/// the constrained ones — also for a large prescribed motion (a face turned
/// by 90°): the free nodes are not carried along, so the elements next to the
/// moved set start strongly deformed. For large motions apply the map in
/// steps (set_affine_map, set_starting_configuration(previous solution), solve).
class QuasistaticProblem final : public Nlp {
public:
    /// `rest_positions` is dimension × num_nodes (mesh.nodes). InputError for
    /// a null potential, rest positions of another size than the potential's
    /// or not finite, an invalid Dirichlet set (check_dirichlet_set), a node
    /// in two sets, or no free coordinate left.
    QuasistaticProblem(const Eigen::MatrixXd& rest_positions, std::shared_ptr<TotalPotential> potential,
                       std::vector<DirichletSet> dirichlet, QuasistaticOptions options = {});

    std::string name() const override { return options_.name; }
    int num_variables() const override;
    int num_constraints() const override;
    void constraint_bounds(VectorRef lower, VectorRef upper) const override;
    Vector starting_point() const override;

    double objective(ConstVectorRef x) override;
    void gradient(ConstVectorRef x, VectorRef grad) override;
    void constraints(ConstVectorRef x, VectorRef c) override;
    const SparsityPattern& jacobian_pattern() const override { return jacobian_pattern_; }
    void jacobian_values(ConstVectorRef x, VectorRef values) override;
    const SparsityPattern& hessian_pattern() const override { return hessian_pattern_; }
    bool supports(Projection) const override { return true; }
    /// The rigid-body modes of the nodes at x (rigid_body_modes), on the variables.
    NearNullSpace near_null_space(ConstVectorRef x) const override;

    DirichletStrategy strategy() const { return options_.dirichlet; }
    /// The first row of `set` among the NLP's constraints; −1 when the problem does not hold it.
    int constraint_offset(const ConstraintSet& set) const;
    TotalPotential& potential() { return *potential_; }
    const std::vector<DirichletSet>& dirichlet_sets() const { return sets_; }
    int num_prescribed_coordinates() const { return static_cast<int>(prescribed_coordinates_.size()); }
    /// The coordinates held by a Dirichlet set, and the others, both sorted;
    /// under elimination variable k is free_coordinates()[k].
    const std::vector<int>& prescribed_coordinates() const { return prescribed_coordinates_; }
    const std::vector<int>& free_coordinates() const { return free_coordinates_; }

    /// Replaces M and t of set `set` (new rig parameters θ_k): the prescribed
    /// values change, the patterns do not. InputError as check_dirichlet_set.
    void set_affine_map(int set, const Eigen::MatrixXd& map, const Eigen::VectorXd& translation);

    /// Starts the next solve from `configuration` (node-major, all
    /// coordinates; a previous solution, say); prescribed coordinates still
    /// take their prescribed values. InputError for a wrong size or a
    /// non-finite entry.
    void set_starting_configuration(ConstVectorRef configuration);

    /// Lets every constraint set choose its rows anew at `configuration`
    /// (node-major, all coordinates; ConstraintSet::refresh, a contact
    /// candidate set); when one does, the NLP's rows and patterns are mapped
    /// again and true is returned: solvers made afterwards see the new rows.
    /// Between solves only. InputError for a wrong size or a non-finite entry.
    bool refresh_constraints(ConstVectorRef configuration);
    /// Whether every set's rows still stand for all its constraints at
    /// `configuration` (ConstraintSet::rows_suffice).
    bool constraint_rows_suffice(ConstVectorRef configuration) const;

    /// All coordinates for the variables x: prescribed coordinates at their
    /// values (elimination) or as x has them (equality constraints).
    Eigen::VectorXd full_configuration(ConstVectorRef x) const;
    /// The variables of a full configuration (its free coordinates, or all).
    Eigen::VectorXd variables_of(ConstVectorRef configuration) const;
    /// The rest positions with every prescribed coordinate at its value.
    const Eigen::VectorXd& prescribed_configuration() const { return prescribed_; }

protected:
    /// σ∇²E + Σ λᵢ∇²cᵢ.
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;
    /// The same with each element's term and each λᵢ∇²cᵢ projected (σ ≥ 0).
    void projected_hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    bool eliminating() const { return options_.dirichlet == DirichletStrategy::eliminate; }
    /// Writes the prescribed values of set `s` (index `set`) into prescribed_
    /// and full_x_; throws (changing nothing) when one is not finite.
    void apply_set(const DirichletSet& s, int set);
    /// full_x_ for the variables x (elimination: free entries replaced).
    const Eigen::VectorXd& configuration_of(ConstVectorRef x);
    void fill_hessian(ConstVectorRef x, Projection projection, double sigma, ConstVectorRef lambda, VectorRef values);
    /// Maps every constraint set's Jacobian and Hessian entries to the
    /// variables: at construction and after a refresh that changed rows.
    void map_constraint_sets();
    /// InputError unless `configuration` has every coordinate, finite.
    void check_configuration(ConstVectorRef configuration) const;

    QuasistaticOptions options_;
    std::shared_ptr<TotalPotential> potential_;
    std::vector<DirichletSet> sets_;
    Eigen::VectorXd rest_;                     ///< node-major rest positions
    Eigen::VectorXd prescribed_;               ///< rest_ with prescribed values applied
    Eigen::VectorXd start_;                    ///< starting configuration before prescribed values
    std::vector<int> prescribed_coordinates_;  ///< sorted
    std::vector<int> free_coordinates_;        ///< sorted
    SparsityPattern hessian_pattern_;
    int objective_hessian_nonzeros_ = 0;  ///< the first entries of hessian_pattern_, the potential's
    std::vector<int> hessian_entries_;  ///< for each NLP Hessian nonzero, its index in the potential's pattern
    SparsityPattern jacobian_pattern_;
    std::shared_ptr<PrescribedCoordinates> dirichlet_constraints_;  ///< equality strategy only
    std::vector<std::shared_ptr<ConstraintSet>> constraint_sets_;    ///< Dirichlet first, then options_.constraints
    std::vector<int> constraint_offsets_;                            ///< first row of each set
    std::vector<int> variable_of_;  ///< NLP variable of each coordinate (−1: eliminated)
    /// (set, entry of the set's pattern) for each NLP Jacobian entry, and each
    /// constraint entry appended to the NLP Hessian pattern.
    std::vector<std::pair<int, int>> jacobian_entries_, constraint_hessian_entries_;
    std::vector<Eigen::VectorXd> set_values_;  ///< scratch per set: c, J or Hessian values
    Eigen::VectorXd full_x_;         ///< scratch: the configuration being evaluated
    Eigen::VectorXd full_gradient_;  ///< scratch
    Eigen::VectorXd full_hessian_;   ///< scratch, the potential's pattern
};

} // namespace sinew
