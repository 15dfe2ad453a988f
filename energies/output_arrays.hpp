#pragma once
#include <Eigen/Core>

#include <map>
#include <string>

namespace sinew {

/// The point and cell data of one output file (a VTU), which each potential
/// and constraint set of a scene fills with its own arrays through its
/// add_output_data hook: name → components × count, one column per node or
/// per element. A runner writes them without knowing who wrote what.
struct OutputArrays {
    int num_points = 0;
    int num_cells = 0;
    std::map<std::string, Eigen::MatrixXd> points;
    std::map<std::string, Eigen::MatrixXd> cells;

    /// The cell array `name`, created with `components` rows filled with
    /// `fill` when missing, so that several sets can fill one array.
    Eigen::MatrixXd& cell_array(const std::string& name, int components, double fill)
    {
        auto found = cells.find(name);
        if (found == cells.end())
            found = cells.emplace(name, Eigen::MatrixXd::Constant(components, num_cells, fill)).first;
        return found->second;
    }
    /// The point array `name`, likewise.
    Eigen::MatrixXd& point_array(const std::string& name, int components, double fill)
    {
        auto found = points.find(name);
        if (found == points.end())
            found = points.emplace(name, Eigen::MatrixXd::Constant(components, num_points, fill)).first;
        return found->second;
    }
};

} // namespace sinew
