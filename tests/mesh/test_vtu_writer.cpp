#include "sinew/mesh/box_tets.hpp"
#include "sinew/mesh/rectangle_triangles.hpp"
#include "sinew/mesh/vtu_writer.hpp"

#include "mesh/mesh_test_support.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

using namespace sinew;
using sinew::test::require_input_error;
using sinew::test::ScratchDirectory;

namespace {

struct DataArray {
    std::string name;  ///< empty for the Points array
    std::string parent;
    int components = 1;
    std::vector<double> values;
};

/// What a VTU file holds, read back with a small XML scanner that also
/// checks the file is well formed: one root, every tag closed in order.
struct VtuContent {
    std::string root;
    int points = -1;
    int cells = -1;
    std::vector<DataArray> arrays;

    const DataArray& array(const std::string& name, const std::string& parent) const
    {
        for (const DataArray& a : arrays)
            if (a.name == name && a.parent == parent)
                return a;
        FAIL("no DataArray '" << name << "' in " << parent);
        return arrays.front();
    }
};

std::string attribute(const std::string& tag, const std::string& name)
{
    const std::string key = " " + name + "=\"";
    const auto start = tag.find(key);
    if (start == std::string::npos)
        return {};
    const auto begin = start + key.size();
    return tag.substr(begin, tag.find('"', begin) - begin);
}

VtuContent read_vtu(const std::string& path)
{
    std::ifstream in(path);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    REQUIRE(text.rfind("<?xml version=\"1.0\"?>", 0) == 0);
    VtuContent content;
    std::vector<std::string> open;
    std::size_t at = 0;
    int roots = 0;
    while ((at = text.find('<', at)) != std::string::npos) {
        const auto end = text.find('>', at);
        REQUIRE(end != std::string::npos);
        const std::string tag = text.substr(at + 1, end - at - 1);
        if (tag[0] == '?') {
            at = end;
            continue;
        }
        if (tag[0] == '/') {
            REQUIRE(!open.empty());
            CHECK(open.back() == tag.substr(1));
            open.pop_back();
            at = end;
            continue;
        }
        const std::string name = tag.substr(0, tag.find(' '));
        if (open.empty())
            ++roots;
        if (name == "VTKFile")
            content.root = attribute(tag, "type");
        if (name == "Piece") {
            content.points = std::stoi(attribute(tag, "NumberOfPoints"));
            content.cells = std::stoi(attribute(tag, "NumberOfCells"));
        }
        if (name == "DataArray") {
            DataArray array;
            array.name = attribute(tag, "Name");
            array.parent = open.back();
            const std::string components = attribute(tag, "NumberOfComponents");
            array.components = components.empty() ? 1 : std::stoi(components);
            std::istringstream values(text.substr(end + 1, text.find('<', end) - end - 1));
            for (double value; values >> value;)
                array.values.push_back(value);
            content.arrays.push_back(array);
        }
        open.push_back(name);
        at = end;
    }
    CHECK(open.empty());
    CHECK(roots == 1);
    return content;
}

/// Column-major values of a components × count matrix, as the file lists them.
std::vector<double> listed(const Eigen::MatrixXd& values)
{
    return std::vector<double>(values.data(), values.data() + values.size());
}

} // namespace

TEST_CASE("VTU writer: a tet mesh with point and cell data reads back exactly", "[mesh][vtu]")
{
    ScratchDirectory dir;
    const Mesh mesh = box_tets(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 1, 1), 2, 1, 1);
    Eigen::MatrixXd displacement = Eigen::MatrixXd::Random(3, mesh.num_nodes()) / 3.0;
    const Eigen::MatrixXd positions = mesh.nodes + displacement;
    Eigen::MatrixXd fixed = Eigen::MatrixXd::Zero(1, mesh.num_nodes());
    fixed(0, 0) = 1.0;
    Eigen::MatrixXd group = Eigen::MatrixXd::Zero(1, mesh.num_elements());
    Eigen::MatrixXd fiber = Eigen::MatrixXd::Zero(3, mesh.num_elements());
    fiber.row(0).setOnes();
    const Eigen::MatrixXd invariant = Eigen::MatrixXd::Random(1, mesh.num_elements()) * 1e5;
    const std::string path = dir.path("box.vtu");
    write_vtu(path, mesh, positions, {{"displacement", displacement}, {"fixed", fixed}},
              {{"group", group}, {"fiber direction", fiber}, {"stress <I1 & \"J\">", invariant}});

    const VtuContent vtu = read_vtu(path);
    CHECK(vtu.root == "UnstructuredGrid");
    CHECK(vtu.points == mesh.num_nodes());
    CHECK(vtu.cells == mesh.num_elements());
    CHECK(vtu.array("", "Points").components == 3);
    CHECK(vtu.array("", "Points").values == listed(positions));
    CHECK(vtu.array("displacement", "PointData").components == 3);
    CHECK(vtu.array("displacement", "PointData").values == listed(displacement));
    CHECK(vtu.array("fixed", "PointData").values == listed(fixed));
    CHECK(vtu.array("fiber direction", "CellData").values == listed(fiber));
    CHECK(vtu.array("stress &lt;I1 &amp; &quot;J&quot;&gt;", "CellData").values == listed(invariant));
    const Eigen::MatrixXd connectivity = mesh.elements.cast<double>();
    CHECK(vtu.array("connectivity", "Cells").values == listed(connectivity));
    std::vector<double> offsets;
    for (int e = 1; e <= mesh.num_elements(); ++e)
        offsets.push_back(4.0 * e);
    CHECK(vtu.array("offsets", "Cells").values == offsets);
    CHECK(vtu.array("types", "Cells").values == std::vector<double>(mesh.num_elements(), 10.0));

    // An independent XML parser (Debian's python3, installed by setup.sh)
    // must read the file as a VTKFile document.
    const std::string parse = "/usr/bin/python3 -c \"import sys, xml.dom.minidom as m; d = m.parse(sys.argv[1]); "
                              "sys.exit(0 if d.documentElement.tagName == 'VTKFile' else 1)\" '" +
                              path + "'";
    CHECK(std::system(parse.c_str()) == 0);
}

