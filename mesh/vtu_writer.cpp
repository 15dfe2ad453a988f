#include "sinew/mesh/vtu_writer.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/vtk_xml.hpp"

#include <cstdint>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <vector>

namespace sinew {
namespace {

using namespace vtk_xml;

constexpr int kVtkTriangle = 5;
constexpr int kVtkTetra = 10;

} // namespace

void write_vtu(const std::string& path, const Mesh& mesh, const Eigen::MatrixXd& positions,
               const VtuArrays& point_data, const VtuArrays& cell_data, VtuEncoding encoding)
{
    const int dimension = space_dimension(mesh.kind);
    if (positions.rows() != dimension || positions.cols() != mesh.num_nodes())
        throw std::invalid_argument("write_vtu: positions are " + shape(positions) + ", expected " +
                                    std::to_string(dimension) + "x" + std::to_string(mesh.num_nodes()));
    if (mesh.elements.rows() != nodes_per_element(mesh.kind))
        throw std::invalid_argument("write_vtu: elements have " + std::to_string(mesh.elements.rows()) +
                                    " rows, a " + to_string(mesh.kind) + " has " +
                                    std::to_string(nodes_per_element(mesh.kind)) + " nodes");
    check_arrays("write_vtu", point_data, mesh.num_nodes(), "point");
    check_arrays("write_vtu", cell_data, mesh.num_elements(), "cell");

    std::ofstream out(path);
    if (!out)
        throw InputError(path + ": cannot write file");
    out.precision(std::numeric_limits<double>::max_digits10);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << mesh.num_nodes() << "\" NumberOfCells=\"" << mesh.num_elements()
        << "\">\n";
    DataArrayWriter writer(out, encoding);
    write_data_arrays(writer, out, point_data, "PointData");
    write_data_arrays(writer, out, cell_data, "CellData");

    out << "      <Points>\n";
    Eigen::MatrixXd points = Eigen::MatrixXd::Zero(3, positions.cols());
    points.topRows(dimension) = positions;
    writer.float64("", points);
    out << "      </Points>\n";

    const int corners = nodes_per_element(mesh.kind);
    const std::uint8_t cell_type = mesh.kind == ElementKind::tetrahedron ? kVtkTetra : kVtkTriangle;
    std::vector<std::int64_t> connectivity, offsets;
    for (int e = 0; e < mesh.num_elements(); ++e) {
        for (int k = 0; k < corners; ++k)
            connectivity.push_back(mesh.elements(k, e));
        offsets.push_back(static_cast<std::int64_t>(e + 1) * corners);
    }
    out << "      <Cells>\n";
    writer.integers("Int64", "connectivity", connectivity, static_cast<size_t>(corners));
    writer.integers("Int64", "offsets", offsets, 1);
    writer.integers("UInt8", "types", std::vector<std::uint8_t>(static_cast<size_t>(mesh.num_elements()), cell_type), 1);
    out << "      </Cells>\n"
        << "    </Piece>\n"
        << "  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
    out.close();
    if (!out)
        throw InputError(path + ": writing the file failed");
}

} // namespace sinew
