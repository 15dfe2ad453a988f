#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/bodies/surface_body.hpp"
#include "sinew/core/format_number.hpp"
#include "sinew/energies/models/model_catalog.hpp"
#include "sinew/mesh/read_mesh.hpp"
#include "sinew/mpm/particle_sampling.hpp"
#include "sinew/mpm/transfers.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace sinew {
namespace {

constexpr double kMaxSpeed = 1e8;  // m/s: anything beyond is a typo
constexpr double kMaxTurnRate = 1e6;  // rad/s
constexpr double kMaxSteps = 1e7;  // duration / time_step

/// The particles' material, by name.
struct MaterialEntry {
    int index = 0;
    double density = 1000.0;
};

/// "mpm": particles on a background grid instead of a mesh (docs/mpm.md,
/// "Scenes"). The whole MPM description lives under this one key.
class MpmPart final : public ScenePart {
public:
    std::string key() const override { return "mpm"; }
    std::string doc() const override { return "particles on a grid, stepped in time (docs/mpm.md); a scene without a mesh"; }
    std::string kind() const override { return "run"; }
    bool mesh_free() const override { return true; }
    int stage() const override { return 35; }
    std::vector<SceneKey> keys() const override
    {
        return {ranged({"dimension", "integer", "2 | 3", "", "2D (disks, plane models) or 3D", true}, 2, 3),
                ranged({"dx", "number", "(0, 1e6]", "", "grid spacing (m)", true}, 0.0, 1e6),
                {"spline", "string", "quadratic | cubic", "quadratic", "B-spline weights of particles on nodes"},
                {"transfer", "string", "apic | pic-flip", "apic", "how velocities go between particles and grid"},
                ranged({"flip_ratio", "number", "[0, 1]", "0.95", "pic-flip: the share of FLIP"}, 0.0, 1.0),
                ranged({"gravity", "vector", "[-1e8, 1e8]", "0", "g (m/s²)"}, -kMaxSpeed, kMaxSpeed),
                {"materials", "array", "", "", "constitutive models of the particles", true},
                {"materials[].name", "string", "", "", "referred to by particles[].material", true},
                {"materials[].model", "string", "sinew energy --list", "", "a model taking F of dimension × dimension", true},
                {"materials[].parameters", "object", "", "the model's defaults", "the model's parameters"},
                ranged({"materials[].density", "number", "(0, 1e8]", "1000", "ρ (kg/m³)"}, 0.0, 1e8),
                {"particles", "array", "", "", "where particles are sampled, at least one source", true},
                {"particles[].shape", "string", "box | ball | mesh | surface", "", "a box, a ball (disk in 2D), one particle per element of a mesh, or a lattice inside a closed surface", true},
                {"particles[].lower", "vector", "", "", "box: lower corner (m)"},
                {"particles[].upper", "vector", "", "", "box: upper corner (m)"},
                {"particles[].center", "vector", "", "", "ball: centre (m)"},
                ranged({"particles[].radius", "number", "(0, inf)", "", "ball: radius (m)"}, 0.0, HUGE_VAL),
                {"particles[].file", "string", "", "", "mesh: a tet mesh (3D) or planar triangle mesh (2D), relative to the scene"},
                {"particles[].surface", "string or object", "as bodies[].surface", "", "surface: a closed triangle surface (an OBJ file or a generator), 3D"},
                {"particles[].material", "string", "materials[].name", "", "the particles' material", true},
                ranged({"particles[].per_cell", "integer", "[1, 16]", "2", "box, ball: particles along each cell edge"}, 1, 16),
                ranged({"particles[].velocity", "vector", "[-1e8, 1e8]", "0", "initial velocity (m/s)"}, -kMaxSpeed, kMaxSpeed),
                {"particles[].fiber", "vector", "nonzero", "e₁ (mesh: the mesh's fibers)", "the fiber director a₀ in rest space, normalized (qr-anisotropic, muscle)"},
                {"walls", "object", "", "none", "the domain's walls, applied to grid velocities"},
                {"walls.lower", "vector", "", "", "lower corner of the domain (m)", true},
                {"walls.upper", "vector", "", "", "upper corner of the domain (m)", true},
                {"walls.condition", "string", "sticky | slip | separate", "separate", "what every wall does to a node it holds"},
                ranged({"walls.thickness", "number", "[0, 100]", "2", "cells of dx from a face whose nodes it holds"}, 0.0, 100.0),
                {"colliders", "array", "", "none", "rigid bodies acting on the grid"},
                {"colliders[].plane", "object", "{point, normal}", "", "the half space n·(x − p) < 0"},
                {"colliders[].sphere", "object", "{center, radius}", "", "the ball |x − c| < r"},
                {"colliders[].box", "object", "{lower, upper}", "", "the box lower < x < upper"},
                {"colliders[].surface", "string or object", "as bodies[].surface", "", "a closed triangle surface, 3D"},
                {"colliders[].level_set", "string or object", "as bodies[].level_set", "", "an OpenVDB signed distance, 3D"},
                {"colliders[].name", "string", "", "the kind", "the collider's name in messages"},
                {"colliders[].condition", "string", "sticky | slip | separate", "separate", "what it does to a node it holds"},
                ranged({"colliders[].velocity", "vector", "[-1e8, 1e8]", "0", "the collider's velocity (m/s): it moves at it from where the scene places it"}, -kMaxSpeed, kMaxSpeed),
                ranged({"colliders[].angular_velocity", "vector", "[-1e6, 1e6]", "0",
                        "ω (rad/s; 2D: [ω] about z): the collider turns at it about its center"}, -kMaxTurnRate, kMaxTurnRate),
                {"colliders[].center", "vector", "", "", "the point the collider turns about at t = 0 (m), moving at its velocity; needed with angular_velocity"},
                ranged({"colliders[].thickness", "number", "[0, 100]", "1", "cells of dx outside the body whose nodes it holds"}, 0.0, 100.0),
                {"stepping", "string", "explicit | implicit", "explicit", "symplectic Euler, or the grid-velocity NLP solved every step (solver: the scene's)"},
                ranged({"time_step", "number", "(0, inf)", "", "Δt (s)", true}, 0.0, HUGE_VAL),
                ranged({"duration", "number", "(0, inf), at most 1e7 steps", "", "T (s)", true}, 0.0, HUGE_VAL),
                ranged({"cfl", "number", "(0, 1]", "0.5", "explicit: Δt ≤ cfl · dx / max(c + |v|)"}, 0.0, 1.0),
                {"substeps", "boolean", "", "false", "explicit: split a step above the CFL bound into sub-steps instead of refusing it"},
                ranged({"frames", "integer", "[1, 100000]", "50", "output frames after t = 0, equally spaced"}, 1, 100000),
                {"grid_output", "boolean", "", "false", "also write the active grid (nodes with mass, cells with mass at every corner) as grid_k.vtu with grid.pvd"}};
    }

