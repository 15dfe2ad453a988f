#include "sinew/mesh/cell_vtu_writer.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/vtk_xml.hpp"

#include <cstdint>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace sinew {

template <int Dim>
void write_cell_vtu(const std::string& path, const Eigen::MatrixXd& points,
                    const std::vector<std::array<int, (1 << Dim)>>& cells, const VtuArrays& point_data,
                    VtuEncoding encoding)
{
    using namespace vtk_xml;
    constexpr int kCorners = 1 << Dim;
    constexpr std::uint8_t kCellType = Dim == 2 ? 8 : 11;  // VTK_PIXEL, VTK_VOXEL
    if (points.rows() != Dim)
        throw std::invalid_argument("write_cell_vtu: points are " + shape(points) + ", expected " +
                                    std::to_string(Dim) + " rows");
    check_arrays("write_cell_vtu", point_data, points.cols(), "point");
    std::vector<std::int64_t> connectivity, offsets;
    connectivity.reserve(cells.size() * kCorners);
    for (const auto& cell : cells) {
        for (const int corner : cell) {
            if (corner < 0 || corner >= points.cols())
                throw std::invalid_argument("write_cell_vtu: a cell's corner " + std::to_string(corner) +
                                            " is not one of the " + std::to_string(points.cols()) + " points");
            connectivity.push_back(corner);
        }
        offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    }
    std::ofstream out(path);
    if (!out)
        throw InputError(path + ": cannot write file");
    out.precision(std::numeric_limits<double>::max_digits10);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << points.cols() << "\" NumberOfCells=\"" << cells.size() << "\">\n";
    DataArrayWriter writer(out, encoding);
    write_data_arrays(writer, out, point_data, "PointData");
    out << "      <Points>\n";
    Eigen::MatrixXd padded = Eigen::MatrixXd::Zero(3, points.cols());
    padded.topRows(Dim) = points;
    writer.float64("", padded);
    out << "      </Points>\n"
        << "      <Cells>\n";
    writer.integers("Int64", "connectivity", connectivity, kCorners);
    writer.integers("Int64", "offsets", offsets, 1);
    writer.integers("UInt8", "types", std::vector<std::uint8_t>(cells.size(), kCellType), 1);
    out << "      </Cells>\n"
        << "    </Piece>\n"
        << "  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
    out.close();
    if (!out)
        throw InputError(path + ": writing the file failed");
}

template void write_cell_vtu<2>(const std::string&, const Eigen::MatrixXd&, const std::vector<std::array<int, 4>>&,
                                const VtuArrays&, VtuEncoding);
template void write_cell_vtu<3>(const std::string&, const Eigen::MatrixXd&, const std::vector<std::array<int, 8>>&,
                                const VtuArrays&, VtuEncoding);

} // namespace sinew
