#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/mesh/box_tets.hpp"
#include "sinew/mesh/face_mesh.hpp"
#include "sinew/mesh/graded_axis.hpp"
#include "sinew/mesh/fusiform_muscle.hpp"
#include "sinew/mesh/mesh_validation.hpp"
#include "sinew/mesh/read_mesh.hpp"
#include "sinew/mesh/rectangle_triangles.hpp"
#include "sinew/mesh/tetrahedralize_surface.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace sinew {
namespace {

Eigen::Vector3i cell_counts(const JsonCursor& cells, int dimension, int& total)
{
    Eigen::Vector3i n = Eigen::Vector3i::Ones();
    if (cells.size() != static_cast<size_t>(dimension))
        cells.fail("expected " + std::to_string(dimension) + " cell counts");
    double product = 1.0;
    for (int k = 0; k < dimension; ++k) {
        n[k] = cells[static_cast<size_t>(k)].integer_in(1, 100000);
        product *= n[k];
    }
    if (product * (dimension == 3 ? 6.0 : 2.0) > kMaxGeneratedElements)
        cells.fail("more than 2e7 elements");
    total = static_cast<int>(product);
    return n;
}

/// A corner of a generator's extent: coordinates within ±kMaxCoordinate.
Eigen::VectorXd extent_corner(const JsonCursor& corner, int dimension)
{
    return corner.vector_in(dimension, -kMaxCoordinate, kMaxCoordinate);
}

/// A box's cells are halved at most this many times along each axis.
constexpr int kMaxHalvings = 6;

/// The axis with a node added in the middle of every cell, `times` times:
/// nested refinement, each mesh's nodes among the next one's.
std::vector<double> halved(std::vector<double> nodes, int times)
{
    for (int t = 0; t < times; ++t) {
        std::vector<double> finer{nodes.front()};
        for (size_t i = 1; i < nodes.size(); ++i) {
            finer.push_back(0.5 * (nodes[i - 1] + nodes[i]));
            finer.push_back(nodes[i]);
        }
        nodes = std::move(finer);
    }
    return nodes;
}

Mesh generated_mesh(const JsonCursor& m)
{
    const std::string generator = m.at("generator").string();
    int total = 0;
    if (generator == "box") {
        m.expect_object({"generator", "lower", "upper", "cells", "grading", "halvings"});
        const Eigen::Vector3i n = cell_counts(m.at("cells"), 3, total);
        const Eigen::Vector3d lower = extent_corner(m.at("lower"), 3), upper = extent_corner(m.at("upper"), 3);
        const int halvings = m.has("halvings") ? m.at("halvings").integer_in(0, kMaxHalvings) : 0;
        if (6.0 * total * std::pow(8.0, halvings) > kMaxGeneratedElements)
            m.at("halvings").fail("more than 2e7 elements");
        std::array<std::vector<double>, 3> axes;
        const JsonCursor where = m.has("grading") ? m.at("grading") : m;
        Eigen::Vector3d focus = lower;
        double ratio = 1.0;
        if (auto g = m.find("grading")) {
            g->expect_object({"focus", "ratio"});
            focus = g->at("focus").vector(3);
            ratio = g->at("ratio").number_in(1.0, kMaxGradingRatio);
        }
        return at_place(where, [&] {
            if (!m.has("grading") && halvings == 0)
                return box_tets(lower, upper, n[0], n[1], n[2]);
            for (int a = 0; a < 3; ++a)
                axes[a] = halved(graded_axis(lower[a], upper[a], n[a], focus[a], ratio), halvings);
            return box_tets(axes);
        });
    }
    if (generator == "rectangle" || generator == "sheet") {
        m.expect_object({"generator", "lower", "upper", "cells"});
        const Eigen::Vector3i n = cell_counts(m.at("cells"), 2, total);
        const Eigen::Vector2d lower = extent_corner(m.at("lower"), 2), upper = extent_corner(m.at("upper"), 2);
        return at_place(m, [&] {
            return generator == "rectangle" ? rectangle_triangles(lower, upper, n[0], n[1])
                                            : sheet_triangles(lower, upper, n[0], n[1]);
        });
    }
    if (generator == "fusiform-muscle") {
        m.expect_object({"generator", "length", "belly_radius", "tendon_radius", "tendon_length", "rings",
                         "belly_layers", "tendon_layers"});
        FusiformMuscleShape shape;
        auto read_length = [&](const char* key, double& value) {
            if (auto v = m.find(key))
                value = v->number_in(-kMaxCoordinate, kMaxCoordinate);  // the generator checks the sign
        };
        auto read_count = [&](const char* key, int& value) {
            if (auto v = m.find(key))
                value = v->integer_in(1, 1000);
        };
        read_length("length", shape.length);
        read_length("belly_radius", shape.belly_radius);
        read_length("tendon_radius", shape.tendon_radius);
        read_length("tendon_length", shape.tendon_length);
        read_count("rings", shape.rings);
        read_count("belly_layers", shape.belly_layers);
        read_count("tendon_layers", shape.tendon_layers);
        const double elements = 6.0 * shape.rings * shape.rings * 3.0 * (shape.belly_layers + 2.0 * shape.tendon_layers);
        if (elements > kMaxGeneratedElements)
            m.fail("more than 2e7 elements");
        return at_place(m, [&] { return fusiform_muscle(shape); });
    }
    if (generator == "face") {
        m.expect_object({"generator", "target_tets", "skull_gap"});
        const FaceShape shape = face_shape(m);
        return at_place(m, [&] { return generate_face(shape).mesh; });
    }
    m.at("generator").fail("unknown generator '" + generator +
                           "'; valid generators: box, rectangle, sheet, fusiform-muscle, face");
}

Mesh scene_mesh(const JsonCursor& m, const std::string& base_folder)
{
    if (m.has("file")) {
        m.expect_object({"file"});
        const std::string path = resolve_path(m.at("file").string(), base_folder);
        return at_place(m.at("file"), [&] { return read_mesh(path); });
    }
    if (m.has("tetrahedralize")) {
        m.expect_object({"tetrahedralize", "max_volume", "max_radius_edge_ratio"});
        TetrahedralizeOptions options;
        if (auto v = m.find("max_volume"))
            options.max_volume = v->number_in(0.0, HUGE_VAL);
        if (auto v = m.find("max_radius_edge_ratio"))
            options.max_radius_edge_ratio = v->number_in(0.0, HUGE_VAL);
        const std::string path = resolve_path(m.at("tetrahedralize").string(), base_folder);
        return at_place(m, [&] { return tetrahedralize_obj(path, options); });
    }
    if (m.has("generator"))
        return generated_mesh(m);
    m.expect_object({"file", "tetrahedralize", "generator"});
    m.fail("expected one of the keys file, tetrahedralize, generator");
}


/// "mesh": a file, a surface to tetrahedralize, or a generator.
class MeshPart final : public ScenePart {
public:
    std::string key() const override { return "mesh"; }
    std::string doc() const override { return "where the mesh comes from: a file, a surface to tetrahedralize, or a generator"; }
    std::string kind() const override { return "scene"; }
    bool required() const override { return true; }
    int stage() const override { return 10; }
    std::vector<SceneKey> keys() const override
    {
        return {{"file", "string", "", "", "a mesh file: TetGen .node/.ele, Gmsh .msh 2.2 or 4.1, OBJ, relative to the scene"},
                {"tetrahedralize", "string", "", "", "a closed OBJ surface, tetrahedralized by TetGen"},
                {"max_volume", "number", "(0, inf)", "", "tetrahedralize: the largest tet volume"},
                {"max_radius_edge_ratio", "number", "(0, inf)", "", "tetrahedralize: the quality bound"},
                {"generator", "string", "box | rectangle | sheet | fusiform-muscle | face", "", "a generated mesh"},
                {"lower", "vector", "", "", "box, rectangle, sheet: the lower corner"},
                {"upper", "vector", "", "", "box, rectangle, sheet: the upper corner"},
                {"cells", "integers", "[1, 100000] each", "", "box, rectangle, sheet: cells per axis"},
                {"grading", "object", "{focus, ratio}", "equal cells",
                 "box: cell widths grow by ratio ∈ [1, 2] per cell away from the point focus"},
                {"halvings", "integer", "[0, 6]", "0",
                 "box: every cell cut in two along each axis this many times (nested refinement)"},
                {"length", "number", "", "", "fusiform-muscle: length (m)"},
                {"belly_radius", "number", "", "", "fusiform-muscle: radius at the belly (m)"},
                {"tendon_radius", "number", "", "", "fusiform-muscle: radius of the tendons (m)"},
                {"tendon_length", "number", "", "", "fusiform-muscle: length of each tendon (m)"},
                {"rings", "integer", "[1, 1000]", "", "fusiform-muscle: rings of the cross-section"},
                {"belly_layers", "integer", "[1, 1000]", "", "fusiform-muscle: layers along the belly"},
                {"tendon_layers", "integer", "[1, 1000]", "", "fusiform-muscle: layers along each tendon"},
                {"target_tets", "integer", "[1000, 2000000]", "20000", "face: the tet count aimed at (within 25 %)"},
                {"skull_gap", "number", "[0, 0.015]", "0.0005",
                 "face: the skull's distance below the lips' and cheeks' inner surface (m), as its face-skull body's"}};
    }
    void read(const JsonCursor& value, SceneAssembly& assembly) const override
    {
        Scene& scene = assembly.scene;
        scene.mesh = scene_mesh(value, assembly.base_folder);
        const Eigen::VectorXd extent = scene.mesh.nodes.rowwise().maxCoeff() - scene.mesh.nodes.rowwise().minCoeff();
        scene.size = extent.norm();
        assembly.tolerance = 1e-9 * scene.size;
        assembly.mesh_place = value;
    }
};

const SceneRegistration<MeshPart> mesh_part;

} // namespace
} // namespace sinew
