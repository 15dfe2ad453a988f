#include "sinew/inverse/muscle_rig.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/problems/quasistatic/dirichlet_set.hpp"
#include "sinew/solvers/solver.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace sinew {
namespace {

constexpr int kDim = 3;

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void check_nodes(const std::vector<int>& nodes, int num_nodes, const std::string& what)
{
    for (const int node : nodes)
        if (node < 0 || node >= num_nodes)
            throw InputError("rig: " + what + " node " + std::to_string(node) + " is outside [0, " +
                             std::to_string(num_nodes) + ")");
}

void check_definition(const RigDefinition& rig)
{
    if (rig.mesh.kind != ElementKind::tetrahedron)
        throw InputError("rig: the tissue mesh must be made of tetrahedra");
    const int nodes = rig.mesh.num_nodes();
    check_nodes(rig.cranium_nodes, nodes, "cranium");
    check_nodes(rig.jaw_nodes, nodes, "jaw");
    check_nodes(rig.landmarks, nodes, "landmark");
    for (const auto* contact : {&rig.contact, &rig.jaw_contact})
        if (*contact) {
            if (!(*contact)->body)
                throw InputError("rig: the contact has no body");
            check_nodes((*contact)->nodes, nodes, "contact");
        }
    if (rig.landmarks.empty())
        throw InputError("rig: no landmark");
    if (rig.muscle_names.size() != rig.muscle_elements.size())
        throw InputError("rig: " + std::to_string(rig.muscle_names.size()) + " muscle names for " +
                         std::to_string(rig.muscle_elements.size()) + " muscles");
    for (std::size_t m = 0; m < rig.muscle_elements.size(); ++m) {
        if (rig.muscle_elements[m].empty())
            throw InputError("rig: muscle '" + rig.muscle_names[m] + "' has no element");
        for (const int e : rig.muscle_elements[m])
            if (e < 0 || e >= rig.mesh.num_elements())
                throw InputError("rig: muscle '" + rig.muscle_names[m] + "' element " + std::to_string(e) +
                                 " is outside [0, " + std::to_string(rig.mesh.num_elements()) + ")");
    }
}

double bounding_box_diagonal(const Eigen::MatrixXd& nodes)
{
    return (nodes.rowwise().maxCoeff() - nodes.rowwise().minCoeff()).norm();
}

} // namespace

MuscleRig::MuscleRig(RigDefinition definition, EquilibriumSolveSettings settings)
    : definition_(std::move(definition)), settings_(std::move(settings))
{
    check_definition(definition_);
    validate(settings_.options);
    elastic_ = std::make_shared<ElasticPotential>(definition_.mesh, definition_.group_models);
    std::vector<std::shared_ptr<Potential>> terms{elastic_};
    if (const auto& contact = definition_.contact) {
        contact_ = std::make_shared<ObstaclePenaltyPotential>(
            kDim, definition_.mesh.num_nodes(), std::make_shared<PlacedBody>(contact->body), contact->stiffness,
            contact->nodes);
        terms.push_back(contact_);
    }
    if (const auto& contact = definition_.jaw_contact) {
        jaw_body_ = std::make_shared<PlacedBody>(contact->body);
        jaw_contact_ = std::make_shared<ObstaclePenaltyPotential>(kDim, definition_.mesh.num_nodes(), jaw_body_,
                                                                  contact->stiffness, contact->nodes);
        terms.push_back(jaw_contact_);
    }
    auto potential = std::make_shared<TotalPotential>(std::move(terms));
    // Set 0 holds the cranium nodes at rest, set 1 places the jaw nodes (§2.3);
    // QuasistaticProblem refuses a node in both.
    std::vector<DirichletSet> sets{fixed_at_rest("cranium", definition_.cranium_nodes, kDim),
                                   fixed_at_rest("jaw", definition_.jaw_nodes, kDim)};
    QuasistaticOptions options;
    options.name = "rig equilibrium";
    problem_ = std::make_unique<QuasistaticProblem>(definition_.mesh.nodes, potential, std::move(sets), options);
    check_solve(*problem_, "projected-newton", settings_.options);
    size_ = bounding_box_diagonal(definition_.mesh.nodes);
    theta_ = RigParameters::neutral(num_muscles());
    if (settings_.force_scale == 0.0)
        settings_.force_scale = full_activation_force();
}

double MuscleRig::full_activation_force() const
{
    const Eigen::VectorXd rest = Eigen::Map<const Eigen::VectorXd>(definition_.mesh.nodes.data(), definition_.mesh.nodes.size());
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(rest.size());
    for (const std::vector<int>& muscle : definition_.muscle_elements)
        elastic_->add_activation_gradient(rest, muscle, gradient);  // ∂(∇E)/∂α at rest, α = 1 for all: Σ −f_i
    Eigen::VectorXd free(problem_->num_variables());
    for (int k = 0; k < problem_->num_variables(); ++k)
        free[k] = gradient[problem_->free_coordinates()[k]];
    return free.size() > 0 ? free.cwiseAbs().maxCoeff() : 0.0;
}

