#include "sinew/mesh/mesh_source.hpp"

namespace sinew {
namespace {

std::string location(const std::string& name, const std::string& file, const std::vector<int>& lines,
                     const std::string& what, int index)
{
    const std::string item = what + " " + std::to_string(index);
    if (index >= 0 && index < static_cast<int>(lines.size()))
        return (file.empty() ? name : file) + ":" + std::to_string(lines[index]) + ": " + item;
    return name + ": " + item;
}

} // namespace

std::string MeshSource::node_location(int node) const
{
    return location(name, node_file, node_lines, "node", node);
}

std::string MeshSource::element_location(int element) const
{
    return location(name, element_file, element_lines, "element", element);
}

} // namespace sinew
