#include "sinew/runs/scene_vtu.hpp"

namespace sinew {
namespace {

/// The node-major vector v (dimension·n entries) as a dimension × n matrix.
Eigen::MatrixXd by_node(const Eigen::VectorXd& v, int dimension)
{
    return Eigen::Map<const Eigen::MatrixXd>(v.data(), dimension, v.size() / dimension);
}

} // namespace

OutputArrays scene_output_arrays(Scene& scene, const Eigen::VectorXd& configuration, const Eigen::VectorXd& multipliers)
{
    const Mesh& mesh = scene.mesh;
    const int dimension = static_cast<int>(mesh.nodes.rows());
    QuasistaticProblem& problem = *scene.problem;
    Eigen::VectorXd gradient(configuration.size());
    problem.potential().gradient(configuration, gradient);
    const Eigen::MatrixXd positions = by_node(configuration, dimension);

    OutputArrays arrays;
    arrays.num_points = mesh.num_nodes();
    arrays.num_cells = mesh.num_elements();
    arrays.points["displacement"] = positions - mesh.nodes;
    arrays.points["force"] = -by_node(gradient, dimension);  // net force −∂E/∂x
    arrays.points["fixed"] = scene.fixed_flags().transpose();
    Eigen::MatrixXd group(1, mesh.num_elements());
    for (int e = 0; e < mesh.num_elements(); ++e)
        group(0, e) = mesh.element_groups[static_cast<size_t>(e)];
    arrays.cells["group"] = group;

    // Each part of the scene writes its own data.
    for (const auto& term : problem.potential().terms())
        term->add_output_data(configuration, arrays);
    for (const auto& set : scene.constraints) {
        const int offset = problem.constraint_offset(*set);
        const bool solved = offset >= 0 && offset + set->num_constraints() <= multipliers.size();
        const Eigen::VectorXd rows = solved ? Eigen::VectorXd(multipliers.segment(offset, set->num_constraints()))
                                            : Eigen::VectorXd();
        set->add_output_data(configuration, rows, arrays);
    }
    return arrays;
}

void write_scene_vtu(const std::string& path, Scene& scene, const Eigen::VectorXd& configuration,
                     const Eigen::VectorXd& multipliers, VtuEncoding encoding, const VtuArrays& extra_point_data)
{
    OutputArrays arrays = scene_output_arrays(scene, configuration, multipliers);
    for (const auto& [name, values] : extra_point_data)
        arrays.points[name] = values;
    const int dimension = static_cast<int>(scene.mesh.nodes.rows());
    write_vtu(path, scene.mesh, by_node(configuration, dimension), arrays.points, arrays.cells, encoding);
}

} // namespace sinew
