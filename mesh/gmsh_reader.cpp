#include "sinew/mesh/gmsh_reader.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/element_orientation.hpp"
#include "sinew/mesh/gmsh_content.hpp"
#include "sinew/mesh/mesh_source.hpp"
#include "sinew/mesh/mesh_validation.hpp"
#include "sinew/mesh/remove_unused_nodes.hpp"
#include "sinew/mesh/text_line_reader.hpp"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace sinew {
namespace {

enum class MshVersion { v2_2, v4_1 };

/// "$MeshFormat", "<version> <file type> <data size>", "$EndMeshFormat".
MshVersion read_mesh_format(TextLineReader& in)
{
    if (!in.next())
        throw InputError(in.path() + ": the file is empty, not a Gmsh MSH file");
    if (in.token(0) != "$MeshFormat")
        in.fail("not a Gmsh MSH file: the first line must be $MeshFormat");
    in.require_next("the MSH version line");
    in.expect_token_count(3, "$MeshFormat (version, file type, data size)");
    const std::string version = in.token(0);
    if (version != "2.2" && version != "4.1")
        in.fail("MSH version " + version + " is not supported (sinew reads 2.2 and 4.1)");
    if (in.token(1) != "0")
        in.fail("binary MSH files are not supported: save the mesh as ASCII (file type 0)");
    gmsh::require_section_end(in, "$MeshFormat");
    return version == "2.2" ? MshVersion::v2_2 : MshVersion::v4_1;
}

/// Node tag → index into `nodes`; a repeated tag is an error.
std::unordered_map<int, int> index_node_tags(const std::string& path, const std::vector<gmsh::Node>& nodes)
{
    std::unordered_map<int, int> node_of_tag;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const auto [where, inserted] = node_of_tag.emplace(nodes[i].tag, static_cast<int>(i));
        if (!inserted)
            throw InputError(path + ":" + std::to_string(nodes[i].line) + ": node tag " +
                             std::to_string(nodes[i].tag) + " appears twice (first on line " +
                             std::to_string(nodes[where->second].line) + ")");
    }
    return node_of_tag;
}

/// The name of the group of physical tag `physical` (0: no physical group).
std::string group_name(const gmsh::Content& content, int dimension, int physical)
{
    if (physical == 0)
        return kDefaultGroupName;
    const auto name = content.physical_names.find({dimension, physical});
    return name != content.physical_names.end() ? name->second : "physical " + std::to_string(physical);
}

/// The kept elements (tets, else triangles) over the nodes they use.
Mesh mesh_from_content(const std::string& path, const gmsh::Content& content)
{
    if (content.elements.empty())
        throw InputError(path + ": no tetrahedra or triangles (Gmsh types 4 and 2) in $Elements");
    const bool has_tets = std::any_of(content.elements.begin(), content.elements.end(),
                                      [](const gmsh::Element& e) { return e.type == gmsh::kTetrahedronType; });
    const int kept_type = has_tets ? gmsh::kTetrahedronType : gmsh::kTriangleType;
    const int kept_dimension = has_tets ? 3 : 2;

    const std::unordered_map<int, int> node_of_tag = index_node_tags(path, content.nodes);
    std::vector<const gmsh::Element*> kept;
    for (const gmsh::Element& element : content.elements)
        if (element.type == kept_type)
            kept.push_back(&element);

    Mesh mesh;
    mesh.kind = has_tets ? ElementKind::tetrahedron : ElementKind::triangle_3d;
    mesh.nodes.resize(3, static_cast<Eigen::Index>(content.nodes.size()));
    for (std::size_t i = 0; i < content.nodes.size(); ++i)
        mesh.nodes.col(static_cast<Eigen::Index>(i)) = content.nodes[i].x;
    const int corners = nodes_per_element(mesh.kind);
    mesh.elements.resize(corners, static_cast<Eigen::Index>(kept.size()));
    MeshSource source(path);
    source.node_file = path;
    source.element_file = path;
    std::map<int, int> group_of_physical;
    for (std::size_t e = 0; e < kept.size(); ++e) {
        for (int k = 0; k < corners; ++k) {
            const int tag = kept[e]->node_tags[k];
            const auto found = node_of_tag.find(tag);
            if (found == node_of_tag.end())
                throw InputError(path + ":" + std::to_string(kept[e]->line) + ": node tag " + std::to_string(tag) +
                                 " is not in $Nodes");
            mesh.elements(k, static_cast<Eigen::Index>(e)) = found->second;
        }
        source.element_lines.push_back(kept[e]->line);
        group_of_physical.emplace(kept[e]->physical_tag, 0);
    }

    for (const int old_index : remove_unused_nodes(mesh))
        source.node_lines.push_back(content.nodes[old_index].line);
    if (!has_tets && mesh.nodes.row(2).isZero(0.0)) {
        mesh.kind = ElementKind::triangle_2d;
        mesh.nodes = Eigen::MatrixXd(mesh.nodes.topRows(2));
    }

    for (auto& [physical, group] : group_of_physical) {
        group = static_cast<int>(mesh.group_names.size());
        mesh.group_names.push_back(group_name(content, kept_dimension, physical));
    }
    for (const gmsh::Element* element : kept)
        mesh.element_groups.push_back(group_of_physical.at(element->physical_tag));

    orient_elements_positively(mesh);
    validate_mesh(mesh, source);
    return mesh;
}

} // namespace

Mesh read_gmsh(const std::string& path)
{
    TextLineReader in(path);
    const MshVersion version = read_mesh_format(in);
    const gmsh::Content content = version == MshVersion::v2_2 ? gmsh::parse_msh2(in) : gmsh::parse_msh4(in);
    return mesh_from_content(path, content);
}

} // namespace sinew
