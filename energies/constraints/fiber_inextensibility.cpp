#include "sinew/energies/constraints/fiber_inextensibility.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/element_rest_shape.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <string>

namespace sinew {
namespace {

const std::string kWho = "fiber inextensibility";

std::string element_label(int k, int element)
{
    return kWho + ": listed element " + std::to_string(k) + " (mesh element " + std::to_string(element) + ")";
}

/// Dm⁻¹ of a mesh element (material_dimension × material_dimension), as the
/// elastic potential forms it (rest_edge_matrix, seed 000 §4.1).
Eigen::MatrixXd rest_inverse(const Mesh& mesh, int element)
{
    if (material_dimension(mesh.kind) == 3)
        return rest_edge_matrix<3>(mesh, element).inverse();
    return rest_edge_matrix<2>(mesh, element).inverse();
}

} // namespace

FiberInextensibility::FiberInextensibility(const Mesh& mesh, std::vector<int> elements, const Eigen::MatrixXd& fibers)
    : kind_(mesh.kind),
      dimension_(space_dimension(mesh.kind)),
      nodes_per_element_(nodes_per_element(mesh.kind)),
      elements_(std::move(elements))
{
    check_mesh_arrays(mesh, kWho);
    const int count = num_constraints();
    const int cols = material_dimension(kind_);
    const bool membrane = kind_ == ElementKind::triangle_3d;
    if (fibers.cols() != count)
        throw InputError(kWho + ": " + std::to_string(count) + " elements listed but " +
                         std::to_string(fibers.cols()) + " fibers given");
    if (count > 0 && fibers.rows() != cols && !(membrane && fibers.rows() == 3))
        throw InputError(kWho + ": fibers of " + to_string(kind_) + " elements have " + std::to_string(cols) +
                         (membrane ? " or 3" : "") + " components, not " + std::to_string(fibers.rows()));

    std::vector<char> listed(mesh.num_elements(), 0);
    element_nodes_.resize(nodes_per_element_, count);
    fibers_.reserve(count);
    weights_.reserve(count);
    for (int k = 0; k < count; ++k) {
        const int e = elements_[k];
        if (e < 0 || e >= mesh.num_elements())
            throw InputError(kWho + ": listed element " + std::to_string(k) + " is " + std::to_string(e) +
                             ", outside [0, " + std::to_string(mesh.num_elements()) + ")");
        if (listed[e])
            throw InputError(element_label(k, e) + " is listed twice");
        listed[e] = 1;
        element_nodes_.col(k) = mesh.elements.col(e);

        // A degenerate element has no Dm⁻¹: rest_measure names it.
        try {
            rest_measure(mesh, e);
        } catch (const InputError& error) {
            throw InputError(kWho + ": " + error.what());
        }

        // a₀ in material coordinates (the elastic potential's convention): as
        // given, or for a membrane fiber given in space its in-plane part Eᵀa.
        const Eigen::VectorXd given = fibers.col(k);
        if (!given.allFinite())
            throw InputError(element_label(k, e) + ": fiber is not finite");
        Eigen::VectorXd a0 = given;
        if (membrane && given.size() == 3) {
            const Eigen::Matrix<double, 3, 2> frame =
                membrane_rest_frame(mesh.nodes.col(element_nodes_(0, k)), mesh.nodes.col(element_nodes_(1, k)),
                                    mesh.nodes.col(element_nodes_(2, k)));
            a0 = frame.transpose() * Eigen::Vector3d(given);
        }
        const double length = a0.norm();
        if (!(length > 1e-8 * given.norm()))
            throw InputError(element_label(k, e) +
                             (membrane ? ": fiber is zero or normal to the rest plane" : ": fiber is zero"));
        a0 /= length;  // unit a₀, so that tr(C M) = 1 at rest (seed 004 §4.1)

        // b = Dm⁻¹a₀ and F a₀ = Ds b = Σ_{a≥1} b_{a−1}(x_a − x₀) = Σ_a w_a x_a.
        const Eigen::VectorXd b = rest_inverse(mesh, e) * a0;
        Eigen::VectorXd w(nodes_per_element_);
        w[0] = -b.sum();
        w.tail(cols) = b;
        fibers_.push_back(a0);
        weights_.push_back(w);
    }

    // ∂c_k/∂x_a: row k, node by node, coordinate by coordinate.
    for (int k = 0; k < count; ++k)
        for (int a = 0; a < nodes_per_element_; ++a)
            for (int m = 0; m < dimension_; ++m)
                jacobian_.add(k, element_nodes_(a, k) * dimension_ + m);
    // ∇²c_k = 2 (w wᵀ) ⊗ I: only (x_a[m], x_b[m]) pairs; each unordered node
    // pair once (a ≥ b), written in the lower triangle of the coordinates.
    for (int k = 0; k < count; ++k)
        for (int a = 0; a < nodes_per_element_; ++a)
            for (int b = 0; b <= a; ++b)
                for (int m = 0; m < dimension_; ++m) {
                    const int p = element_nodes_(a, k) * dimension_ + m;
                    const int q = element_nodes_(b, k) * dimension_ + m;
                    hessian_.add(std::max(p, q), std::min(p, q));
                }
}

FiberInextensibility::SpaceVector FiberInextensibility::stretched_fiber(ConstVectorRef x, int k) const
{
    // F a₀ = Σ_a w_a x_a (seed 004 §4.1 with F = Ds·Dm⁻¹).
    SpaceVector Fa = SpaceVector::Zero(dimension_);
    for (int a = 0; a < nodes_per_element_; ++a)
        Fa += weights_[k][a] * x.segment(element_nodes_(a, k) * dimension_, dimension_);
    return Fa;
}

void FiberInextensibility::values(ConstVectorRef x, VectorRef c)
{
    for (int k = 0; k < num_constraints(); ++k)
        c[k] = stretched_fiber(x, k).squaredNorm() - 1.0;  // c = a₀ᵀ C a₀ − 1 = |F a₀|² − 1
}

void FiberInextensibility::jacobian_values(ConstVectorRef x, VectorRef values)
{
    int entry = 0;
    for (int k = 0; k < num_constraints(); ++k) {
        const SpaceVector Fa = stretched_fiber(x, k);
        for (int a = 0; a < nodes_per_element_; ++a)
            for (int m = 0; m < dimension_; ++m)
                values[entry++] = 2.0 * weights_[k][a] * Fa[m];  // ∂c/∂x_a = 2 w_a (F a₀)
    }
}

void FiberInextensibility::hessian_values(ConstVectorRef, ConstVectorRef lambda, Projection projection,
                                          VectorRef values)
{
    int entry = 0;
    for (int k = 0; k < num_constraints(); ++k) {
        // λ∇²c = 2λ (w wᵀ) ⊗ I; ∇²c is PSD, so its PSD projection is max(λ, 0)∇²c.
        const double weight = projection == Projection::clamp ? std::max(lambda[k], 0.0) : lambda[k];
        const Eigen::VectorXd& w = weights_[k];
        for (int a = 0; a < nodes_per_element_; ++a)
            for (int b = 0; b <= a; ++b)
                for (int m = 0; m < dimension_; ++m)
                    values[entry++] = 2.0 * weight * w[a] * w[b];
    }
}

void FiberInextensibility::add_output_data(ConstVectorRef x, ConstVectorRef multipliers, OutputArrays& arrays)
{
    std::vector<int> rows(elements_.size());
    for (size_t k = 0; k < rows.size(); ++k)
        rows[k] = static_cast<int>(k);
    add_element_data(x, multipliers, rows, arrays);
}

void FiberInextensibility::add_element_data(ConstVectorRef x, ConstVectorRef multipliers,
                                            const std::vector<int>& row_of, OutputArrays& arrays)
{
    Eigen::VectorXd c(num_constraints());
    values(x, c);  // c_e = a₀ᵀC_e a₀ − 1
    Eigen::MatrixXd& flag = arrays.cell_array("inextensible", 1, 0.0);
    Eigen::MatrixXd& value = arrays.cell_array("inextensibility_value", 1, 0.0);
    Eigen::MatrixXd& multiplier = arrays.cell_array("inextensibility_multiplier", 1, 0.0);
    for (size_t k = 0; k < elements_.size(); ++k) {
        const int e = elements_[k];
        flag(0, e) = 1.0;
        value(0, e) = c[static_cast<Eigen::Index>(k)];
        if (row_of[k] < multipliers.size())
            multiplier(0, e) = multipliers[row_of[k]];
    }
}

} // namespace sinew