TEST_CASE("VTU writer: 2D meshes get z = 0 and 2-component vectors a zero third component", "[mesh][vtu]")
{
    ScratchDirectory dir;
    const Mesh mesh = rectangle_triangles(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 2), 2, 3);
    const Eigen::MatrixXd displacement = Eigen::MatrixXd::Random(2, mesh.num_nodes());
    const std::string path = dir.path("plane.vtu");
    write_vtu(path, mesh, mesh.nodes, {{"displacement", displacement}});

    const VtuContent vtu = read_vtu(path);
    Eigen::MatrixXd points = Eigen::MatrixXd::Zero(3, mesh.num_nodes());
    points.topRows(2) = mesh.nodes;
    CHECK(vtu.array("", "Points").values == listed(points));
    Eigen::MatrixXd padded = Eigen::MatrixXd::Zero(3, mesh.num_nodes());
    padded.topRows(2) = displacement;
    CHECK(vtu.array("displacement", "PointData").components == 3);
    CHECK(vtu.array("displacement", "PointData").values == listed(padded));
    CHECK(vtu.array("types", "Cells").values == std::vector<double>(mesh.num_elements(), 5.0));
    CHECK(vtu.array("offsets", "Cells").values.back() == 3.0 * mesh.num_elements());
}

TEST_CASE("VTU writer: wrong shapes are the caller's bug, an unwritable path is bad input", "[mesh][vtu][bad_input]")
{
    ScratchDirectory dir;
    const Mesh mesh = box_tets(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 1, 1, 1);
    const std::string path = dir.path("box.vtu");
    CHECK_THROWS_AS(write_vtu(path, mesh, Eigen::MatrixXd::Zero(2, mesh.num_nodes())), std::invalid_argument);
    CHECK_THROWS_AS(write_vtu(path, mesh, mesh.nodes, {{"u", Eigen::MatrixXd::Zero(3, 2)}}), std::invalid_argument);
    CHECK_THROWS_AS(write_vtu(path, mesh, mesh.nodes, {}, {{"s", Eigen::MatrixXd::Zero(4, mesh.num_elements())}}),
                    std::invalid_argument);
    CHECK_THROWS_AS(write_vtu(path, mesh, mesh.nodes, {{"", Eigen::MatrixXd::Zero(1, mesh.num_nodes())}}),
                    std::invalid_argument);
    const std::string unwritable = dir.path("no/such/folder/box.vtu");
    require_input_error([&] { write_vtu(unwritable, mesh, mesh.nodes); }, {unwritable, "cannot write file"});
}

TEST_CASE("VTU writer: the binary encoding holds exactly the values of the ASCII one", "[mesh][vtu]")
{
    ScratchDirectory dir;
    const Mesh mesh = box_tets(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3), 2, 1, 2);
    const Eigen::MatrixXd displacement = Eigen::MatrixXd::Random(3, mesh.num_nodes());
    const Eigen::MatrixXd velocity = Eigen::MatrixXd::Random(2, mesh.num_nodes());  // padded to 3
    const Eigen::MatrixXd stress = Eigen::MatrixXd::Random(1, mesh.num_elements());
    const std::string ascii = dir.path("ascii.vtu"), binary = dir.path("binary.vtu");
    write_vtu(ascii, mesh, mesh.nodes + displacement, {{"displacement", displacement}, {"velocity", velocity}},
              {{"stress", stress}}, VtuEncoding::ascii);
    write_vtu(binary, mesh, mesh.nodes + displacement, {{"displacement", displacement}, {"velocity", velocity}},
              {{"stress", stress}}, VtuEncoding::binary);
    // Python's XML, base64 and struct decode the binary file independently:
    // every array (Float64, Int64, UInt8) must equal the ASCII file's.
    const std::string script = R"(
import base64, struct, sys, xml.dom.minidom as m
sizes = {'Float64': ('d', 8), 'Int64': ('q', 8), 'UInt8': ('B', 1)}
def arrays(path):
    out = {}
    for a in m.parse(path).getElementsByTagName('DataArray'):
        text = a.firstChild.data.strip() if a.firstChild else ''
        if a.getAttribute('format') == 'binary':
            raw = base64.b64decode(text)
            n = struct.unpack('<I', raw[:4])[0]
            code, size = sizes[a.getAttribute('type')]
            assert len(raw) == 4 + n, (len(raw), n)
            values = list(struct.unpack('<%d%s' % (n // size, code), raw[4:]))
        else:
            values = [float(v) for v in text.split()]
        out[a.getAttribute('Name') + '/' + a.parentNode.tagName] = values
    return out
a, b = arrays(sys.argv[1]), arrays(sys.argv[2])
sys.exit(0 if a == b and len(a) == 7 else 1)
)";
    const std::string script_path = dir.path("compare.py");
    std::ofstream(script_path) << script;
    const std::string command = "/usr/bin/python3 '" + script_path + "' '" + ascii + "' '" + binary + "'";
    CHECK(std::system(command.c_str()) == 0);
    // The binary file is the smaller one.
    CHECK(std::filesystem::file_size(binary) < std::filesystem::file_size(ascii));
}