RigEvaluation MuscleRig::evaluate(const RigParameters& theta)
{
    if (theta.num_muscles() != num_muscles())
        throw InputError("rig: " + std::to_string(theta.num_muscles()) + " activations given for " +
                         std::to_string(num_muscles()) + " muscles");
    const Eigen::VectorXd packed = theta.packed();
    if (!packed.allFinite())
        throw InputError("rig: a parameter is not finite");
    for (int m = 0; m < num_muscles(); ++m)
        if (!(theta.activations[m] >= 0.0 && theta.activations[m] <= 1.0))
            throw InputError("rig: activation of muscle '" + definition_.muscle_names[m] + "' is " +
                             std::to_string(theta.activations[m]) + ", outside [0, 1]");
    RigEvaluation evaluation;
    if (last_theta_ && *last_theta_ == packed) {
        evaluation.ok = true;
        return evaluation;
    }
    last_theta_.reset();
    sensitivities_.reset();
    for (int m = 0; m < num_muscles(); ++m)
        for (const int e : definition_.muscle_elements[m])
            elastic_->set_activation(e, theta.activations[m]);
    problem_->set_affine_map(1, theta.jaw_map, theta.jaw_translation);
    if (jaw_body_)
        jaw_body_->set_affine_placement(theta.jaw_map, theta.jaw_translation);  // y ↦ M_j y + t_j
    if (warm_start_.size() > 0)
        problem_->set_starting_configuration(warm_start_);
    const auto start = std::chrono::steady_clock::now();
    EquilibriumSolve solve = solve_equilibrium(*problem_, settings_);
    equilibrium_seconds_ += seconds_since(start);
    ++equilibrium_solves_;
    evaluation.inner = solve.result;
    if (!solve.converged) {
        evaluation.failure = "rig: " + solve.failure;
        return evaluation;
    }
    evaluation.ok = true;
    equilibrium_ = solve.configuration;
    warm_start_ = solve.configuration;
    theta_ = theta;
    last_theta_ = packed;
    return evaluation;
}

void MuscleRig::require_evaluated() const
{
    if (!last_theta_)
        throw std::logic_error("rig: positions or derivatives asked for without a successful evaluation");
}

Eigen::VectorXd MuscleRig::positions() const
{
    require_evaluated();
    // x̂_i = M_c x_i + t_c (§2.2).
    Eigen::VectorXd x_hat(equilibrium_.size());
    for (Eigen::Index i = 0; i < equilibrium_.size() / kDim; ++i)
        x_hat.segment<kDim>(kDim * i) = theta_.cranium_map * equilibrium_.segment<kDim>(kDim * i) + theta_.cranium_translation;
    return x_hat;
}

Eigen::VectorXd MuscleRig::landmark_positions() const
{
    const Eigen::VectorXd x_hat = positions();
    Eigen::VectorXd landmarks(kDim * num_landmarks());
    for (int l = 0; l < num_landmarks(); ++l)
        landmarks.segment<kDim>(kDim * l) = x_hat.segment<kDim>(kDim * definition_.landmarks[l]);
    return landmarks;
}

double MuscleRig::max_penetration() const
{
    require_evaluated();
    double deepest = 0.0;
    for (const auto& contact : {contact_, jaw_contact_})
        if (contact)
            deepest = std::max(deepest, contact->max_penetration(equilibrium_));
    return deepest;
}

Eigen::Vector3d MuscleRig::contact_force() const
{
    require_evaluated();
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    for (const auto& contact : {contact_, jaw_contact_})
        if (contact)
            force += contact->total_force(equilibrium_);
    return force;
}

EquilibriumSensitivities& MuscleRig::sensitivities()
{
    require_evaluated();
    if (!sensitivities_) {
        const auto start = std::chrono::steady_clock::now();
        sensitivities_ = std::make_unique<EquilibriumSensitivities>(*problem_, equilibrium_);
        sensitivity_seconds_ += seconds_since(start);
        ++sensitivity_factorizations_;
    }
    if (!sensitivities_->ok())
        throw std::runtime_error("rig: " + sensitivities_->failure());
    return *sensitivities_;
}

