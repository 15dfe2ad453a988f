#include "sinew/problems/quasistatic/quasistatic_problem.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/problems/quasistatic/rigid_body_modes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace sinew {

std::string to_string(DirichletStrategy strategy)
{
    return strategy == DirichletStrategy::eliminate ? "eliminate" : "equality_constraints";
}

QuasistaticProblem::QuasistaticProblem(const Eigen::MatrixXd& rest_positions,
                                       std::shared_ptr<TotalPotential> potential, std::vector<DirichletSet> dirichlet,
                                       QuasistaticOptions options)
    : options_(std::move(options)), potential_(std::move(potential)), sets_(std::move(dirichlet))
{
    const std::string who = "quasistatic problem '" + options_.name + "': ";
    if (!potential_)
        throw InputError(who + "no potential");
    const int d = potential_->dimension();
    const int num_nodes = potential_->num_nodes();
    if (rest_positions.rows() != d || rest_positions.cols() != num_nodes)
        throw InputError(who + "rest positions are " + std::to_string(rest_positions.rows()) + "x" +
                         std::to_string(rest_positions.cols()) + " but the potential has " +
                         std::to_string(num_nodes) + " nodes in " + std::to_string(d) + "D");
    if (!rest_positions.allFinite())
        throw InputError(who + "a rest position is not finite");
    rest_ = Eigen::Map<const Eigen::VectorXd>(rest_positions.data(), rest_positions.size());

    // Which set holds each node (−1: free).
    std::vector<int> set_of(static_cast<std::size_t>(num_nodes), -1);
    for (int s = 0; s < static_cast<int>(sets_.size()); ++s) {
        check_dirichlet_set(sets_[s], s, d, num_nodes);
        for (int node : sets_[s].nodes) {
            if (set_of[node] >= 0)
                throw InputError(who + "node " + std::to_string(node) + " is in both " +
                                 dirichlet_set_label(sets_[set_of[node]], set_of[node]) + " and " +
                                 dirichlet_set_label(sets_[s], s));
            set_of[node] = s;
        }
    }
    for (int node = 0; node < num_nodes; ++node)
        for (int k = 0; k < d; ++k)
            (set_of[node] >= 0 ? prescribed_coordinates_ : free_coordinates_).push_back(node * d + k);
    if (free_coordinates_.empty())
        throw InputError(who + "every node is prescribed: nothing to solve for");

    prescribed_ = rest_;
    full_x_ = rest_;
    for (int s = 0; s < static_cast<int>(sets_.size()); ++s)
        apply_set(sets_[s], s);
    start_ = rest_;
    full_gradient_.resize(rest_.size());

    // The potential's Hessian pattern restricted to the variables, mapped once.
    variable_of_.assign(static_cast<std::size_t>(rest_.size()), -1);
    if (eliminating())
        for (int k = 0; k < static_cast<int>(free_coordinates_.size()); ++k)
            variable_of_[free_coordinates_[k]] = k;
    else
        for (int i = 0; i < static_cast<int>(rest_.size()); ++i)
            variable_of_[i] = i;
    const HessianPattern& full = potential_->hessian_pattern();
    full_hessian_.resize(full.nonzeros());
    for (int entry = 0; entry < full.nonzeros(); ++entry) {
        const int row = variable_of_[full.rows()[entry]];
        const int col = variable_of_[full.cols()[entry]];
        if (row >= 0 && col >= 0) {
            hessian_pattern_.add(row, col);
            hessian_entries_.push_back(entry);
        }
    }
    objective_hessian_nonzeros_ = hessian_pattern_.nonzeros();
    if (!eliminating()) {
        Eigen::VectorXd targets(num_prescribed_coordinates());
        for (int k = 0; k < num_prescribed_coordinates(); ++k)
            targets[k] = prescribed_[prescribed_coordinates_[k]];
        dirichlet_constraints_ = std::make_shared<PrescribedCoordinates>(prescribed_coordinates_, targets);
        constraint_sets_.push_back(dirichlet_constraints_);
    }
    for (const auto& set : options_.constraints) {
        if (!set)
            throw InputError(who + "a constraint set is null");
        constraint_sets_.push_back(set);
    }
    map_constraint_sets();
}