    void read(const JsonCursor& m, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        declared.expect_object(m);
        auto scene = std::make_shared<MpmScene>();
        scene->dimension = declared.integer(m.at("dimension"), "dimension");
        scene->dx = positive(m.at("dx"), declared.number(m.at("dx"), "dx"));
        read_time(m, declared, *scene);
        if (scene->dimension == 2)
            scene->setup = read_setup<2>(m, declared, assembly.base_folder, *scene);
        else
            scene->setup = read_setup<3>(m, declared, assembly.base_folder, *scene);
        assembly.scene.mpm = scene;
    }

private:
    static double positive(const JsonCursor& v, double value)
    {
        if (!(value > 0.0))
            v.fail("must be > 0, got " + format_number(value));
        return value;
    }

    static void read_time(const JsonCursor& m, const DeclaredKeys& declared, MpmScene& scene)
    {
        if (auto v = m.find("stepping")) {
            const std::string stepping = v->string();
            if (stepping != "explicit" && stepping != "implicit")
                v->fail("unknown value '" + stepping + "'; valid: explicit, implicit");
            scene.stepping = stepping == "implicit" ? MpmStepping::implicit_steps : MpmStepping::explicit_steps;
        }
        const double time_step = positive(m.at("time_step"), declared.number(m.at("time_step"), "time_step"));
        scene.duration = positive(m.at("duration"), declared.number(m.at("duration"), "duration"));
        const double steps = std::ceil(scene.duration / time_step * (1.0 - 1e-12));
        if (steps > kMaxSteps)
            m.at("duration").fail("asks for " + format_number(steps) + " steps of time_step; at most 1e7");
        if (auto v = m.find("cfl"))
            scene.cfl = positive(*v, declared.number(*v, "cfl"));
        if (auto v = m.find("substeps"))
            scene.substeps = v->boolean();
        if (auto v = m.find("frames"))
            scene.frames = declared.integer(*v, "frames");
        if (auto v = m.find("grid_output"))
            scene.grid_output = v->boolean();
    }

