#include "sinew/mesh/tetgen_reader.hpp"

#include "sinew/mesh/element_orientation.hpp"
#include "sinew/mesh/mesh_source.hpp"
#include "sinew/mesh/mesh_validation.hpp"
#include "sinew/mesh/text_line_reader.hpp"

#include <cctype>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace sinew {
namespace {

bool ends_with_ignoring_case(const std::string& text, const std::string& suffix)
{
    if (text.size() < suffix.size())
        return false;
    const std::size_t start = text.size() - suffix.size();
    for (std::size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[start + i])) != suffix[i])
            return false;
    return true;
}

std::string base_path(const std::string& path)
{
    for (const char* extension : {".ele", ".node"})
        if (ends_with_ignoring_case(path, extension))
            return path.substr(0, path.size() - std::string(extension).size());
    return path;
}

struct NodeFile {
    Eigen::MatrixXd nodes;  ///< dimension × count
    std::vector<int> lines;
    int first_number = 0;   ///< 0 or 1: the numbering of both files
};

/// .node: header "<#points> <dimension> <#attributes> <#boundary markers>"
/// (trailing fields optional: 3, 0, 0), then "<number> <x> <y> [<z>]
/// [attributes] [marker]" per point.
NodeFile read_node_file(const std::string& path)
{
    TextLineReader in(path, '#');
    in.require_next("the header line");
    if (in.token_count() > 4)
        in.fail("header: expected '<#points> <dimension> <#attributes> <#boundary markers>', found " +
                std::to_string(in.token_count()) + " values");
    const int count = in.integer(0, "number of points");
    const int dimension = in.token_count() > 1 ? in.integer(1, "dimension") : 3;
    const int attributes = in.token_count() > 2 ? in.integer(2, "number of attributes") : 0;
    const int markers = in.token_count() > 3 ? in.integer(3, "number of boundary markers") : 0;
    if (count < 1)
        in.fail("number of points is " + std::to_string(count) + ", expected at least 1");
    if (dimension != 2 && dimension != 3)
        in.fail("dimension is " + std::to_string(dimension) + ", expected 2 or 3");
    if (attributes < 0)
        in.fail("number of attributes is " + std::to_string(attributes));
    if (markers != 0 && markers != 1)
        in.fail("number of boundary markers is " + std::to_string(markers) + ", expected 0 or 1");
    in.require_room(attributes, 1, "attributes per point");
    const long long values = 1LL + dimension + attributes + markers;

    // Grown as the points are read, never sized by the header's count alone.
    NodeFile file;
    std::vector<double> coordinates;
    for (int i = 0; i < count; ++i) {
        in.require_next("point " + std::to_string(i + 1) + " of " + std::to_string(count));
        in.expect_token_count(static_cast<std::size_t>(values), "point");
        const int number = in.integer(0, "point number");
        if (i == 0) {
            if (number != 0 && number != 1)
                in.fail("first point number is " + std::to_string(number) + ", expected 0 or 1");
            file.first_number = number;
        } else if (number != file.first_number + i) {
            in.fail("point number " + std::to_string(number) + " out of sequence, expected " +
                    std::to_string(file.first_number + i));
        }
        for (int k = 0; k < dimension; ++k)
            coordinates.push_back(in.number(1 + k, std::string("coordinate ") + "xyz"[k] + " of point " +
                                                       std::to_string(number)));
        file.lines.push_back(in.line_number());
    }
    if (in.next())
        in.fail("more lines than the " + std::to_string(count) + " points the header declares");
    file.nodes = Eigen::Map<const Eigen::MatrixXd>(coordinates.data(), dimension, count);
    return file;
}

std::string region_name(double value)
{
    std::ostringstream name;
    name.precision(15);
    name << "region " << value;
    return name.str();
}

struct ElementFile {
    Eigen::MatrixXi elements;     ///< corners × count, 0-based
    std::vector<int> lines;
    std::vector<double> regions;  ///< first attribute of each element; empty without attributes
};

