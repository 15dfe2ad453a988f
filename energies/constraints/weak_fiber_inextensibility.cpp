#include "sinew/energies/constraints/weak_fiber_inextensibility.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/element_rest_shape.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace sinew {

namespace {

/// "(i, j, k) of the 4 × 4 × 2 grid" for the linear cell index (x fastest).
std::string cell_name(int cell, const Eigen::VectorXi& cells)
{
    std::string index, grid;
    for (Eigen::Index d = 0; d < cells.size(); ++d) {
        index += (d ? ", " : "") + std::to_string(cell % cells[d]);
        grid += (d ? " × " : "") + std::to_string(cells[d]);
        cell /= cells[d];
    }
    return "(" + index + ") of the " + grid + " grid";
}

} // namespace

WeakFiberInextensibility::WeakFiberInextensibility(const Mesh& mesh, std::vector<int> elements,
                                                   const Eigen::MatrixXd& fibers, const Eigen::VectorXi& cells)
{
    const int dimension = static_cast<int>(mesh.nodes.rows());
    if (cells.size() != dimension || (cells.array() < 1).any())
        throw InputError("weak fiber inextensibility: the grid needs " + std::to_string(dimension) +
                         " cell counts, each at least 1");
    cells_ = cells;
    per_element_ = std::make_unique<FiberInextensibility>(mesh, std::move(elements), fibers);
    const std::vector<int>& listed = per_element_->elements();
    // The grid spans the listed elements' nodes; a cell is the row of its index.
    Eigen::VectorXd lower = Eigen::VectorXd::Constant(dimension, HUGE_VAL), upper = -lower;
    for (int e : listed)
        for (Eigen::Index a = 0; a < mesh.elements.rows(); ++a) {
            lower = lower.cwiseMin(mesh.nodes.col(mesh.elements(a, e)));
            upper = upper.cwiseMax(mesh.nodes.col(mesh.elements(a, e)));
        }
    const Eigen::VectorXd extent = (upper - lower).cwiseMax(1e-300);
    std::vector<int> members(static_cast<size_t>(cells.prod()), 0);
    weights_.resize(static_cast<Eigen::Index>(listed.size()));
    for (size_t k = 0; k < listed.size(); ++k) {
        const int e = listed[k];
        Eigen::VectorXd centroid = Eigen::VectorXd::Zero(dimension);
        for (Eigen::Index a = 0; a < mesh.elements.rows(); ++a)
            centroid += mesh.nodes.col(mesh.elements(a, e));
        centroid /= static_cast<double>(mesh.elements.rows());
        int cell = 0;
        for (int d = dimension - 1; d >= 0; --d) {
            const int i = std::min(cells[d] - 1, static_cast<int>((centroid[d] - lower[d]) / extent[d] * cells[d]));
            cell = cell * cells[d] + std::max(0, i);
        }
        ++members[static_cast<size_t>(cell)];
        row_of_element_.push_back(cell);
        weights_[static_cast<Eigen::Index>(k)] = rest_measure(mesh, e);  // V_e
    }
    const auto empty = std::find(members.begin(), members.end(), 0);
    if (empty != members.end())
        throw InputError("weak fiber inextensibility: cell " +
                         cell_name(static_cast<int>(empty - members.begin()), cells) +
                         " over the constrained elements holds no element's centroid; use fewer cells");
    // w_e = V_e / V_z, V_z = Σ_{e∈z} V_e: each row a volume-weighted mean.
    Eigen::VectorXd cell_volume = Eigen::VectorXd::Zero(cells.prod());
    for (Eigen::Index k = 0; k < weights_.size(); ++k)
        cell_volume[row_of_element_[static_cast<size_t>(k)]] += weights_[k];
    for (Eigen::Index k = 0; k < weights_.size(); ++k)
        weights_[k] /= cell_volume[row_of_element_[static_cast<size_t>(k)]];
    // One entry per (cell, coordinate): the elements of a cell share nodes, and
    // a repeated entry would multiply the pattern of JᵀJ (a row with k
    // entries gives k² products) by the square of the sharing.
    const SparsityPattern& element_jacobian = per_element_->jacobian_pattern();
    std::map<std::pair<int, int>, int> entry_of;
    for (int entry = 0; entry < element_jacobian.nonzeros(); ++entry) {
        const int row = row_of_element_[static_cast<size_t>(element_jacobian.rows[entry])];
        const int col = element_jacobian.cols[entry];
        const auto [found, added] = entry_of.emplace(std::make_pair(row, col), jacobian_.nonzeros());
        if (added)
            jacobian_.add(row, col);
        entry_of_element_entry_.push_back(found->second);
    }
    scratch_.resize(std::max<Eigen::Index>(element_jacobian.nonzeros(), weights_.size()));
}

void WeakFiberInextensibility::values(ConstVectorRef x, VectorRef c)
{
    auto per_element = scratch_.head(weights_.size());
    per_element_->values(x, per_element);
    c.setZero();
    for (Eigen::Index k = 0; k < weights_.size(); ++k)
        c[row_of_element_[static_cast<size_t>(k)]] += weights_[k] * per_element[k];  // c_z = Σ w_e c_e
}

void WeakFiberInextensibility::jacobian_values(ConstVectorRef x, VectorRef values)
{
    const SparsityPattern& element_jacobian = per_element_->jacobian_pattern();
    auto per_element = scratch_.head(element_jacobian.nonzeros());
    per_element_->jacobian_values(x, per_element);
    values.setZero();
    for (int entry = 0; entry < element_jacobian.nonzeros(); ++entry)  // ∂c_z/∂x = Σ_{e∈z} w_e ∂c_e/∂x
        values[entry_of_element_entry_[static_cast<size_t>(entry)]] +=
            weights_[element_jacobian.rows[entry]] * per_element[entry];
}

void WeakFiberInextensibility::hessian_values(ConstVectorRef x, ConstVectorRef lambda, Projection projection,
                                              VectorRef values)
{
    // Σ_z λ_z Σ_{e∈z} w_e ∇²c_e = Σ_e (w_e λ_{z(e)}) ∇²c_e; w_e > 0, so the
    // clamp of each term is the clamp of λ_z.
    auto weights = scratch_.head(weights_.size());
    for (Eigen::Index k = 0; k < weights_.size(); ++k)
        weights[k] = weights_[k] * lambda[row_of_element_[static_cast<size_t>(k)]];
    per_element_->hessian_values(x, weights, projection, values);
}

void WeakFiberInextensibility::add_output_data(ConstVectorRef x, ConstVectorRef multipliers, OutputArrays& arrays)
{
    per_element_->add_element_data(x, multipliers, row_of_element_, arrays);
    Eigen::MatrixXd& cell = arrays.cell_array("inextensibility_cell", 1, -1.0);
    for (size_t k = 0; k < row_of_element_.size(); ++k)
        cell(0, per_element_->elements()[k]) = row_of_element_[k];
}

} // namespace sinew
