// The VTK UnstructuredGrid writer for axis-aligned cells (MPM's active grid):
// read back by Python's XML, base64 and struct (an independent reader),
// ASCII and binary, pixels in 2D and voxels in 3D.
#include "sinew/mesh/cell_vtu_writer.hpp"

#include "mesh/mesh_test_support.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

using namespace sinew;
using sinew::test::ScratchDirectory;

namespace {

/// Decodes every DataArray of a .vtu and checks it against the expected
/// values written beside it as text: points padded to 3D, the cells'
/// corners, offsets every 2^d corners, one cell type (8 or 11) per cell.
const char* kCheckScript = R"(
import base64, struct, sys, xml.dom.minidom as m
sizes = {'Float64': ('d', 8), 'Int64': ('q', 8), 'UInt8': ('B', 1)}
doc = m.parse(sys.argv[1])
assert doc.documentElement.getAttribute('type') == 'UnstructuredGrid'
piece = doc.getElementsByTagName('Piece')[0]
cells = int(piece.getAttribute('NumberOfCells'))
def values(a):
    text = a.firstChild.data.strip() if a.firstChild else ''
    if a.getAttribute('format') == 'binary':
        raw = base64.b64decode(text)
        count = struct.unpack('<I', raw[:4])[0]
        code, size = sizes[a.getAttribute('type')]
        assert len(raw) == 4 + count
        return list(struct.unpack('<%d%s' % (count // size, code), raw[4:]))
    return [float(v) for v in text.split()]
arrays = {}
for a in doc.getElementsByTagName('DataArray'):
    arrays[a.parentNode.tagName + '/' + a.getAttribute('Name')] = values(a)
expected = {}
for line in open(sys.argv[2]):
    key, *numbers = line.split()
    expected[key] = [float(v) for v in numbers]
corners, kind = int(sys.argv[3]), int(sys.argv[4])
assert arrays['Cells/offsets'] == [corners * (k + 1) for k in range(cells)], 'offsets'
assert arrays['Cells/types'] == [kind] * cells, 'types'
for key, numbers in expected.items():
    assert arrays[key] == numbers, key
assert len(arrays) == len(expected) + 2, sorted(arrays)
)";

template <int Dim>
void check_cell_vtu(VtuEncoding encoding)
{
    constexpr int kCorners = 1 << Dim;
    ScratchDirectory dir;
    // Two unit cells side by side along x: the nodes of a 3 × 2 (× 2) lattice.
    const int count = Dim == 2 ? 6 : 12;
    Eigen::MatrixXd points(Dim, count);
    for (int k = 0; k < count; ++k)
        for (int a = 0; a < Dim; ++a)
            points(a, k) = a == 0 ? k % 3 : (k / (a == 1 ? 3 : 6)) % 2;
    std::vector<std::array<int, kCorners>> cells(2);
    for (int cell = 0; cell < 2; ++cell)
        for (int corner = 0; corner < kCorners; ++corner)
            cells[static_cast<std::size_t>(cell)][static_cast<std::size_t>(corner)] =
                cell + (corner & 1) + 3 * ((corner >> 1) & 1) + 6 * ((corner >> 2) & 1);
    const Eigen::MatrixXd mass = Eigen::MatrixXd::Random(1, count);
    const std::string path = dir.path("grid.vtu");
    write_cell_vtu<Dim>(path, points, cells, {{"mass", mass}}, encoding);
    Eigen::MatrixXd padded = Eigen::MatrixXd::Zero(3, count);
    padded.topRows(Dim) = points;
    std::ofstream expected(dir.path("expected.txt"));
    expected.precision(17);
    expected << "Points/";
    for (Eigen::Index k = 0; k < padded.size(); ++k)
        expected << ' ' << padded.data()[k];
    expected << "\nPointData/mass";
    for (Eigen::Index k = 0; k < mass.size(); ++k)
        expected << ' ' << mass.data()[k];
    expected << "\nCells/connectivity";
    for (const auto& cell : cells)
        for (const int corner : cell)
            expected << ' ' << corner;
    expected << '\n';
    expected.close();
    std::ofstream(dir.path("check.py")) << kCheckScript;
    const std::string command = "/usr/bin/python3 '" + dir.path("check.py") + "' '" + path + "' '" +
                                dir.path("expected.txt") + "' " + std::to_string(kCorners) + " " +
                                (Dim == 2 ? "8" : "11");
    CHECK(std::system(command.c_str()) == 0);
}

} // namespace

TEST_CASE("cell VTU writer: pixels and voxels read back exactly, ASCII and binary", "[mesh][vtu]")
{
    for (const VtuEncoding encoding : {VtuEncoding::ascii, VtuEncoding::binary}) {
        CAPTURE(encoding == VtuEncoding::binary);
        check_cell_vtu<2>(encoding);
        check_cell_vtu<3>(encoding);
    }
}

TEST_CASE("cell VTU writer: wrong shapes and corners are the caller's bug, an unwritable path is bad input",
          "[mesh][vtu][bad_input]")
{
    ScratchDirectory dir;
    const Eigen::MatrixXd points = Eigen::MatrixXd::Zero(2, 4);
    const std::vector<std::array<int, 4>> square{{0, 1, 2, 3}};
    CHECK_THROWS_AS(write_cell_vtu<2>(dir.path("a.vtu"), Eigen::MatrixXd::Zero(3, 4), square), std::invalid_argument);
    CHECK_THROWS_AS(write_cell_vtu<2>(dir.path("a.vtu"), points, {{0, 1, 2, 4}}), std::invalid_argument);
    CHECK_THROWS_AS(write_cell_vtu<2>(dir.path("a.vtu"), points, square, {{"m", Eigen::MatrixXd::Zero(1, 3)}}),
                    std::invalid_argument);
    CHECK_THROWS_AS(write_cell_vtu<2>(dir.path("missing/a.vtu"), points, square), InputError);
}
