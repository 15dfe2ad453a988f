#include "sinew/energies/constraints/weak_fiber_inextensibility.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/element_rest_shape.hpp"

#include <algorithm>
#include <map>

namespace sinew {

WeakFiberInextensibility::WeakFiberInextensibility(const Mesh& mesh, std::vector<int> elements,
                                                   const Eigen::MatrixXd& fibers, const Eigen::VectorXi& cells)
{
    const int dimension = static_cast<int>(mesh.nodes.rows());
    if (cells.size() != dimension || (cells.array() < 1).any())
        throw InputError("weak fiber inextensibility: the grid needs " + std::to_string(dimension) +
                         " cell counts, each at least 1");
    per_element_ = std::make_unique<FiberInextensibility>(mesh, std::move(elements), fibers);
    const std::vector<int>& listed = per_element_->elements();
    const Eigen::VectorXd lower = mesh.nodes.rowwise().minCoeff();
    const Eigen::VectorXd extent = (mesh.nodes.rowwise().maxCoeff() - lower).cwiseMax(1e-300);
    std::map<int, int> row_of_cell;
    volumes_.resize(static_cast<Eigen::Index>(listed.size()));
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
        const auto [found, added] = row_of_cell.emplace(cell, static_cast<int>(row_of_cell.size()));
        if (added)
            cell_of_row_.push_back(cell);
        row_of_element_.push_back(found->second);
        volumes_[static_cast<Eigen::Index>(k)] = rest_measure(mesh, e);  // V_e
    }
    const SparsityPattern& element_jacobian = per_element_->jacobian_pattern();
    for (int entry = 0; entry < element_jacobian.nonzeros(); ++entry)
        jacobian_.add(row_of_element_[static_cast<size_t>(element_jacobian.rows[entry])], element_jacobian.cols[entry]);
    scratch_.resize(std::max<Eigen::Index>(element_jacobian.nonzeros(), volumes_.size()));
}

void WeakFiberInextensibility::values(ConstVectorRef x, VectorRef c)
{
    auto per_element = scratch_.head(volumes_.size());
    per_element_->values(x, per_element);
    c.setZero();
    for (Eigen::Index k = 0; k < volumes_.size(); ++k)
        c[row_of_element_[static_cast<size_t>(k)]] += volumes_[k] * per_element[k];  // c_z = Σ V_e c_e
}

void WeakFiberInextensibility::jacobian_values(ConstVectorRef x, VectorRef values)
{
    per_element_->jacobian_values(x, values);
    const SparsityPattern& element_jacobian = per_element_->jacobian_pattern();
    for (int entry = 0; entry < element_jacobian.nonzeros(); ++entry)
        values[entry] *= volumes_[element_jacobian.rows[entry]];  // ∂c_z/∂x = Σ V_e ∂c_e/∂x
}

void WeakFiberInextensibility::hessian_values(ConstVectorRef x, ConstVectorRef lambda, Projection projection,
                                              VectorRef values)
{
    // Σ_z λ_z Σ_{e∈z} V_e ∇²c_e = Σ_e (V_e λ_{z(e)}) ∇²c_e; V_e > 0, so the
    // clamp of each term is the clamp of λ_z.
    auto weights = scratch_.head(volumes_.size());
    for (Eigen::Index k = 0; k < volumes_.size(); ++k)
        weights[k] = volumes_[k] * lambda[row_of_element_[static_cast<size_t>(k)]];
    per_element_->hessian_values(x, weights, projection, values);
}

} // namespace sinew
