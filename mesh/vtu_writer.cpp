#include "sinew/mesh/vtu_writer.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/base64.hpp"

#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

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

/// Emits DataArray elements in one encoding.
class DataArrayWriter {
public:
    DataArrayWriter(std::ofstream& out, VtuEncoding encoding) : out_(out), encoding_(encoding) {}

    /// A Float64 array of the columns of `values`, 2-component columns padded
    /// with a zero third component. `name` empty: no Name attribute.
    void float64(const std::string& name, const Eigen::MatrixXd& values)
    {
        const Eigen::Index components = values.rows() == 2 ? 3 : values.rows();
        std::vector<double> data;
        data.reserve(static_cast<size_t>(components * values.cols()));
        for (Eigen::Index j = 0; j < values.cols(); ++j)
            for (Eigen::Index i = 0; i < components; ++i)
                data.push_back(i < values.rows() ? values(i, j) : 0.0);
        write("Float64", name, components, data, values.cols() > 0 ? static_cast<size_t>(components) : 1);
    }

    /// An integer array of `type` Int64 or UInt8, `per_line` values a line in ASCII.
    template <typename Integer>
    void integers(const char* type, const std::string& name, const std::vector<Integer>& data, size_t per_line)
    {
        write(type, name, 1, data, per_line);
    }

private:
    template <typename Value>
    void write(const char* type, const std::string& name, Eigen::Index components, const std::vector<Value>& data,
               size_t per_line)
    {
        out_ << "        <DataArray type=\"" << type << "\"";
        if (!name.empty())
            out_ << " Name=\"" << xml_escaped(name) << "\"";
        if (components > 1 || std::is_same<Value, double>::value)
            out_ << " NumberOfComponents=\"" << components << "\"";
        out_ << " format=\"" << (encoding_ == VtuEncoding::ascii ? "ascii" : "binary") << "\">\n";
        if (encoding_ == VtuEncoding::ascii) {
            for (size_t k = 0; k < data.size(); ++k)
                out_ << (k % per_line == 0 ? "" : " ") << +data[k] << (k % per_line == per_line - 1 ? "\n" : "");
        } else {
            // base64 of (UInt32 byte count, the values), little-endian as the header says.
            const std::uint32_t bytes = static_cast<std::uint32_t>(data.size() * sizeof(Value));
            std::vector<unsigned char> block(sizeof bytes + bytes);
            std::memcpy(block.data(), &bytes, sizeof bytes);
            if (bytes > 0)
                std::memcpy(block.data() + sizeof bytes, data.data(), bytes);
            out_ << base64(block.data(), block.size()) << "\n";
        }
        out_ << "        </DataArray>\n";
    }

    std::ofstream& out_;
    VtuEncoding encoding_;
};

void write_data_arrays(DataArrayWriter& writer, std::ofstream& out, const VtuArrays& arrays, const std::string& section)
{
    if (arrays.empty())
        return;
    out << "      <" << section << ">\n";
    for (const auto& [name, values] : arrays)
        writer.float64(name, values);
    out << "      </" << section << ">\n";
}

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
