#include "sinew/runs/scene_vtu.hpp"

#include "sinew/energies/constraints/fiber_inextensibility.hpp"
#include "sinew/energies/constraints/weak_fiber_inextensibility.hpp"

namespace sinew {
namespace {

/// The node-major vector v (dimension·n entries) as a dimension × n matrix.
Eigen::MatrixXd by_node(const Eigen::VectorXd& v, int dimension)
{
    return Eigen::Map<const Eigen::MatrixXd>(v.data(), dimension, v.size() / dimension);
}

/// The element columns of the inextensibility cell data, filled per set.
struct InextensibilityCells {
    Eigen::MatrixXd flag, value, multiplier, cell;
    bool any = false, weak = false;
};

/// Per element: c_e = a₀ᵀC_e a₀ − 1 at the configuration, and the multiplier
/// of the element's row (`row_of` the element's index in the set's list).
template <typename RowOf>
void add_fiber_elements(FiberInextensibility& fibers, const Eigen::VectorXd& configuration,
                        const Eigen::VectorXd& multipliers, int offset, RowOf row_of, InextensibilityCells& cells)
{
    Eigen::VectorXd c(fibers.num_constraints());
    fibers.values(configuration, c);
    for (int k = 0; k < fibers.num_constraints(); ++k) {
        const int e = fibers.elements()[static_cast<size_t>(k)];
        const int row = row_of(k);
        cells.flag(0, e) = 1.0;
        cells.value(0, e) = c[k];
        if (offset >= 0 && offset + row < multipliers.size())
            cells.multiplier(0, e) = multipliers[offset + row];
    }
    cells.any = true;
}

/// Cell data of the scene's inextensible fibers: "inextensible" (1 where an
/// element carries a₀ᵀCa₀ − 1 = 0, alone or in a weak-form cell), the
/// element's own value c_e and the multiplier of its row (Ipopt's sign
/// convention: λ_e per element, λ_z of its grid cell in weak form; 0 where
/// the element carries none), and in weak form "inextensibility_cell", the
/// grid cell z of each element (−1 elsewhere).
void add_inextensibility_cells(const Scene& scene, const Eigen::VectorXd& configuration,
                               const Eigen::VectorXd& multipliers, VtuArrays& arrays)
{
    const int count = scene.mesh.num_elements();
    InextensibilityCells cells;
    cells.flag = cells.value = cells.multiplier = Eigen::MatrixXd::Zero(1, count);
    cells.cell = Eigen::MatrixXd::Constant(1, count, -1.0);
    for (const auto& set : scene.constraints) {
        const int offset = scene.problem->constraint_offset(*set);
        if (auto* fibers = dynamic_cast<FiberInextensibility*>(set.get()))
            add_fiber_elements(*fibers, configuration, multipliers, offset, [](int k) { return k; }, cells);
        if (auto* weak = dynamic_cast<WeakFiberInextensibility*>(set.get())) {
            const std::vector<int>& row_of_element = weak->row_of_element();
            const auto row_of = [&row_of_element](int k) { return row_of_element[static_cast<size_t>(k)]; };
            add_fiber_elements(weak->per_element(), configuration, multipliers, offset, row_of, cells);
            for (size_t k = 0; k < row_of_element.size(); ++k)
                cells.cell(0, weak->per_element().elements()[k]) = row_of_element[k];
            cells.weak = true;
        }
    }
    if (!cells.any)
        return;
    arrays["inextensible"] = cells.flag;
    arrays["inextensibility_value"] = cells.value;
    arrays["inextensibility_multiplier"] = cells.multiplier;
    if (cells.weak)
        arrays["inextensibility_cell"] = cells.cell;
}

} // namespace

void write_scene_vtu(const std::string& path, Scene& scene, const Eigen::VectorXd& configuration,
                     const Eigen::VectorXd& multipliers, const VtuArrays& extra_point_data)
{
    const Mesh& mesh = scene.mesh;
    const int dimension = static_cast<int>(mesh.nodes.rows());
    Eigen::VectorXd gradient(configuration.size());
    scene.problem->potential().gradient(configuration, gradient);
    const Eigen::MatrixXd positions = by_node(configuration, dimension);

    VtuArrays points;
    points["displacement"] = positions - mesh.nodes;
    points["force"] = -by_node(gradient, dimension);  // net force −∂E/∂x
    points["fixed"] = scene.fixed_flags().transpose();
    for (const auto& [name, values] : extra_point_data)
        points[name] = values;

    const int count = mesh.num_elements();
    const int fiber_rows = material_dimension(mesh.kind);
    Eigen::MatrixXd group(1, count), activation(1, count), damage(1, count), fiber(fiber_rows, count);
    for (int e = 0; e < count; ++e) {
        group(0, e) = mesh.element_groups[static_cast<size_t>(e)];
        activation(0, e) = scene.elastic->activation(e);
        damage(0, e) = scene.elastic->damage(e);
        fiber.col(e) = scene.elastic->fiber(e);
    }
    VtuArrays cells;
    cells["group"] = group;
    cells["activation"] = activation;
    cells["damage"] = damage;
    cells["fiber"] = fiber;
    cells["stress_norm"] = scene.elastic->stress_norms(configuration).transpose();
    add_inextensibility_cells(scene, configuration, multipliers, cells);
    write_vtu(path, mesh, positions, points, cells);
}

} // namespace sinew