ParameterDirections MuscleRig::equilibrium_directions() const
{
    const int n = static_cast<int>(equilibrium_.size());
    const int m = num_muscles();
    ParameterDirections directions;
    directions.gradient_change = Eigen::MatrixXd::Zero(n, m + RigParameters::kAffineParameters);
    for (int k = 0; k < m; ++k) {
        Eigen::VectorXd column = Eigen::VectorXd::Zero(n);
        elastic_->add_activation_gradient(equilibrium_, definition_.muscle_elements[k], column);  // −f_k (§2.1)
        directions.gradient_change.col(k) = column;
    }
    // The body the jaw carries moves with M_j and t_j: ∂(∇E_c)/∂θ_jaw at the
    // equilibrium, columns in the order of placement_gradient_derivatives.
    if (jaw_contact_)
        directions.gradient_change.middleCols(m, RigParameters::kAffineParameters) =
            jaw_contact_->placement_gradient_derivatives(equilibrium_);
    // ∂x^C/∂M_j(a,b) = e_a X_b, ∂x^C/∂t_j(a) = e_a on the jaw nodes (§3.3).
    directions.prescribed_motion = Eigen::MatrixXd::Zero(n, m + RigParameters::kAffineParameters);
    for (const int node : definition_.jaw_nodes)
        for (int a = 0; a < kDim; ++a) {
            for (int b = 0; b < kDim; ++b)
                directions.prescribed_motion(kDim * node + a, m + 3 * a + b) = definition_.mesh.nodes(b, node);
            directions.prescribed_motion(kDim * node + a, m + 9 + a) = 1.0;
        }
    return directions;
}

Eigen::MatrixXd MuscleRig::landmark_jacobian()
{
    EquilibriumSensitivities& s = sensitivities();
    const auto start = std::chrono::steady_clock::now();
    const Eigen::MatrixXd dx = s.derivatives(equilibrium_directions());  // cranium frame: activations, jaw
    const int m = num_muscles();
    const int c = theta_.cranium_offset(), j = theta_.jaw_offset();
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(kDim * num_landmarks(), num_parameters());
    for (int l = 0; l < num_landmarks(); ++l) {
        const int node = definition_.landmarks[l];
        const auto rows = Eigen::seqN(kDim * l, kDim);
        const auto node_rows = Eigen::seqN(kDim * node, kDim);
        jacobian(rows, Eigen::seqN(0, m)) = theta_.cranium_map * dx(node_rows, Eigen::seqN(0, m));
        jacobian(rows, Eigen::seqN(j, RigParameters::kAffineParameters)) =
            theta_.cranium_map * dx(node_rows, Eigen::seqN(m, RigParameters::kAffineParameters));
        // §3.2: ∂x̂/∂M_c(a,b) = e_a x_b, ∂x̂/∂t_c(a) = e_a.
        for (int a = 0; a < kDim; ++a) {
            for (int b = 0; b < kDim; ++b)
                jacobian(kDim * l + a, c + 3 * a + b) = equilibrium_[kDim * node + b];
            jacobian(kDim * l + a, c + 9 + a) = 1.0;
        }
    }
    sensitivity_seconds_ += seconds_since(start);
    return jacobian;
}

Eigen::VectorXd MuscleRig::landmark_gradient(const Eigen::VectorXd& w)
{
    if (w.size() != kDim * num_landmarks())
        throw InputError("rig: landmark weights have " + std::to_string(w.size()) + " entries, expected " +
                         std::to_string(kDim * num_landmarks()));
    EquilibriumSensitivities& s = sensitivities();
    const auto start = std::chrono::steady_clock::now();
    // wᵀ S M_c ∂x/∂θ = (S ᵀ M_cᵀ w)ᵀ ∂x/∂θ: the weights carried into the cranium frame.
    Eigen::VectorXd carried = Eigen::VectorXd::Zero(equilibrium_.size());
    for (int l = 0; l < num_landmarks(); ++l)
        carried.segment<kDim>(kDim * definition_.landmarks[l]) +=
            theta_.cranium_map.transpose() * w.segment<kDim>(kDim * l);
    const Eigen::VectorXd moved = s.adjoint_gradient(carried, equilibrium_directions());
    const int m = num_muscles();
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(num_parameters());
    gradient.head(m) = moved.head(m);
    gradient.segment(theta_.jaw_offset(), RigParameters::kAffineParameters) = moved.tail(RigParameters::kAffineParameters);
    for (int l = 0; l < num_landmarks(); ++l) {
        const int node = definition_.landmarks[l];
        for (int a = 0; a < kDim; ++a) {
            for (int b = 0; b < kDim; ++b)
                gradient[theta_.cranium_offset() + 3 * a + b] += w[kDim * l + a] * equilibrium_[kDim * node + b];
            gradient[theta_.cranium_offset() + 9 + a] += w[kDim * l + a];
        }
    }
    sensitivity_seconds_ += seconds_since(start);
    return gradient;
}

} // namespace sinew
