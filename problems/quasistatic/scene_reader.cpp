#include "sinew/problems/quasistatic/scene_reader.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/energies/constraints/fiber_inextensibility.hpp"
#include "sinew/energies/constraints/thread_lengths.hpp"
#include "sinew/energies/constraints/weak_fiber_inextensibility.hpp"
#include "sinew/energies/potentials/element_model.hpp"
#include "sinew/energies/potentials/lumped_mass.hpp"
#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"
#include "sinew/mesh/box_tets.hpp"
#include "sinew/mesh/fusiform_muscle.hpp"
#include "sinew/mesh/helical_fibers.hpp"
#include "sinew/mesh/mesh_validation.hpp"
#include "sinew/mesh/read_mesh.hpp"
#include "sinew/mesh/rectangle_triangles.hpp"
#include "sinew/mesh/tetrahedralize_surface.hpp"
#include "sinew/problems/quasistatic/dynamics_section.hpp"
#include "sinew/problems/quasistatic/node_selection.hpp"
#include "sinew/problems/quasistatic/strict_json.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sinew {
namespace {

/// A prescribed rotation turns by at most this many degrees (100 turns).
constexpr double kMaxTurnDegrees = 36000.0;

/// Runs `work`, prefixing any InputError it throws with the cursor's place.
template <typename Work>
auto at_place(const JsonCursor& cursor, const Work& work) -> decltype(work())
{
    try {
        return work();
    } catch (const InputError& e) {
        throw InputError(cursor.where() + ": " + e.what());
    }
}

std::string resolve_path(const std::string& path, const std::string& base_folder)
{
    const std::filesystem::path p(path);
    if (p.is_absolute() || base_folder.empty())
        return path;
    return (std::filesystem::path(base_folder) / p).string();
}

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

Mesh generated_mesh(const JsonCursor& m)
{
    const std::string generator = m.at("generator").string();
    int total = 0;
    if (generator == "box") {
        m.expect_object({"generator", "lower", "upper", "cells"});
        const Eigen::Vector3i n = cell_counts(m.at("cells"), 3, total);
        const Eigen::Vector3d lower = extent_corner(m.at("lower"), 3), upper = extent_corner(m.at("upper"), 3);
        return at_place(m, [&] { return box_tets(lower, upper, n[0], n[1], n[2]); });
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
    m.at("generator").fail("unknown generator '" + generator +
                           "'; valid generators: box, rectangle, sheet, fusiform-muscle");
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

NodeSelection node_selection(const JsonCursor& s, int dimension)
{
    s.expect_object({"all", "nodes", "box", "plane", "half_space", "group"});
    if (s.keys().size() != 1)
        s.fail("expected exactly one of all, nodes, box, plane, half_space, group");
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
    return NodesOfGroup{s.at("group").string()};
}

std::vector<int> selected_nodes(const JsonCursor& s, const Scene& scene, double tolerance)
{
    const NodeSelection selection = node_selection(s, static_cast<int>(scene.mesh.nodes.rows()));
    return at_place(s, [&] { return select_nodes(scene.mesh, selection, tolerance); });
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

struct Material {
    ElementModel model;
    double density = 0.0;
    std::optional<Eigen::VectorXd> fiber;      ///< one fiber for the whole group,
    std::optional<JsonCursor> fiber_at;        ///< and where it is written
    std::optional<JsonCursor> fiber_list;      ///< a fiber per element of the group, in mesh order
    std::optional<JsonCursor> fiber_of_mesh;   ///< "mesh", said explicitly: the mesh must have a fiber field
    std::optional<HelixField> helix;           ///< a helical field, evaluated at each element's rest centroid
    double activation = 0.0;
    double damage = 0.0;
};

/// {"axis": [ax, ay, az], "point": [px, py, pz], "angle_deg": θ}: a helical
/// fiber field (mesh/helical_fibers.hpp), tets only.
HelixField helix_field(const JsonCursor& h, ElementKind kind)
{
    h.expect_object({"axis", "point", "angle_deg"});
    if (kind != ElementKind::tetrahedron)
        h.fail("a helical fiber field needs a tet mesh, this mesh has " + to_string(kind) +
               " elements (give the fiber as [a...] or per_element)");
    HelixField out;
    const Eigen::Vector3d axis = h.at("axis").vector(3);
    const double length = axis.stableNorm();  // no overflow or underflow on the way
    if (!(length > 0.0))
        h.at("axis").fail("axis must not be zero");
    out.axis = axis / length;
    out.point = h.at("point").vector_in(3, -kMaxCoordinate, kMaxCoordinate);
    out.angle = h.at("angle_deg").number_in(-90.0, 90.0) * (M_PI / 180.0);
    return out;
}

Material material(const JsonCursor& m, ElementKind kind)
{
    m.expect_object({"group", "model", "parameters", "density", "fiber", "activation", "damage"});
    Material out;
    const ParameterText parameters = m.has("parameters") ? parameter_text(m.at("parameters")) : ParameterText{};
    const std::string model = m.at("model").string();
    out.model = at_place(m, [&] { return parse_element_model(kind, model, parameters); });
    if (auto v = m.find("density"))
        out.density = v->number_in(0.0, HUGE_VAL);
    if (auto v = m.find("fiber")) {
        // [a…]: constant; {"per_element": [[a…], …]}: one per element of the
        // group; {"helix": {…}}: a helical field; "mesh": the generator's
        // fiber field (also the default).
        if (v->is_array()) {
            out.fiber = v->vector();
            out.fiber_at = v;
        } else if (v->is_object()) {
            v->expect_object({"per_element", "helix"});
            if (v->keys().size() != 1)
                v->fail("expected exactly one of per_element, helix");
            if (auto h = v->find("helix")) {
                out.helix = helix_field(*h, kind);
            } else {
                out.fiber_list = v->at("per_element");
                out.fiber_list->size();  // an array, or an error here
            }
        } else if (v->is_string() && v->string() == "mesh") {
            out.fiber_of_mesh = v;
        } else {
            v->fail("expected an array of numbers, {\"per_element\": [...]}, {\"helix\": {...}}, or \"mesh\"");
        }
    }
    if (auto v = m.find("activation"))
        out.activation = v->number_in(0.0, 1.0);
    if (auto v = m.find("damage"))
        out.damage = v->number_in(0.0, 1.0);
    return out;
}

/// One material per mesh group: a material with "group" takes that group,
/// one without takes every group no other material names.
std::vector<Material> group_materials(const JsonCursor& list, const Mesh& mesh)
{
    const size_t groups = mesh.group_names.size();
    std::vector<std::optional<Material>> assigned(groups);
    std::optional<Material> fallback;
    if (list.size() == 0)
        list.fail("expected at least one material");
    for (size_t i = 0; i < list.size(); ++i) {
        const JsonCursor m = list[i];
        Material made = material(m, mesh.kind);
        if (auto group = m.find("group")) {
            const std::string name = group->string();
            const auto found = std::find(mesh.group_names.begin(), mesh.group_names.end(), name);
            if (found == mesh.group_names.end()) {
                std::string names;
                for (const auto& g : mesh.group_names)
                    names += (names.empty() ? "" : ", ") + g;
                group->fail("the mesh has no group '" + name + "'; its groups: " + names);
            }
            auto& slot = assigned[static_cast<size_t>(found - mesh.group_names.begin())];
            if (slot)
                group->fail("group '" + name + "' has a material already");
            slot = std::move(made);
        } else {
            if (made.fiber_list && groups > 1)
                m.at("fiber").fail("per-element fibers need the material's \"group\" (the mesh has several)");
            if (fallback)
                m.fail("a second material without \"group\"; only one may apply to the remaining groups");
            fallback = std::move(made);
        }
    }
    std::vector<Material> out;
    for (size_t g = 0; g < groups; ++g) {
        if (!assigned[g] && !fallback)
            list.fail("group '" + mesh.group_names[g] + "' has no material");
        out.push_back(assigned[g] ? *assigned[g] : *fallback);
    }
    return out;
}

/// The index of the mesh group called `name`; an error at `where` listing the groups otherwise.
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

/// {"type": "fiber_inextensibility", "groups": [...]}: a₀ᵀCa₀ = 1 on every
/// element of the groups (all groups when absent), a₀ the elastic
/// potential's fiber of each element (seed 004 §4.1). With `weak`,
/// {"type": "weak_fiber_inextensibility", "groups", "cells": [n...]}: one
/// constraint Σ V_e(a₀ᵀC_e a₀ − 1) per cell of a coarse grid (seed 004 §4.2.2).
std::shared_ptr<ConstraintSet> fiber_constraints(const JsonCursor& c, const Scene& scene,
                                                 const std::vector<Material>& materials, bool weak)
{
    if (weak)
        c.expect_object({"type", "groups", "cells"});
    else
        c.expect_object({"type", "groups"});
    const Mesh& mesh = scene.mesh;
    std::vector<char> chosen(mesh.group_names.size(), c.has("groups") ? 0 : 1);
    if (auto groups = c.find("groups")) {
        if (groups->size() == 0)
            groups->fail("selects no group");
        for (size_t i = 0; i < groups->size(); ++i)
            chosen[static_cast<size_t>(group_index((*groups)[i], mesh, (*groups)[i].string()))] = 1;
    }
    for (size_t g = 0; g < chosen.size(); ++g) {
        const Material& m = materials[g];
        if (chosen[g] && !m.fiber && !m.fiber_list && !m.helix && mesh.element_fibers.size() == 0)
            c.fail("group '" + mesh.group_names[g] + "' has no fiber (give its material a \"fiber\")");
    }
    std::vector<int> elements;
    for (int e = 0; e < mesh.num_elements(); ++e)
        if (chosen[static_cast<size_t>(mesh.element_groups[static_cast<size_t>(e)])])
            elements.push_back(e);
    if (elements.empty())
        c.fail("selects no element");
    Eigen::MatrixXd fibers(material_dimension(mesh.kind), static_cast<Eigen::Index>(elements.size()));
    for (size_t k = 0; k < elements.size(); ++k)
        fibers.col(static_cast<Eigen::Index>(k)) = scene.elastic->fiber(elements[k]);
    if (!weak)
        return at_place(c, [&] { return std::make_shared<FiberInextensibility>(mesh, elements, fibers); });
    const JsonCursor cells = c.at("cells");
    const int dimension = static_cast<int>(mesh.nodes.rows());
    if (static_cast<int>(cells.size()) != dimension)
        cells.fail("expected " + std::to_string(dimension) + " cell counts, one per dimension");
    Eigen::VectorXi counts(dimension);
    for (int d = 0; d < dimension; ++d)
        counts[d] = cells[static_cast<size_t>(d)].integer_in(1, 10000);
    return at_place(c, [&] { return std::make_shared<WeakFiberInextensibility>(mesh, elements, fibers, counts); });
}

/// {"type": "threads", "polylines": [[node, node, ...], ...]}: inextensible
/// segments |x_j − x_i| = L_ij along each polyline.
std::shared_ptr<ConstraintSet> thread_constraints(const JsonCursor& c, const Mesh& mesh)
{
    c.expect_object({"type", "polylines"});
    const JsonCursor list = c.at("polylines");
    if (list.size() == 0)
        list.fail("selects no polyline");
    std::vector<std::vector<int>> polylines;
    for (size_t i = 0; i < list.size(); ++i) {
        const JsonCursor line = list[i];
        std::vector<int> nodes;
        for (size_t k = 0; k < line.size(); ++k)
            nodes.push_back(line[k].integer_in(0, mesh.num_nodes() - 1));
        polylines.push_back(std::move(nodes));
    }
    const int dimension = static_cast<int>(mesh.nodes.rows());
    const Eigen::VectorXd rest = Eigen::Map<const Eigen::VectorXd>(mesh.nodes.data(), mesh.nodes.size());
    return at_place(c, [&] { return std::make_shared<ThreadLengths>(mesh.num_nodes(), dimension, rest, polylines); });
}

/// The scene's "constraints" array: constraint sets beside the potentials.
std::vector<std::shared_ptr<ConstraintSet>> scene_constraints(const JsonCursor& list, const Scene& scene,
                                                              const std::vector<Material>& materials)
{
    std::vector<std::shared_ptr<ConstraintSet>> sets;
    for (size_t i = 0; i < list.size(); ++i) {
        const JsonCursor c = list[i];
        const std::string type = c.at("type").string();
        if (type == "fiber_inextensibility" || type == "weak_fiber_inextensibility")
            sets.push_back(fiber_constraints(c, scene, materials, type == "weak_fiber_inextensibility"));
        else if (type == "threads")
            sets.push_back(thread_constraints(c, scene.mesh));
        else
            c.at("type").fail("unknown constraint type '" + type +
                              "'; valid: fiber_inextensibility, weak_fiber_inextensibility, threads");
    }
    return sets;
}

/// A load step s moves a set by M(s) = I + s(M − I) (scene.hpp). det M(s) =
/// Π(1 + s μᵢ) over the eigenvalues μᵢ of M − I vanishes for some s ∈ (0, 1]
/// exactly when a real μᵢ ≤ −1, i.e. when M has a real eigenvalue λ ≤ 0: such
/// a map (singular, a reflection, a flattening) collapses the set on the way.
void require_blend_regular(const JsonCursor& where, const Eigen::MatrixXd& M)
{
    const double scale = M.cwiseAbs().maxCoeff();
    const Eigen::VectorXcd eigenvalues = M.eigenvalues();
    for (Eigen::Index i = 0; i < eigenvalues.size(); ++i) {
        const std::complex<double> lambda = eigenvalues[i];
        if (std::abs(lambda.imag()) <= 1e-12 * scale && lambda.real() <= 1e-12 * scale)
            where.fail("the map has the real eigenvalue " + format_number(lambda.real()) +
                       " <= 0: it is singular or reverses orientation, and the load steps I + s(M - I) "
                       "pass through a singular map");
    }
}

PrescribedMotion motion(const JsonCursor& b, int dimension)
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
    if (auto m = b.find("map")) {
        out.map = m->matrix(dimension, dimension);
        require_blend_regular(*m, out.map);
    }
    if (auto t = b.find("translation"))
        out.translation = t->vector(dimension);
    return out;
}

/// The "dynamics" object: the settings, the lumped masses (every density
/// must be > 0: a node without mass has no inertia) and the step's inertia
/// and Rayleigh damping terms, appended to the scene's potentials.
void add_dynamics(const JsonCursor& d, Scene& scene, const std::vector<double>& densities,
                  const JsonCursor& material_list, std::vector<std::shared_ptr<Potential>>& terms)
{
    const int dimension = static_cast<int>(scene.mesh.nodes.rows());
    scene.dynamics = read_dynamics(d, dimension);
    for (size_t g = 0; g < densities.size(); ++g)
        if (!(densities[g] > 0.0))
            material_list.fail("group '" + (g < scene.mesh.group_names.size() ? scene.mesh.group_names[g] : std::to_string(g)) +
                               "' has density 0; a scene with dynamics needs a density > 0 (mass) on every material");
    scene.node_masses = at_place(d, [&] { return lumped_masses(scene.mesh, densities); });
    const DynamicsSettings& settings = *scene.dynamics;
    const double largest_activation = scene.target_activations.size() > 0 ? scene.target_activations.maxCoeff() : 0.0;
    for (const KeyframeCurve::Keyframe& k : settings.load_factor.keyframes())
        if (largest_activation > 0.0 && (k.value < 0.0 || k.value * largest_activation > 1.0))
            d.at("load_curve").fail("the load factor " + format_number(k.value) +
                                    " takes an activation out of [0, 1] (largest activation " +
                                    format_number(largest_activation) + ")");
    scene.inertia = std::make_shared<InertiaPotential>("inertia", dimension, scene.node_masses);
    terms.push_back(scene.inertia);
    if (settings.mass_damping > 0.0) {
        scene.mass_damping = std::make_shared<InertiaPotential>("mass damping", dimension, scene.node_masses);
        terms.push_back(scene.mass_damping);
    }
    if (settings.stiffness_damping > 0.0) {
        scene.stiffness_damping = std::make_shared<StiffnessDampingPotential>(scene.elastic, settings.stiffness_damping);
        terms.push_back(scene.stiffness_damping);
    }
}

std::string read_text_file(const std::string& path)
{
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored))
        throw InputError(path + ": is a folder, not a scene file");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path + ": cannot read file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw InputError(path + ": read error");
    return text.str();
}

} // namespace

