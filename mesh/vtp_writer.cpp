#include "sinew/mesh/vtp_writer.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/vtk_xml.hpp"

#include <cstdint>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <vector>

namespace sinew {

void write_vtp(const std::string& path, const Eigen::MatrixXd& points, const VtuArrays& point_data,
               VtuEncoding encoding)
{
    using namespace vtk_xml;
    if (points.rows() != 2 && points.rows() != 3)
        throw std::invalid_argument("write_vtp: points are " + shape(points) + ", expected 2 or 3 rows");
    check_arrays("write_vtp", point_data, points.cols(), "point");
    std::ofstream out(path);
    if (!out)
        throw InputError(path + ": cannot write file");
    out.precision(std::numeric_limits<double>::max_digits10);
    const Eigen::Index count = points.cols();
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <PolyData>\n"
        << "    <Piece NumberOfPoints=\"" << count << "\" NumberOfVerts=\"" << count
        << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
    DataArrayWriter writer(out, encoding);
    write_data_arrays(writer, out, point_data, "PointData");
    out << "      <Points>\n";
    Eigen::MatrixXd padded = Eigen::MatrixXd::Zero(3, count);
    padded.topRows(points.rows()) = points;
    writer.float64("", padded);
    out << "      </Points>\n";
    // One vertex cell per point: connectivity k, offset k + 1.
    std::vector<std::int64_t> connectivity(static_cast<std::size_t>(count)), offsets(static_cast<std::size_t>(count));
    for (Eigen::Index k = 0; k < count; ++k) {
        connectivity[static_cast<std::size_t>(k)] = k;
        offsets[static_cast<std::size_t>(k)] = k + 1;
    }
    out << "      <Verts>\n";
    writer.integers("Int64", "connectivity", connectivity, 1);
    writer.integers("Int64", "offsets", offsets, 1);
    out << "      </Verts>\n"
        << "    </Piece>\n"
        << "  </PolyData>\n"
        << "</VTKFile>\n";
    out.close();
    if (!out)
        throw InputError(path + ": writing the file failed");
}

} // namespace sinew
