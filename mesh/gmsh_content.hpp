#pragma once
// What the Gmsh MSH parsers (2.2 and 4.1) extract from a file, before it
// becomes a Mesh (gmsh_reader.cpp). Internal to mesh/.
#include "sinew/mesh/text_line_reader.hpp"

#include <Eigen/Core>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace sinew::gmsh {

/// Gmsh element types sinew keeps: 4-node tetrahedron and 3-node triangle.
inline constexpr int kTetrahedronType = 4;
inline constexpr int kTriangleType = 2;

struct Node {
    int tag = 0;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    int line = 0;
};

struct Element {
    int type = 0;  ///< kTetrahedronType or kTriangleType
    std::vector<int> node_tags;
    int physical_tag = 0;  ///< 0 when the element is in no physical group
    int line = 0;
};

struct Content {
    std::vector<Node> nodes;
    std::vector<Element> elements;  ///< tetrahedra and triangles only
    std::map<std::pair<int, int>, std::string> physical_names;  ///< (dimension, tag) → name
};

/// How sinew treats a Gmsh element type: keeps it (tetrahedron, triangle),
/// ignores it (points and lines of any order), or rejects it (everything else).
enum class TypeUse { keep, ignore, reject };
TypeUse type_use(int type);
/// Nodes of a kept type (4 or 3).
int kept_type_nodes(int type);
/// A readable name of a Gmsh element type for messages ("8-node hexahedron").
std::string type_name(int type);

/// Moves to the next line, which must be an entry of `section` (`what`, e.g.
/// "node 3 of 8"): fails when the file or the section ends first, i.e. when
/// the section holds fewer entries than its counts promise.
void require_entry(TextLineReader& in, const std::string& section, const std::string& what);
/// Moves to the next line, which must be the section's "$End…" line: fails
/// when the section holds more entries than its counts promise.
void require_section_end(TextLineReader& in, const std::string& section);
/// Skips a section the reader does not use.
void skip_section(TextLineReader& in, const std::string& section);
/// Fails when an element lists a node tag twice.
void require_distinct_node_tags(const TextLineReader& in, const std::vector<int>& node_tags);
/// $PhysicalNames (the same in 2.2 and 4.1): "<dimension> <tag> "<name>"".
void read_physical_names(TextLineReader& in, Content& content);

/// The sections after $MeshFormat of an ASCII MSH 2.2 / 4.1 file.
Content parse_msh2(TextLineReader& in);
Content parse_msh4(TextLineReader& in);

} // namespace sinew::gmsh
