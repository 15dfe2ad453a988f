// The VTK PolyData writer for particles: read back by Python's XML, base64
// and struct (an independent reader), ASCII and binary, 2D and 3D.
#include "sinew/mesh/vtp_writer.hpp"

#include "mesh/mesh_test_support.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

using namespace sinew;
using sinew::test::ScratchDirectory;

namespace {

/// Decodes every DataArray of a .vtp and checks it against the expected
/// values written beside it as text: points padded to 3D, one vertex cell
/// per point (connectivity k, offsets k + 1), the point data arrays.
const char* kCheckScript = R"(
import base64, struct, sys, xml.dom.minidom as m
sizes = {'Float64': ('d', 8), 'Int64': ('q', 8)}
doc = m.parse(sys.argv[1])
root = doc.documentElement
assert root.getAttribute('type') == 'PolyData'
piece = doc.getElementsByTagName('Piece')[0]
n = int(piece.getAttribute('NumberOfPoints'))
assert int(piece.getAttribute('NumberOfVerts')) == n
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
assert arrays['Verts/connectivity'] == list(range(n)), 'connectivity'
assert arrays['Verts/offsets'] == list(range(1, n + 1)), 'offsets'
for key, numbers in expected.items():
    assert arrays[key] == numbers, key
assert len(arrays) == len(expected) + 2, sorted(arrays)
)";

void check_vtp(int dimension, VtuEncoding encoding)
{
    ScratchDirectory dir;
    const int count = 7;
    const Eigen::MatrixXd points = Eigen::MatrixXd::Random(dimension, count);
    const Eigen::MatrixXd velocity = Eigen::MatrixXd::Random(dimension, count);
    const Eigen::MatrixXd J = Eigen::MatrixXd::Random(1, count);
    const std::string path = dir.path("particles.vtp");
    write_vtp(path, points, {{"velocity", velocity}, {"J", J}}, encoding);
    // The expected arrays, padded to 3 components as the writer pads them.
    auto padded = [&](const Eigen::MatrixXd& values) {
        Eigen::MatrixXd out = Eigen::MatrixXd::Zero(values.rows() == 1 ? 1 : 3, count);
        out.topRows(values.rows()) = values;
        return out;
    };
    std::ofstream expected(dir.path("expected.txt"));
    expected.precision(17);
    for (const auto& [key, values] : {std::pair<std::string, Eigen::MatrixXd>{"Points/", padded(points)},
                                      {"PointData/velocity", padded(velocity)},
                                      {"PointData/J", J}}) {
        expected << key;
        for (Eigen::Index k = 0; k < values.size(); ++k)
            expected << ' ' << values.data()[k];
        expected << '\n';
    }
    expected.close();
    std::ofstream(dir.path("check.py")) << kCheckScript;
    const std::string command = "/usr/bin/python3 '" + dir.path("check.py") + "' '" + path + "' '" +
                                dir.path("expected.txt") + "'";
    CHECK(std::system(command.c_str()) == 0);
}

} // namespace

TEST_CASE("VTP writer: particles read back exactly, 2D and 3D, ASCII and binary", "[mesh][vtp]")
{
    for (const int dimension : {2, 3})
        for (const VtuEncoding encoding : {VtuEncoding::ascii, VtuEncoding::binary}) {
            CAPTURE(dimension, encoding == VtuEncoding::binary);
            check_vtp(dimension, encoding);
        }
}

TEST_CASE("VTP writer: wrong shapes are the caller's bug, an unwritable path is bad input", "[mesh][vtp][bad_input]")
{
    ScratchDirectory dir;
    const Eigen::MatrixXd points = Eigen::MatrixXd::Zero(3, 4);
    CHECK_THROWS_AS(write_vtp(dir.path("a.vtp"), Eigen::MatrixXd::Zero(4, 4)), std::invalid_argument);
    CHECK_THROWS_AS(write_vtp(dir.path("a.vtp"), points, {{"J", Eigen::MatrixXd::Zero(1, 3)}}), std::invalid_argument);
    CHECK_THROWS_AS(write_vtp(dir.path("a.vtp"), points, {{"", Eigen::MatrixXd::Zero(1, 4)}}), std::invalid_argument);
    CHECK_THROWS_AS(write_vtp(dir.path("missing/a.vtp"), points), InputError);
}