Scene parse_scene(const std::string& text, const std::string& document, const std::string& base_folder)
{
    const JsonDocument json = parse_json_text(text, document);
    const JsonCursor root(json);
    root.expect_object({"name", "description", "mesh", "materials", "gravity", "boundary", "loads", "obstacles",
                        "constraints", "dirichlet", "load_steps", "solver", "output", "dynamics"});
    Scene scene;
    scene.name = root.has("name") ? root.at("name").string()
                                  : std::filesystem::path(document).stem().string();
    if (auto d = root.find("description"))
        scene.description = d->string();

    scene.mesh = scene_mesh(root.at("mesh"), base_folder);
    const Mesh& mesh = scene.mesh;
    const int dimension = static_cast<int>(mesh.nodes.rows());
    const Eigen::VectorXd extent = mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff();
    scene.size = extent.norm();
    const double tolerance = 1e-9 * scene.size;

    // Materials (the elastic potential) and their per-element data.
    const JsonCursor material_list = root.at("materials");
    const std::vector<Material> materials = group_materials(material_list, mesh);
    std::vector<ElementModel> models;
    std::vector<double> densities;
    for (const Material& m : materials) {
        models.push_back(m.model);
        densities.push_back(m.density);
    }
    scene.elastic = at_place(root.at("mesh"), [&] { return std::make_shared<ElasticPotential>(mesh, models); });
    scene.target_activations.resize(mesh.num_elements());
    std::vector<size_t> rank_in_group(materials.size(), 0);
    std::vector<Eigen::MatrixXd> helical(materials.size());
    for (size_t g = 0; g < materials.size(); ++g)
        if (materials[g].helix)
            helical[g] = helical_fibers(mesh, *materials[g].helix);
    for (int e = 0; e < mesh.num_elements(); ++e) {
        const size_t group = static_cast<size_t>(mesh.element_groups[static_cast<size_t>(e)]);
        const Material& m = materials[group];
        const size_t rank = rank_in_group[group]++;
        if (m.fiber)
            at_place(*m.fiber_at, [&] { scene.elastic->set_fiber(e, *m.fiber); });
        if (m.helix)
            scene.elastic->set_fiber(e, helical[group].col(e));
        if (m.fiber_of_mesh && mesh.element_fibers.size() == 0)
            m.fiber_of_mesh->fail("the mesh has no fiber field (give the fiber as [a...] or per_element)");
        if (m.fiber_list) {
            if (rank >= m.fiber_list->size())
                m.fiber_list->fail("has " + std::to_string(m.fiber_list->size()) + " fibers, group '" +
                                   mesh.group_names[group] + "' more elements");
            const JsonCursor fiber = (*m.fiber_list)[rank];
            const Eigen::VectorXd a = fiber.vector();
            at_place(fiber, [&] { scene.elastic->set_fiber(e, a); });
        }
        scene.elastic->set_damage(e, m.damage);
        scene.target_activations[e] = m.activation;
    }
    for (size_t g = 0; g < materials.size(); ++g)
        if (materials[g].fiber_list && materials[g].fiber_list->size() != rank_in_group[g])
            materials[g].fiber_list->fail("has " + std::to_string(materials[g].fiber_list->size()) +
                                          " fibers, group '" + mesh.group_names[g] + "' " +
                                          std::to_string(rank_in_group[g]) + " elements");
    std::vector<std::shared_ptr<Potential>> terms{scene.elastic};

    if (auto g = root.find("gravity")) {
        const Eigen::VectorXd gravity = g->vector(dimension);
        scene.gravity = at_place(*g, [&] {
            return std::make_shared<GravityPotential>(dimension, lumped_masses(mesh, densities), gravity);
        });
        terms.push_back(scene.gravity);
    }

    if (auto list = root.find("loads")) {
        std::vector<int> nodes;
        std::vector<Eigen::VectorXd> forces;
        for (size_t i = 0; i < list->size(); ++i) {
            const JsonCursor l = (*list)[i];
            l.expect_object({"select", "force_per_node", "total_force"});
            const std::vector<int> selected = selected_nodes(l.at("select"), scene, tolerance);
            if (l.has("force_per_node") == l.has("total_force"))
                l.fail("give exactly one of force_per_node, total_force");
            const bool per_node = l.has("force_per_node");
            Eigen::VectorXd f = l.at(per_node ? "force_per_node" : "total_force").vector(dimension);
            if (!per_node)
                f /= static_cast<double>(selected.size());
            for (int node : selected) {
                nodes.push_back(node);
                forces.push_back(f);
            }
        }
        Eigen::MatrixXd force_matrix(dimension, static_cast<Eigen::Index>(forces.size()));
        for (size_t k = 0; k < forces.size(); ++k)
            force_matrix.col(static_cast<Eigen::Index>(k)) = forces[k];
        scene.loads = std::make_shared<PointLoadPotential>(dimension, mesh.num_nodes(), nodes, force_matrix);
        terms.push_back(scene.loads);
    }

    if (auto list = root.find("obstacles")) {
        for (size_t i = 0; i < list->size(); ++i) {
            const JsonCursor o = (*list)[i];
            o.expect_object({"plane", "sphere", "stiffness", "select"});
            if (o.has("plane") == o.has("sphere"))
                o.fail("give exactly one of plane, sphere");
            AnalyticObstacle obstacle;
            if (auto p = o.find("plane")) {
                p->expect_object({"point", "normal"});
                const Eigen::VectorXd point = p->at("point").vector(dimension), normal = p->at("normal").vector(dimension);
                obstacle = PlaneObstacle{normal, normal.dot(point)};  // n·x ≥ n·p
            } else {
                const JsonCursor s = o.at("sphere");
                s.expect_object({"center", "radius"});
                obstacle = SphereObstacle{s.at("center").vector(dimension), s.at("radius").number()};
            }
            const double stiffness = o.at("stiffness").number();
            const std::vector<int> nodes = o.has("select") ? selected_nodes(o.at("select"), scene, tolerance)
                                                           : std::vector<int>{};
            terms.push_back(at_place(o, [&] {
                return std::make_shared<ObstaclePenaltyPotential>(dimension, mesh.num_nodes(), obstacle, stiffness,
                                                                  nodes);
            }));
        }
    }

    if (auto d = root.find("dynamics"))
        add_dynamics(*d, scene, densities, material_list, terms);

    std::vector<DirichletSet> sets;
    if (auto list = root.find("boundary")) {
        for (size_t i = 0; i < list->size(); ++i) {
            const JsonCursor b = (*list)[i];
            b.expect_object({"name", "select", "rotation", "map", "translation"});
            PrescribedMotion m = motion(b, dimension);
            DirichletSet set;
            set.name = b.has("name") ? b.at("name").string() : "boundary[" + std::to_string(i) + "]";
            set.nodes = selected_nodes(b.at("select"), scene, tolerance);
            set.map = m.map_at(1.0, dimension);
            set.translation = m.translation_at(1.0, dimension);
            sets.push_back(std::move(set));
            scene.motions.push_back(std::move(m));
        }
    }

    QuasistaticOptions options;
    options.name = scene.name;
    if (auto d = root.find("dirichlet")) {
        const std::string strategy = d->string();
        if (strategy == "eliminate")
            options.dirichlet = DirichletStrategy::eliminate;
        else if (strategy == "equality_constraints")
            options.dirichlet = DirichletStrategy::equality_constraints;
        else
            d->fail("unknown strategy '" + strategy + "'; valid: eliminate, equality_constraints");
    }
    if (auto list = root.find("constraints")) {
        scene.constraints = scene_constraints(*list, scene, materials);
        options.constraints = scene.constraints;
    }
    if (auto n = root.find("load_steps")) {
        scene.load_steps = n->integer_in(1, 100000);
        if (scene.dynamics)
            n->fail("a scene with dynamics is stepped in time; its load factor over time is dynamics.load_curve");
    }

    if (auto s = root.find("solver")) {
        s->expect_object({"name", "tolerance", "max_iterations", "options"});
        scene.solver.source = s->where();
        if (auto v = s->find("name"))
            scene.solver.name = v->string();
        if (auto v = s->find("tolerance"))
            scene.solver.tolerance = v->number_in(1e-300, HUGE_VAL);
        if (auto v = s->find("max_iterations"))
            scene.solver.max_iterations = v->integer_in(1, std::numeric_limits<int>::max());
        if (auto v = s->find("options"))
            scene.solver.options = parameter_text(*v);
    }
    if (auto o = root.find("output")) {
        o->expect_object({"folder", "vtu", "every"});
        if (auto v = o->find("every"))
            scene.output.every = v->integer_in(1, std::numeric_limits<int>::max());
        if (auto v = o->find("folder"))
            scene.output.folder = resolve_path(v->string(), base_folder);
        if (auto v = o->find("vtu")) {
            const std::string vtu = v->string();
            if (vtu == "none")
                scene.output.vtu = VtuOutput::none;
            else if (vtu == "final")
                scene.output.vtu = VtuOutput::final;
            else if (vtu == "every_step")
                scene.output.vtu = VtuOutput::every_step;
            else
                v->fail("unknown value '" + vtu + "'; valid: none, final, every_step");
        }
    }

    auto total = at_place(root, [&] { return std::make_shared<TotalPotential>(terms); });
    const JsonCursor where = root.has("boundary") ? root.at("boundary") : root;
    scene.problem = at_place(where, [&] {
        return std::make_unique<QuasistaticProblem>(mesh.nodes, total, sets, options);
    });
    scene.apply_load_factor(1.0);
    return scene;
}

std::string scene_description(const std::string& text)
{
    const JsonDocument json = parse_json_text(text, "scene");
    const auto found = json.root.find("description");
    return found != json.root.end() && found->is_string() ? found->get<std::string>() : std::string();
}

Scene read_scene_file(const std::string& path)
{
    const std::string text = read_text_file(path);
    return parse_scene(text, path, std::filesystem::path(path).parent_path().string());
}

} // namespace sinew
