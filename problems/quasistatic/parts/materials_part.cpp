#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/energies/potentials/element_model.hpp"
#include "sinew/mesh/helical_fibers.hpp"
#include "sinew/mesh/mesh_validation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace sinew {
namespace {

struct Material {
    ElementModel model;
    double density = 0.0;
    std::optional<Eigen::VectorXd> fiber;      ///< one fiber for the whole group,
    std::optional<JsonCursor> fiber_at;        ///< and where it is written
    std::optional<JsonCursor> fiber_list;      ///< a fiber per element of the group, in mesh order
    std::optional<JsonCursor> fiber_of_mesh;   ///< "mesh", said explicitly: the mesh must have a fiber field
    std::optional<HelixField> helix;           ///< a helical field, evaluated at each element's rest centroid
    double activation = 0.0;                   ///< at load factor 1,
    std::optional<KeyframeCurve> activation_curve;  ///< or α(t), given as keyframes
    std::optional<JsonCursor> activation_at;
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

Material material(const JsonCursor& m, ElementKind kind, const DeclaredKeys& declared)
{
    declared.expect_object(m, "[]");
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
            declared.expect_object(*v, "[].fiber");
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
    if (auto v = m.find("activation")) {
        out.activation_at = v;
        if (v->is_array()) {  // α(t): the keyframes are the activation itself
            out.activation_curve = keyframes(*v);
            out.activation = 1.0;
        } else {
            out.activation = v->number_in(0.0, 1.0);
        }
    }
    if (auto v = m.find("damage"))
        out.damage = v->number_in(0.0, 1.0);
    return out;
}

/// One material per mesh group: a material with "group" takes that group,
/// one without takes every group no other material names.
std::vector<Material> group_materials(const JsonCursor& list, const Mesh& mesh, const DeclaredKeys& declared)
{
    const size_t groups = mesh.group_names.size();
    std::vector<std::optional<Material>> assigned(groups);
    std::optional<Material> fallback;
    if (list.size() == 0)
        list.fail("expected at least one material");
    for (size_t i = 0; i < list.size(); ++i) {
        const JsonCursor m = list[i];
        Material made = material(m, mesh.kind, declared);
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


/// Each element's fiber and damage from its group's material.
void set_element_data(Scene& scene, const std::vector<Material>& materials)
{
    const Mesh& mesh = scene.mesh;
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
    }
    for (size_t g = 0; g < materials.size(); ++g)
        if (materials[g].fiber_list && materials[g].fiber_list->size() != rank_in_group[g])
            materials[g].fiber_list->fail("has " + std::to_string(materials[g].fiber_list->size()) +
                                          " fibers, group '" + mesh.group_names[g] + "' " +
                                          std::to_string(rank_in_group[g]) + " elements");
}

/// The activation of group g, α_e = s·α on its elements, as a quantity a
/// load factor scales (none when the group has no activation).
void add_activation(const Mesh& mesh, size_t g, const Material& m, SceneAssembly& assembly)
{
    if (!m.activation_at || (m.activation == 0.0 && !m.activation_curve))
        return;
    std::vector<int> elements;
    for (int e = 0; e < mesh.num_elements(); ++e)
        if (static_cast<size_t>(mesh.element_groups[static_cast<size_t>(e)]) == g)
            elements.push_back(e);
    const double alpha = m.activation;
    ScaledQuantity q;
    q.name = "the activation of group '" + mesh.group_names[g] + "'";
    q.curve = m.activation_curve;
    q.set = [elements, alpha](Scene& scene, double s0, double s1, double w) {
        const double s = (1.0 - w) * s0 + w * s1;
        for (int e : elements)
            scene.elastic->set_activation(e, s * alpha);
    };
    q.refusal = [alpha](double lowest, double highest) -> std::string {
        if (lowest * alpha >= 0.0 && highest * alpha <= 1.0)
            return "";
        return "takes the activation to [" + format_number(lowest * alpha) + ", " + format_number(highest * alpha) +
               "], out of [0, 1]";
    };
    assembly.add_scaled(std::move(q), *m.activation_at);
}

/// "materials": one material per mesh group, giving the elastic potential
/// its models and each element its fiber, activation and damage.
class MaterialsPart final : public ScenePart {
public:
    std::string key() const override { return "materials"; }
    std::string doc() const override { return "one material per mesh group: model, parameters, density, fiber, activation, damage"; }
    std::string kind() const override { return "potential"; }
    bool required() const override { return true; }
    int stage() const override { return 20; }
    std::vector<SceneKey> keys() const override
    {
        return {{"[].group", "string", "a group of the mesh", "every group no other material names", "the group"},
                {"[].model", "string", "sinew energy --list", "", "the constitutive model", true},
                {"[].parameters", "object", "the model's parameters", "the model's defaults", "name: value"},
                {"[].density", "number", "[0, inf)", "0", "kg/m³ (tets), kg/m² (triangles)"},
                {"[].fiber", "vector | object | string", "[a…], {per_element}, {helix}, \"mesh\"", "\"mesh\"",
                 "the fiber direction a₀ in material space"},
                {"[].fiber.per_element", "matrix", "", "", "one fiber per element of the group, in mesh order"},
                {"[].fiber.helix", "object", "{axis, point, angle_deg}", "", "a helical field (tets)"},
                {"[].activation", "number | keyframes", "[0, 1], or [[t, α], …] with α in [0, 1]", "0",
                 "muscle activation α at load factor 1, or α(t) over time (a scene with dynamics)"},
                {"[].damage", "number", "[0, 1]", "0", "damage d"}};
    }
    void read(const JsonCursor& material_list, SceneAssembly& assembly) const override
    {
        Scene& scene = assembly.scene;
        const Mesh& mesh = scene.mesh;
        const std::vector<Material> materials = group_materials(material_list, mesh, DeclaredKeys(keys()));
        std::vector<ElementModel> models;
        std::vector<double> densities;
        for (const Material& m : materials) {
            models.push_back(m.model);
            densities.push_back(m.density);
        }
        scene.elastic = at_place(*assembly.mesh_place, [&] { return std::make_shared<ElasticPotential>(mesh, models); });
        set_element_data(scene, materials);
        assembly.densities = densities;
        assembly.group_has_fiber.assign(materials.size(), 0);
        for (size_t g = 0; g < materials.size(); ++g) {
            const Material& m = materials[g];
            assembly.group_has_fiber[g] = m.fiber || m.fiber_list || m.helix || mesh.element_fibers.size() > 0;
            add_activation(mesh, g, m, assembly);
        }
        assembly.terms.insert(assembly.terms.begin(), scene.elastic);
    }
};

const SceneRegistration<MaterialsPart> materials_part;

} // namespace
} // namespace sinew
