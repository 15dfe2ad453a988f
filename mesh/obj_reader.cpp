#include "sinew/mesh/obj_reader.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/core/parse_number.hpp"
#include "sinew/mesh/mesh_source.hpp"
#include "sinew/mesh/mesh_validation.hpp"
#include "sinew/mesh/text_line_reader.hpp"

#include <array>
#include <map>

namespace sinew {
namespace {

struct Face {
    std::array<int, 3> vertices;  ///< 0-based, checked against the vertex count once all are read
    int group = 0;
    int line = 0;
};

/// The 0-based vertex of a face corner "i", "i/t", "i/t/n" or "i//n": i is
/// 1-based, or negative to count back from the last vertex read so far.
int face_vertex(const TextLineReader& in, std::size_t token, int vertices_so_far)
{
    const std::string& corner = in.token(token);
    const int index = parse_int(corner.substr(0, corner.find('/')), in.where() + ": face vertex");
    if (index == 0)
        in.fail("face vertex index 0: OBJ indices start at 1");
    if (index > 0)
        return index - 1;
    if (vertices_so_far + index < 0)
        in.fail("face vertex index " + std::to_string(index) + " reaches before the first vertex (" +
                std::to_string(vertices_so_far) + " read so far)");
    return vertices_so_far + index;
}

Eigen::Vector3d vertex_position(const TextLineReader& in)
{
    const std::size_t values = in.token_count() - 1;
    if (values != 3 && values != 4 && values != 6)
        in.fail("vertex: expected 'v x y z', 'v x y z w' or 'v x y z r g b', found " + std::to_string(values) +
                " values");
    Eigen::Vector3d x;
    for (int k = 0; k < 3; ++k)
        x[k] = in.number(1 + k, std::string("vertex coordinate ") + "xyz"[k]);
    if (values == 4) {
        const double w = in.number(4, "vertex weight w");
        if (w == 0.0)
            in.fail("vertex weight w is 0");
        x /= w;
    }
    return x;
}

} // namespace

Mesh read_obj(const std::string& path)
{
    TextLineReader in(path, '#');
    std::vector<Eigen::Vector3d> vertices;
    std::vector<int> vertex_lines;
    std::vector<Face> faces;
    std::vector<std::string> group_names;
    std::map<std::string, int> group_of_name;
    std::string current_group = kDefaultGroupName;
    while (in.next()) {
        const std::string& keyword = in.token(0);
        if (keyword == "v") {
            vertices.push_back(vertex_position(in));
            vertex_lines.push_back(in.line_number());
        } else if (keyword == "f") {
            const std::size_t corners = in.token_count() - 1;
            if (corners > 3)
                in.fail("face with " + std::to_string(corners) +
                        " vertices: sinew reads triangles only (triangulate the surface on export)");
            if (corners < 3)
                in.fail("face with " + std::to_string(corners) + " vertices: a face needs 3");
            Face face;
            for (std::size_t k = 0; k < 3; ++k) {
                face.vertices[k] = face_vertex(in, 1 + k, static_cast<int>(vertices.size()));
                for (std::size_t j = 0; j < k; ++j)
                    if (face.vertices[j] == face.vertices[k])
                        in.fail("face uses vertex " + std::to_string(face.vertices[k] + 1) + " twice");
            }
            const auto [group, added] = group_of_name.emplace(current_group, static_cast<int>(group_names.size()));
            if (added)
                group_names.push_back(current_group);
            face.group = group->second;
            face.line = in.line_number();
            faces.push_back(face);
        } else if (keyword == "g") {
            current_group = in.token_count() > 1 ? in.token(1) : kDefaultGroupName;
        }
    }
    if (faces.empty())
        throw InputError(path + ": no faces ('f' lines) in the file");

    Mesh mesh;
    mesh.kind = ElementKind::triangle_3d;
    mesh.nodes.resize(3, static_cast<Eigen::Index>(vertices.size()));
    for (std::size_t i = 0; i < vertices.size(); ++i)
        mesh.nodes.col(static_cast<Eigen::Index>(i)) = vertices[i];
    mesh.elements.resize(3, static_cast<Eigen::Index>(faces.size()));
    MeshSource source(path);
    source.node_file = path;
    source.node_lines = vertex_lines;
    source.element_file = path;
    for (std::size_t e = 0; e < faces.size(); ++e) {
        for (int k = 0; k < 3; ++k) {
            const int vertex = faces[e].vertices[k];
            if (vertex >= static_cast<int>(vertices.size()))
                throw InputError(path + ":" + std::to_string(faces[e].line) + ": face vertex " +
                                 std::to_string(vertex + 1) + " does not exist (the file has " +
                                 std::to_string(vertices.size()) + " vertices)");
            mesh.elements(k, static_cast<Eigen::Index>(e)) = vertex;
        }
        mesh.element_groups.push_back(faces[e].group);
        source.element_lines.push_back(faces[e].line);
    }
    mesh.group_names = group_names;
    validate_mesh(mesh, source);
    return mesh;
}

} // namespace sinew
