#include "sinew/mesh/read_mesh.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/gmsh_reader.hpp"
#include "sinew/mesh/obj_reader.hpp"
#include "sinew/mesh/tetgen_reader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace sinew {

Mesh read_mesh(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".node" || extension == ".ele")
        return read_tetgen(path);
    if (extension == ".msh")
        return read_gmsh(path);
    if (extension == ".obj")
        return read_obj(path);
    const std::string found = extension.empty() ? "no extension" : "extension '" + extension + "'";
    throw InputError(path + ": unknown mesh format (" + found +
                     "); sinew reads TetGen .node/.ele, Gmsh .msh (2.2, 4.1 ASCII) and Wavefront .obj");
}

} // namespace sinew
