#include "sinew/mesh/vtu_writer.hpp"

#include "sinew/core/input_error.hpp"

#include <fstream>
#include <limits>
#include <stdexcept>

namespace sinew {
namespace {

constexpr int kVtkTriangle = 5;
constexpr int kVtkTetra = 10;

std::string shape(const Eigen::MatrixXd& values)
{
    return std::to_string(values.rows()) + "x" + std::to_string(values.cols());
}

void check_arrays(const VtuArrays& arrays, Eigen::Index count, const std::string& what)
{
    for (const auto& [name, values] : arrays) {
        if (name.empty())
            throw std::invalid_argument("write_vtu: a " + what + " array has an empty name");
        if (values.rows() < 1 || values.rows() > 3 || values.cols() != count)
            throw std::invalid_argument("write_vtu: " + what + " array '" + name + "' is " + shape(values) +
                                        ", expected 1, 2 or 3 components x " + std::to_string(count));
    }
}

std::string xml_escaped(const std::string& text)
{
    std::string escaped;
    for (char c : text) {
        switch (c) {
        case '&': escaped += "&amp;"; break;
        case '<': escaped += "&lt;"; break;
        case '>': escaped += "&gt;"; break;
        case '"': escaped += "&quot;"; break;
        case '\'': escaped += "&apos;"; break;
        default: escaped += c;
        }
    }
    return escaped;
}

/// Writes columns of `values` one per line, padding 2-component columns with
/// a zero third component.
void write_columns(std::ofstream& out, const Eigen::MatrixXd& values)
{
    const bool pad = values.rows() == 2;
    for (Eigen::Index j = 0; j < values.cols(); ++j) {
        for (Eigen::Index i = 0; i < values.rows(); ++i)
            out << (i > 0 ? " " : "") << values(i, j);
        out << (pad ? " 0\n" : "\n");
    }
}

void write_data_arrays(std::ofstream& out, const VtuArrays& arrays, const std::string& section)
{
    if (arrays.empty())
        return;
    out << "      <" << section << ">\n";
    for (const auto& [name, values] : arrays) {
        const Eigen::Index components = values.rows() == 2 ? 3 : values.rows();
        out << "        <DataArray type=\"Float64\" Name=\"" << xml_escaped(name) << "\" NumberOfComponents=\""
            << components << "\" format=\"ascii\">\n";
        write_columns(out, values);
        out << "        </DataArray>\n";
    }
    out << "      </" << section << ">\n";
}

} // namespace

void write_vtu(const std::string& path, const Mesh& mesh, const Eigen::MatrixXd& positions,
               const VtuArrays& point_data, const VtuArrays& cell_data)
{
    const int dimension = space_dimension(mesh.kind);
    if (positions.rows() != dimension || positions.cols() != mesh.num_nodes())
        throw std::invalid_argument("write_vtu: positions are " + shape(positions) + ", expected " +
                                    std::to_string(dimension) + "x" + std::to_string(mesh.num_nodes()));
    if (mesh.elements.rows() != nodes_per_element(mesh.kind))
        throw std::invalid_argument("write_vtu: elements have " + std::to_string(mesh.elements.rows()) +
                                    " rows, a " + to_string(mesh.kind) + " has " +
                                    std::to_string(nodes_per_element(mesh.kind)) + " nodes");
    check_arrays(point_data, mesh.num_nodes(), "point");
    check_arrays(cell_data, mesh.num_elements(), "cell");

    std::ofstream out(path);
    if (!out)
        throw InputError(path + ": cannot write file");
    out.precision(std::numeric_limits<double>::max_digits10);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << mesh.num_nodes() << "\" NumberOfCells=\"" << mesh.num_elements()
        << "\">\n";
    write_data_arrays(out, point_data, "PointData");
    write_data_arrays(out, cell_data, "CellData");

    out << "      <Points>\n"
        << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    write_columns(out, positions);
    out << "        </DataArray>\n"
        << "      </Points>\n";

    const int corners = nodes_per_element(mesh.kind);
    const int cell_type = mesh.kind == ElementKind::tetrahedron ? kVtkTetra : kVtkTriangle;
    out << "      <Cells>\n"
        << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (int e = 0; e < mesh.num_elements(); ++e) {
        for (int k = 0; k < corners; ++k)
            out << (k > 0 ? " " : "") << mesh.elements(k, e);
        out << "\n";
    }
    out << "        </DataArray>\n"
        << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (int e = 0; e < mesh.num_elements(); ++e)
        out << static_cast<long long>(e + 1) * corners << "\n";
    out << "        </DataArray>\n"
        << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (int e = 0; e < mesh.num_elements(); ++e)
        out << cell_type << "\n";
    out << "        </DataArray>\n"
        << "      </Cells>\n"
        << "    </Piece>\n"
        << "  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
    out.close();
    if (!out)
        throw InputError(path + ": writing the file failed");
}

} // namespace sinew