    template <int Dim>
    static MpmSetup<Dim> read_setup(const JsonCursor& m, const DeclaredKeys& declared, const std::string& base_folder,
                                    MpmScene& scene)
    {
        MpmSetup<Dim> setup;
        setup.step.time_step = m.at("time_step").number();
        read_transfer(m, declared, setup.step.transfer);
        if (auto v = m.find("gravity"))
            setup.step.gravity = vector_of<Dim>(*v, declared.at("gravity"));
        const std::map<std::string, MaterialEntry> materials = read_materials<Dim>(m.at("materials"), declared, setup, scene);
        read_particles<Dim>(m.at("particles"), declared, materials, base_folder, scene.dx, setup.particles);
        if (auto w = m.find("walls"))
            setup.step.walls = read_walls<Dim>(*w, declared);
        if (auto c = m.find("colliders"))
            setup.step.colliders = read_colliders<Dim>(*c, declared, base_folder);
        return setup;
    }

    template <int Dim>
    static Eigen::Matrix<double, Dim, 1> vector_of(const JsonCursor& v, const SceneKey& key)
    {
        return v.vector_in(Dim, key.lower, key.upper);
    }

    static void read_transfer(const JsonCursor& m, const DeclaredKeys& declared, TransferSettings& transfer)
    {
        if (auto v = m.find("spline")) {
            const std::string spline = v->string();
            if (spline != "quadratic" && spline != "cubic")
                v->fail("unknown value '" + spline + "'; valid: quadratic, cubic");
            transfer.order = spline == "cubic" ? SplineOrder::cubic : SplineOrder::quadratic;
        }
        if (auto v = m.find("transfer")) {
            const std::string scheme = v->string();
            if (scheme != "apic" && scheme != "pic-flip")
                v->fail("unknown value '" + scheme + "'; valid: apic, pic-flip");
            transfer.scheme = scheme == "apic" ? TransferScheme::apic : TransferScheme::pic_flip;
        }
        if (auto v = m.find("flip_ratio")) {
            if (transfer.scheme != TransferScheme::pic_flip)
                v->fail("is for transfer \"pic-flip\"");
            transfer.flip_ratio = declared.number(*v, "flip_ratio");
        }
    }

