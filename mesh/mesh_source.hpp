#pragma once
#include <string>
#include <utility>
#include <vector>

namespace sinew {

/// Where a mesh came from, for error messages: a name (a file path or a
/// generator) and, for a mesh read from files, the file and line of each node
/// and element, so a message can point at the line to fix.
struct MeshSource {
    MeshSource() = default;
    MeshSource(std::string source_name) : name(std::move(source_name)) {}

    std::string name;              ///< file path or generator name
    std::string node_file;         ///< file the nodes were read from (TetGen: the .node file)
    std::vector<int> node_lines;   ///< 1-based line of node i in node_file; empty when unknown
    std::string element_file;      ///< file the elements were read from
    std::vector<int> element_lines;  ///< 1-based line of element e in element_file; empty when unknown

    /// "file:line: node i" when node i's line is known, "name: node i" otherwise.
    std::string node_location(int node) const;
    /// "file:line: element e" when element e's line is known, "name: element e" otherwise.
    std::string element_location(int element) const;
};

} // namespace sinew