void QuasistaticProblem::map_constraint_sets()
{
    // Variables are in coordinate order, so a lower-triangle entry stays one.
    constraint_offsets_.clear();
    jacobian_pattern_ = SparsityPattern();
    jacobian_entries_.clear();
    constraint_hessian_entries_.clear();
    set_values_.clear();
    hessian_pattern_.rows.resize(static_cast<std::size_t>(objective_hessian_nonzeros_));
    hessian_pattern_.cols.resize(static_cast<std::size_t>(objective_hessian_nonzeros_));
    int offset = 0;
    for (int s = 0; s < static_cast<int>(constraint_sets_.size()); ++s) {
        ConstraintSet& set = *constraint_sets_[s];
        constraint_offsets_.push_back(offset);
        const SparsityPattern& jacobian = set.jacobian_pattern();
        for (int entry = 0; entry < jacobian.nonzeros(); ++entry)
            if (const int col = variable_of_[jacobian.cols[entry]]; col >= 0) {
                jacobian_pattern_.add(offset + jacobian.rows[entry], col);
                jacobian_entries_.emplace_back(s, entry);
            }
        const SparsityPattern& hessian = set.hessian_pattern();
        for (int entry = 0; entry < hessian.nonzeros(); ++entry) {
            const int row = variable_of_[hessian.rows[entry]];
            const int col = variable_of_[hessian.cols[entry]];
            if (row >= 0 && col >= 0) {
                hessian_pattern_.add(row, col);
                constraint_hessian_entries_.emplace_back(s, entry);
            }
        }
        set_values_.emplace_back(std::max({set.num_constraints(), jacobian.nonzeros(), hessian.nonzeros()}));
        offset += set.num_constraints();
    }
}

int QuasistaticProblem::constraint_offset(const ConstraintSet& set) const
{
    for (size_t s = 0; s < constraint_sets_.size(); ++s)
        if (constraint_sets_[s].get() == &set)
            return constraint_offsets_[s];
    return -1;
}

void QuasistaticProblem::apply_set(const DirichletSet& s, int set)
{
    const int d = potential_->dimension();
    Eigen::VectorXd updated = prescribed_;
    for (int node : s.nodes)
        for (int i = 0; i < d; ++i) {
            double x = s.translation[i];
            for (int j = 0; j < d; ++j)
                x += s.map(i, j) * rest_[node * d + j];
            if (!std::isfinite(x))
                throw InputError(dirichlet_set_label(s, set) + ": the prescribed position of node " +
                                 std::to_string(node) + " is not finite");
            updated[node * d + i] = x;
        }
    prescribed_ = updated;
    for (int i : prescribed_coordinates_)
        full_x_[i] = prescribed_[i];
    if (dirichlet_constraints_) {
        Eigen::VectorXd targets(num_prescribed_coordinates());
        for (int k = 0; k < num_prescribed_coordinates(); ++k)
            targets[k] = prescribed_[prescribed_coordinates_[k]];
        dirichlet_constraints_->set_targets(targets);
    }
}

int QuasistaticProblem::num_variables() const
{
    return eliminating() ? static_cast<int>(free_coordinates_.size()) : static_cast<int>(rest_.size());
}

int QuasistaticProblem::num_constraints() const
{
    int count = 0;
    for (const auto& set : constraint_sets_)
        count += set->num_constraints();
    return count;
}

void QuasistaticProblem::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    for (int s = 0; s < static_cast<int>(constraint_sets_.size()); ++s) {
        const int rows = constraint_sets_[s]->num_constraints();
        constraint_sets_[s]->bounds(lower.segment(constraint_offsets_[s], rows),
                                    upper.segment(constraint_offsets_[s], rows));
    }
}

bool QuasistaticProblem::refresh_constraints(ConstVectorRef configuration)
{
    check_configuration(configuration);
    bool changed = false;
    for (const auto& set : constraint_sets_)
        changed = set->refresh(configuration) || changed;
    if (changed)
        map_constraint_sets();
    return changed;
}

bool QuasistaticProblem::constraint_rows_suffice(ConstVectorRef configuration) const
{
    check_configuration(configuration);
    for (const auto& set : constraint_sets_)
        if (!set->rows_suffice(configuration))
            return false;
    return true;
}

Nlp::Vector QuasistaticProblem::starting_point() const
{
    Eigen::VectorXd configuration = start_;
    for (int i : prescribed_coordinates_)
        configuration[i] = prescribed_[i];
    return variables_of(configuration);
}

const Eigen::VectorXd& QuasistaticProblem::configuration_of(ConstVectorRef x)
{
    if (eliminating())
        for (int k = 0; k < static_cast<int>(free_coordinates_.size()); ++k)
            full_x_[free_coordinates_[k]] = x[k];
    else
        full_x_ = x;
    return full_x_;
}

double QuasistaticProblem::objective(ConstVectorRef x) { return potential_->value(configuration_of(x)); }

void QuasistaticProblem::gradient(ConstVectorRef x, VectorRef grad)
{
    const Eigen::VectorXd& configuration = configuration_of(x);
    if (!eliminating()) {
        potential_->gradient(configuration, grad);
        return;
    }
    potential_->gradient(configuration, full_gradient_);
    for (int k = 0; k < static_cast<int>(free_coordinates_.size()); ++k)
        grad[k] = full_gradient_[free_coordinates_[k]];
}

