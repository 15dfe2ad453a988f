#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/problems/quasistatic/node_selection.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace sinew {
namespace {

NodeSelection node_selection(const JsonCursor& s, int dimension)
{
    s.expect_object({"all", "nodes", "box", "plane", "half_space", "group", "node_set"});
    if (s.keys().size() != 1)
        s.fail("expected exactly one of all, nodes, box, plane, half_space, group, node_set");
    if (auto all = s.find("all")) {
        if (!all->boolean())
            all->fail("must be true");
        return AllNodes{};
    }
    if (auto list = s.find("nodes")) {
        NodeList out;
        for (size_t i = 0; i < list->size(); ++i)
            out.nodes.push_back((*list)[i].integer_in(0, std::numeric_limits<int>::max()));
        return out;
    }
    if (auto box = s.find("box")) {
        box->expect_object({"lower", "upper"});
        return NodesInBox{box->at("lower").vector(dimension), box->at("upper").vector(dimension)};
    }
    const bool on_plane = s.has("plane");
    if (on_plane || s.has("half_space")) {
        const JsonCursor p = s.at(on_plane ? "plane" : "half_space");
        p.expect_object({"point", "normal"});
        const Eigen::VectorXd point = p.at("point").vector(dimension), normal = p.at("normal").vector(dimension);
        if (on_plane)
            return NodesOnPlane{point, normal};
        return NodesInHalfSpace{point, normal};
    }
    if (auto set = s.find("node_set"))
        return NodesOfSet{set->string()};
    return NodesOfGroup{s.at("group").string()};
}

} // namespace

std::string resolve_path(const std::string& path, const std::string& base_folder)
{
    const std::filesystem::path p(path);
    if (p.is_absolute() || base_folder.empty())
        return path;
    return (std::filesystem::path(base_folder) / p).string();
}

std::vector<int> selected_nodes(const JsonCursor& s, const Mesh& mesh, double tolerance)
{
    const NodeSelection selection = node_selection(s, static_cast<int>(mesh.nodes.rows()));
    return at_place(s, [&] { return select_nodes(mesh, selection, tolerance); });
}

ParameterText parameter_text(const JsonCursor& p)
{
    ParameterText text;
    for (const std::string& key : p.keys()) {
        const JsonCursor value = p.at(key);
        text[key] = value.is_string() ? value.string() : value.number_text();
    }
    return text;
}

FaceShape face_shape(const JsonCursor& o)
{
    FaceShape shape;
    if (auto t = o.find("target_tets"))
        shape.target_tets = t->integer_in(1000, 2000000);
    if (auto g = o.find("skull_gap"))
        shape.skull_gap = g->number_in(0.0, shape.thickness);
    return shape;
}

int group_index(const JsonCursor& where, const Mesh& mesh, const std::string& name)
{
    const auto found = std::find(mesh.group_names.begin(), mesh.group_names.end(), name);
    if (found == mesh.group_names.end()) {
        std::string names;
        for (const auto& g : mesh.group_names)
            names += (names.empty() ? "" : ", ") + g;
        where.fail("the mesh has no group '" + name + "'; its groups: " + names);
    }
    return static_cast<int>(found - mesh.group_names.begin());
}

KeyframeCurve keyframes(const JsonCursor& list)
{
    if (list.size() == 0)
        list.fail("expected at least one keyframe [time, value]");
    std::vector<KeyframeCurve::Keyframe> keys;
    for (size_t k = 0; k < list.size(); ++k) {
        const Eigen::VectorXd pair = list[k].vector(2);
        if (k > 0 && !(pair[0] > keys.back().time))
            list[k].fail("time " + format_number(pair[0]) + " is not after the previous keyframe's " +
                         format_number(keys.back().time) + " (keyframes must be in increasing time)");
        keys.push_back({pair[0], pair[1]});
    }
    return KeyframeCurve(std::move(keys));
}

/// A prescribed rotation turns by at most this many degrees (100 turns).
constexpr double kMaxTurnDegrees = 36000.0;

PrescribedMotion prescribed_motion(const JsonCursor& b, int dimension)
{
    PrescribedMotion out;
    out.map = Eigen::MatrixXd::Identity(dimension, dimension);
    out.translation = Eigen::VectorXd::Zero(dimension);
    out.center = Eigen::VectorXd::Zero(dimension);
    if (b.has("rotation") && b.has("map"))
        b.fail("give either rotation or map, not both");
    if (auto r = b.find("rotation")) {
        if (dimension == 3)
            r->expect_object({"axis", "angle_deg", "center"});
        else
            r->expect_object({"angle_deg", "center"});
        out.rotation = true;
        out.angle = r->at("angle_deg").number_in(-kMaxTurnDegrees, kMaxTurnDegrees) * (M_PI / 180.0);
        if (dimension == 3) {
            const Eigen::Vector3d axis = r->at("axis").vector(3);
            if (!(axis.norm() > 0.0))
                r->at("axis").fail("axis must not be zero");
            out.axis = axis.normalized();
        }
        if (auto c = r->find("center"))
            out.center = c->vector(dimension);
    }
    if (auto m = b.find("map"))
        out.map = m->matrix(dimension, dimension);
    if (auto t = b.find("translation"))
        out.translation = t->vector(dimension);
    return out;
}

std::string read_choice(const JsonCursor& v, std::initializer_list<const char*> valid)
{
    const std::string text = v.string();
    std::string list;
    for (const char* option : valid) {
        if (text == option)
            return text;
        list += (list.empty() ? "" : ", ") + std::string(option);
    }
    v.fail("unknown value '" + text + "'; valid: " + list);
}

int mpm_material_index(const JsonCursor& name, const std::vector<std::string>& materials)
{
    for (std::size_t k = 0; k < materials.size(); ++k)
        if (materials[k] == name.string())
            return static_cast<int>(k);
    std::string list;
    for (const std::string& m : materials)
        list += (list.empty() ? "" : ", ") + m;
    name.fail("no mpm material called '" + name.string() + "'; materials: " + list);
}

} // namespace sinew