/// .ele: header "<#elements> <nodes per element> <#attributes>" (trailing
/// fields optional), then "<number> <node> … [attributes]" per element, node
/// numbers in the .node file's numbering.
ElementFile read_element_file(const std::string& path, const std::string& node_path, const NodeFile& nodes)
{
    const int dimension = static_cast<int>(nodes.nodes.rows());
    const int corners = dimension + 1;
    const int num_nodes = static_cast<int>(nodes.nodes.cols());
    const std::string shape = dimension == 3 ? "tetrahedron" : "triangle";
    TextLineReader in(path, '#');
    in.require_next("the header line");
    if (in.token_count() > 3)
        in.fail("header: expected '<#elements> <nodes per element> <#attributes>', found " +
                std::to_string(in.token_count()) + " values");
    const int count = in.integer(0, "number of elements");
    const int listed_corners = in.token_count() > 1 ? in.integer(1, "nodes per element") : corners;
    const int attributes = in.token_count() > 2 ? in.integer(2, "number of attributes") : 0;
    if (count < 1)
        in.fail("number of elements is " + std::to_string(count) + ", expected at least 1");
    if (listed_corners != corners)
        in.fail(std::to_string(listed_corners) + " nodes per element: the " + std::to_string(dimension) +
                "D .node file needs linear " + (dimension == 3 ? "tetrahedra" : "triangles") + " of " +
                std::to_string(corners) + " nodes");
    if (attributes < 0)
        in.fail("number of attributes is " + std::to_string(attributes));
    in.require_room(attributes, 1, "attributes per element");
    const long long values = 1LL + corners + attributes;

    // Grown as the elements are read, never sized by the header's count alone.
    ElementFile file;
    std::vector<int> corner_nodes;
    for (int e = 0; e < count; ++e) {
        in.require_next(shape + " " + std::to_string(e + 1) + " of " + std::to_string(count));
        in.expect_token_count(static_cast<std::size_t>(values), shape);
        in.integer(0, shape + " number");
        for (int k = 0; k < corners; ++k) {
            const int number = in.integer(1 + k, "node number");
            const int node = number - nodes.first_number;
            if (node < 0 || node >= num_nodes)
                in.fail("node number " + std::to_string(number) + " is not in " + node_path + " (numbers " +
                        std::to_string(nodes.first_number) + " to " +
                        std::to_string(nodes.first_number + num_nodes - 1) + ")");
            for (int j = 0; j < k; ++j)
                if (corner_nodes[corner_nodes.size() - static_cast<std::size_t>(k - j)] == node)
                    in.fail("node number " + std::to_string(number) + " appears twice in the " + shape);
            corner_nodes.push_back(node);
        }
        if (attributes > 0)
            file.regions.push_back(in.number(1 + corners, "region attribute"));
        file.lines.push_back(in.line_number());
    }
    if (in.next())
        in.fail("more lines than the " + std::to_string(count) + " elements the header declares");
    file.elements = Eigen::Map<const Eigen::MatrixXi>(corner_nodes.data(), corners, count);
    return file;
}

/// One group per distinct region value, "region <value>", sorted by value.
void group_by_region(const std::vector<double>& regions, Mesh& mesh)
{
    std::map<double, int> group_of_region;
    for (double region : regions)
        group_of_region.emplace(region, 0);
    for (auto& [region, group] : group_of_region) {
        group = static_cast<int>(mesh.group_names.size());
        mesh.group_names.push_back(region_name(region));
    }
    for (double region : regions)
        mesh.element_groups.push_back(group_of_region.at(region));
}

} // namespace

Mesh read_tetgen(const std::string& path)
{
    const std::string base = base_path(path);
    const std::string node_path = base + ".node";
    const std::string element_path = base + ".ele";
    const NodeFile node_file = read_node_file(node_path);
    ElementFile element_file = read_element_file(element_path, node_path, node_file);

    Mesh mesh;
    mesh.kind = node_file.nodes.rows() == 3 ? ElementKind::tetrahedron : ElementKind::triangle_2d;
    mesh.nodes = node_file.nodes;
    mesh.elements = std::move(element_file.elements);
    if (element_file.regions.empty()) {
        mesh.group_names = {kDefaultGroupName};
        mesh.element_groups.assign(mesh.num_elements(), 0);
    } else {
        group_by_region(element_file.regions, mesh);
    }
    MeshSource source(path);
    source.node_file = node_path;
    source.node_lines = node_file.lines;
    source.element_file = element_path;
    source.element_lines = element_file.lines;
    orient_elements_positively(mesh);
    validate_mesh(mesh, source);
    return mesh;
}

} // namespace sinew