void QuasistaticProblem::constraints(ConstVectorRef x, VectorRef c)
{
    const Eigen::VectorXd& configuration = configuration_of(x);
    for (int s = 0; s < static_cast<int>(constraint_sets_.size()); ++s)
        constraint_sets_[s]->values(configuration, c.segment(constraint_offsets_[s], constraint_sets_[s]->num_constraints()));
}

void QuasistaticProblem::jacobian_values(ConstVectorRef x, VectorRef values)
{
    const Eigen::VectorXd& configuration = configuration_of(x);
    for (int s = 0; s < static_cast<int>(constraint_sets_.size()); ++s)
        constraint_sets_[s]->jacobian_values(configuration, set_values_[s]);
    for (int k = 0; k < static_cast<int>(jacobian_entries_.size()); ++k)
        values[k] = set_values_[jacobian_entries_[k].first][jacobian_entries_[k].second];
}

void QuasistaticProblem::fill_hessian(ConstVectorRef x, Projection projection, double sigma, ConstVectorRef lambda,
                                      VectorRef values)
{
    const Eigen::VectorXd& configuration = configuration_of(x);
    const int potential_entries = static_cast<int>(hessian_entries_.size());
    if (sigma == 0.0) {
        values.head(potential_entries).setZero();
    } else {
        potential_->hessian_values(configuration, projection, full_hessian_);
        for (int k = 0; k < potential_entries; ++k)
            values[k] = sigma * full_hessian_[hessian_entries_[k]];  // σ∇²E
    }
    if (constraint_hessian_entries_.empty())
        return;
    for (int s = 0; s < static_cast<int>(constraint_sets_.size()); ++s) {
        ConstraintSet& set = *constraint_sets_[s];
        if (set.hessian_pattern().nonzeros() > 0)
            set.hessian_values(configuration, lambda.segment(constraint_offsets_[s], set.num_constraints()),
                               projection, set_values_[s]);  // Σᵢ λᵢ∇²cᵢ
    }
    for (int k = 0; k < static_cast<int>(constraint_hessian_entries_.size()); ++k)
        values[potential_entries + k] =
            set_values_[constraint_hessian_entries_[k].first][constraint_hessian_entries_[k].second];
}

void QuasistaticProblem::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values)
{
    fill_hessian(x, Projection::none, sigma, lambda, values);
}

void QuasistaticProblem::projected_hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda,
                                                  VectorRef values)
{
    // σ·clamp(H_e) = clamp(σH_e) holds for σ ≥ 0 only.
    if (sigma < 0.0)
        throw std::logic_error("projected Hessian of " + options_.name + " needs sigma >= 0");
    fill_hessian(x, Projection::clamp, sigma, lambda, values);
}

void QuasistaticProblem::set_affine_map(int set, const Eigen::MatrixXd& map, const Eigen::VectorXd& translation)
{
    if (set < 0 || set >= static_cast<int>(sets_.size()))
        throw InputError("quasistatic problem '" + options_.name + "': Dirichlet set " + std::to_string(set) +
                         " does not exist (" + std::to_string(sets_.size()) + " sets)");
    DirichletSet updated = sets_[set];
    updated.map = map;
    updated.translation = translation;
    check_dirichlet_set(updated, set, potential_->dimension(), potential_->num_nodes());
    apply_set(updated, set);
    sets_[set] = std::move(updated);
}

void QuasistaticProblem::check_configuration(ConstVectorRef configuration) const
{
    if (configuration.size() != rest_.size())
        throw InputError("quasistatic problem '" + options_.name + "': configuration has " +
                         std::to_string(configuration.size()) + " coordinates, expected " +
                         std::to_string(rest_.size()));
    if (!configuration.allFinite())
        throw InputError("quasistatic problem '" + options_.name + "': configuration is not finite");
}

void QuasistaticProblem::set_starting_configuration(ConstVectorRef configuration)
{
    check_configuration(configuration);
    start_ = configuration;
}

Eigen::VectorXd QuasistaticProblem::full_configuration(ConstVectorRef x) const
{
    if (!eliminating())
        return x;
    Eigen::VectorXd configuration = prescribed_;
    for (int k = 0; k < static_cast<int>(free_coordinates_.size()); ++k)
        configuration[free_coordinates_[k]] = x[k];
    return configuration;
}

NearNullSpace QuasistaticProblem::near_null_space(ConstVectorRef x) const
{
    std::vector<int> variables = free_coordinates_;
    if (!eliminating()) {
        variables.resize(rest_.size());
        std::iota(variables.begin(), variables.end(), 0);
    }
    return rigid_body_modes(full_configuration(x), potential_->dimension(), variables);
}

Eigen::VectorXd QuasistaticProblem::variables_of(ConstVectorRef configuration) const
{
    if (!eliminating())
        return configuration;
    Eigen::VectorXd x(free_coordinates_.size());
    for (int k = 0; k < static_cast<int>(free_coordinates_.size()); ++k)
        x[k] = configuration[free_coordinates_[k]];
    return x;
}

} // namespace sinew