    template <int Dim>
    static std::map<std::string, MaterialEntry> read_materials(const JsonCursor& list, const DeclaredKeys& declared,
                                                               MpmSetup<Dim>& setup, MpmScene& scene)
    {
        std::map<std::string, MaterialEntry> materials;
        if (list.size() == 0)
            list.fail("needs at least one material");
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor o = list[i];
            declared.expect_object(o, "materials[]");
            const std::string name = o.at("name").string();
            if (materials.count(name))
                o.at("name").fail("a second material called '" + name + "'");
            MaterialEntry entry;
            entry.index = static_cast<int>(i);
            if (auto v = o.find("density"))
                entry.density = positive(*v, declared.number(*v, "materials[].density"));
            const ParameterText parameters = o.has("parameters") ? parameter_text(o.at("parameters")) : ParameterText{};
            const std::string model = o.at("model").string();
            setup.models.push_back(at_place(o, [&] { return std::shared_ptr<const ConstitutiveModel<Dim, Dim>>(make_model<Dim, Dim>(model, parameters)); }));
            materials[name] = entry;
            scene.materials.push_back(name);
        }
        return materials;
    }

    template <int Dim>
    static void read_particles(const JsonCursor& list, const DeclaredKeys& declared,
                               const std::map<std::string, MaterialEntry>& materials, const std::string& base_folder,
                               double dx, Particles<Dim>& particles)
    {
        if (list.size() == 0)
            list.fail("needs at least one source of particles");
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor o = list[i];
            declared.expect_object(o, "particles[]");
            Particles<Dim> source = at_place(o, [&] { return sample_source<Dim>(o, declared, materials, base_folder, dx); });
            if (source.size() == 0)
                o.fail("samples no particle");
            if (auto f = o.find("fiber")) {
                const Eigen::Matrix<double, Dim, 1> fiber = f->vector(Dim);
                if (!(fiber.norm() > 0.0))
                    f->fail("must be a nonzero vector");
                for (auto& point : source.point)
                    point.fiber = fiber.normalized();
            }
            append(source, particles);
        }
        // Every particle within the grid's indices (the transfers would refuse it at the first step).
        for (int p = 0; p < particles.size(); ++p)
            at_place(list, [&] { return checked_stencil(particles, p, dx, SplineOrder::cubic); });
    }

    template <int Dim>
    static Particles<Dim> sample_source(const JsonCursor& o, const DeclaredKeys& declared,
                                        const std::map<std::string, MaterialEntry>& materials,
                                        const std::string& base_folder, double dx)
    {
        const std::string shape = o.at("shape").string();
        const JsonCursor material_place = o.at("material");
        const auto material = materials.find(material_place.string());
        if (material == materials.end())
            material_place.fail("no material called '" + material_place.string() + "'");
        LatticeSampling<Dim> sampling;
        sampling.dx = dx;
        sampling.density = material->second.density;
        sampling.material = material->second.index;
        if (auto v = o.find("per_cell"))
            sampling.per_cell = declared.integer(*v, "particles[].per_cell");
        if (auto v = o.find("velocity"))
            sampling.velocity = vector_of<Dim>(*v, declared.at("particles[].velocity"));
        const auto allowed = [&](std::initializer_list<const char*> keys) {
            for (const char* key : {"lower", "upper", "center", "radius", "file", "surface", "per_cell"})
                if (o.has(key) && std::find_if(keys.begin(), keys.end(), [&](const char* k) { return std::string(k) == key; }) == keys.end())
                    o.at(key).fail("is not a key of shape '" + shape + "'");
        };
        if (shape == "box") {
            allowed({"lower", "upper", "per_cell"});
            return sample_box<Dim>(o.at("lower").vector(Dim), o.at("upper").vector(Dim), sampling);
        }
        if (shape == "ball") {
            allowed({"center", "radius", "per_cell"});
            return sample_ball<Dim>(o.at("center").vector(Dim), declared.number(o.at("radius"), "particles[].radius"), sampling);
        }
        if (shape == "mesh") {
            allowed({"file"});
            const Mesh mesh = at_place(o.at("file"), [&] { return read_mesh(resolve_path(o.at("file").string(), base_folder)); });
            Particles<Dim> particles = sample_mesh_elements<Dim>(mesh, material->second.density);
            for (int p = 0; p < particles.size(); ++p) {
                particles.material[static_cast<std::size_t>(p)] = sampling.material;
                particles.v[static_cast<std::size_t>(p)] = sampling.velocity;
            }
            return particles;
        }
        if (shape == "surface") {
            allowed({"surface", "per_cell"});
            const std::shared_ptr<const CollisionBody> body = read_body(o, Dim, base_folder);
            const auto* surface = dynamic_cast<const SurfaceBody*>(body.get());
            return sample_inside<Dim>(*body, surface->lower().head<Dim>(), surface->upper().head<Dim>(), sampling);
        }
        o.at("shape").fail("unknown shape '" + shape + "'; valid: box, ball, mesh, surface");
        return {};
    }

    template <int Dim>
    static void append(const Particles<Dim>& source, Particles<Dim>& particles)
    {
        auto extend = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
        extend(particles.x, source.x);
        extend(particles.v, source.v);
        extend(particles.mass, source.mass);
        extend(particles.volume, source.volume);
        extend(particles.F, source.F);
        extend(particles.C, source.C);
        extend(particles.material, source.material);
        extend(particles.point, source.point);
    }

    static GridCondition condition_of(const JsonCursor& v)
    {
        return at_place(v, [&] { return grid_condition(v.string()); });
    }

    template <int Dim>
    static GridWalls<Dim> read_walls(const JsonCursor& w, const DeclaredKeys& declared)
    {
        declared.expect_object(w, "walls");
        const GridCondition condition = w.has("condition") ? condition_of(w.at("condition")) : GridCondition::separate;
        GridWalls<Dim> walls = GridWalls<Dim>::box(w.at("lower").vector(Dim), w.at("upper").vector(Dim), condition);
        for (int a = 0; a < Dim; ++a)
            if (!(walls.lower[a] < walls.upper[a]))
                w.at("upper").fail("must lie above walls.lower in every axis");
        if (auto v = w.find("thickness"))
            walls.thickness = declared.number(*v, "walls.thickness");
        return walls;
    }

    /// ω ([ω_z] in 2D, a 3-vector in 3D, as dynamics.initial_velocity.angular) and the centre it needs.
    template <int Dim>
    static void read_turning(const JsonCursor& o, const DeclaredKeys& declared, GridCollider<Dim>& collider)
    {
        const SceneKey& key = declared.at("colliders[].angular_velocity");
        const auto omega = o.find("angular_velocity");
        if (omega)
            collider.angular_velocity.template tail<Dim == 2 ? 1 : 3>() = omega->vector_in(Dim == 2 ? 1 : 3, key.lower, key.upper);
        if (auto c = o.find("center"))
            collider.center = c->vector_in(Dim, -HUGE_VAL, HUGE_VAL);
        else if (omega)
            omega->fail("needs the collider's center, the point it turns about");
    }

    template <int Dim>
    static std::vector<GridCollider<Dim>> read_colliders(const JsonCursor& list, const DeclaredKeys& declared,
                                                        const std::string& base_folder)
    {
        std::vector<GridCollider<Dim>> colliders;
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor o = list[i];
            declared.expect_object(o, "colliders[]");
            GridCollider<Dim> collider;
            const std::string name = o.has("name") ? o.at("name").string() : "collider " + std::to_string(i);
            collider.body = std::make_shared<const PlacedBody>(read_body(o, Dim, base_folder), name);
            if (auto v = o.find("condition"))
                collider.condition = condition_of(*v);
            if (auto v = o.find("velocity"))
                collider.velocity = vector_of<Dim>(*v, declared.at("colliders[].velocity"));
            if (auto v = o.find("thickness"))
                collider.thickness = declared.number(*v, "colliders[].thickness");
            read_turning(o, declared, collider);
            colliders.push_back(collider);
        }
        return colliders;
    }
};

const SceneRegistration<MpmPart> mpm_part;

} // namespace
} // namespace sinew
