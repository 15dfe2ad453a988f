#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/bodies/analytic_obstacle.hpp"
#include "sinew/bodies/level_set_body.hpp"
#include "sinew/bodies/surface_body.hpp"
#include "sinew/core/format_number.hpp"
#include "sinew/energies/constraints/body_gaps.hpp"
#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"
#include "sinew/mesh/face_mesh.hpp"
#include "sinew/mesh/icosphere.hpp"
#include "sinew/mesh/obj_reader.hpp"

namespace sinew {
namespace {

/// The default candidate margin of gap constraints, times the scene's size.
constexpr double kDefaultMarginFraction = 0.05;
/// A level set's default band, voxels on each side of the surface (OpenVDB's LEVEL_SET_HALF_WIDTH).
constexpr double kDefaultHalfWidth = 3.0;

/// A 2D rotation or 3D map as a 3 × 3 rotation, a 2D vector as (x, y, 0).
Eigen::Matrix3d embedded(const Eigen::MatrixXd& rotation)
{
    Eigen::Matrix3d out = Eigen::Matrix3d::Identity();
    out.topLeftCorner(rotation.rows(), rotation.cols()) = rotation;
    return out;
}
Eigen::Vector3d embedded(const Eigen::VectorXd& v)
{
    Eigen::Vector3d out = Eigen::Vector3d::Zero();
    out.head(v.size()) = v;
    return out;
}

/// A closed triangle surface and its name: an OBJ file (string),
/// {generator: icosphere, center, radius, subdivisions} or {generator:
/// face-skull, target_tets, skull_gap} (the skull of the face mesh of the
/// same numbers).
std::pair<Mesh, std::string> surface_mesh(const JsonCursor& s, const std::string& base_folder)
{
    if (!s.is_object()) {
        const std::string path = resolve_path(s.string(), base_folder);
        return {at_place(s, [&] { return read_obj(path); }), path};
    }
    const std::string generator = s.at("generator").string();
    if (generator == "face-skull") {
        s.expect_object({"generator", "target_tets", "skull_gap"});
        const FaceShape shape = face_shape(s);
        return {at_place(s, [&] { return generate_face_skull(shape); }), "face skull"};
    }
    if (generator != "icosphere")
        s.at("generator").fail("unknown surface generator '" + generator + "'; valid: icosphere, face-skull");
    s.expect_object({"generator", "center", "radius", "subdivisions"});
    const Eigen::Vector3d center = s.at("center").vector(3);
    const double radius = s.at("radius").number();
    const int subdivisions = s.at("subdivisions").integer_in(0, kMaxIcosphereSubdivisions);
    return {at_place(s, [&] { return icosphere(center, radius, subdivisions); }), "icosphere"};
}

/// A level set body: a `.vdb` file (string) or {surface, voxel_size, half_width}
/// converted by OpenVDB.
std::shared_ptr<const CollisionBody> level_set_body(const JsonCursor& l, const std::string& base_folder)
{
    if (!l.is_object()) {
        const std::string path = resolve_path(l.string(), base_folder);
        return at_place(l, [&] { return std::make_shared<const LevelSetBody>(LevelSetBody::from_vdb(path)); });
    }
    l.expect_object({"surface", "voxel_size", "half_width"});
    const auto [surface, name] = surface_mesh(l.at("surface"), base_folder);
    const double voxel_size = l.at("voxel_size").number();
    const double half_width = l.has("half_width") ? l.at("half_width").number() : kDefaultHalfWidth;
    return at_place(l, [&, &surface = surface, &name = name] {
        return std::make_shared<const LevelSetBody>(LevelSetBody::from_surface(surface, name, voxel_size, half_width));
    });
}

} // namespace

std::shared_ptr<const CollisionBody> read_body(const JsonCursor& o, int dimension, const std::string& base_folder)
{
    if (o.has("surface") + o.has("level_set") + o.has("plane") + o.has("sphere") + o.has("box") != 1)
        o.fail("give exactly one of surface, level_set, plane, sphere, box");
    for (const char* key : {"surface", "level_set"})
        if (o.has(key) && dimension != 3)
            o.at(key).fail(std::string("a ") + (key[0] == 's' ? "surface" : "level set") + " body needs a 3D scene");
    if (auto s = o.find("surface")) {
        const auto [surface, name] = surface_mesh(*s, base_folder);
        return at_place(*s, [&, &surface = surface, &name = name] {
            return std::make_shared<const SurfaceBody>(surface, name);
        });
    }
    if (auto l = o.find("level_set"))
        return level_set_body(*l, base_folder);
    if (auto p = o.find("plane")) {
        p->expect_object({"point", "normal"});
        const Eigen::VectorXd point = p->at("point").vector(dimension), normal = p->at("normal").vector(dimension);
        return at_place(*p, [&] { return analytic_body(PlaneObstacle{normal, normal.dot(point)}, dimension); });
    }
    if (auto b = o.find("box")) {
        b->expect_object({"lower", "upper"});
        const Eigen::VectorXd lower = b->at("lower").vector(dimension), upper = b->at("upper").vector(dimension);
        return at_place(*b, [&] { return analytic_body(BoxObstacle{lower, upper}, dimension); });
    }
    const JsonCursor s = o.at("sphere");
    s.expect_object({"center", "radius"});
    const Eigen::VectorXd center = s.at("center").vector(dimension);
    const double radius = s.at("radius").number();
    return at_place(s, [&] { return analytic_body(SphereObstacle{center, radius}, dimension); });
}

namespace {

/// The body's rigid motion as a quantity a load factor scales: at factor s
/// it is turned by R(sθ) about c and moved by s·t.
ScaledQuantity body_motion(const JsonCursor& o, const std::shared_ptr<PlacedBody>& body, PrescribedMotion motion,
                           int dimension)
{
    ScaledQuantity q;
    q.name = "body '" + body->name() + "'";
    if (auto curve = o.find("curve"))
        q.curve = keyframes(*curve);
    q.set = [body, motion, dimension](Scene&, double s0, double s1, double w) {
        const double s = (1.0 - w) * s0 + w * s1;
        body->set_placement(embedded(motion.map_at(s, dimension)), embedded(motion.translation_at(s, dimension)));
    };
    return q;
}

/// InputError at `o` when a colliding node that a Dirichlet set holds is
/// inside the body at load factor 0 or 1: no contact force can move it out.
void check_held_nodes(const JsonCursor& o, const SceneAssembly& assembly, PlacedBody& body,
                      const PrescribedMotion& motion, const std::vector<int>& colliding)
{
    const Mesh& mesh = assembly.scene.mesh;
    const int dimension = static_cast<int>(mesh.nodes.rows());
    std::vector<char> collides(static_cast<std::size_t>(mesh.num_nodes()), colliding.empty() ? 1 : 0);
    for (int node : colliding)
        collides[node] = 1;
    for (const double s : {0.0, 1.0}) {
        body.set_placement(embedded(motion.map_at(s, dimension)), embedded(motion.translation_at(s, dimension)));
        for (const DirichletSet& set : assembly.dirichlet_sets) {
            const Eigen::MatrixXd map = Eigen::MatrixXd::Identity(dimension, dimension) + s * (set.map - Eigen::MatrixXd::Identity(dimension, dimension));
            for (int node : set.nodes) {
                if (!collides[node])
                    continue;
                const Eigen::VectorXd x = map * mesh.nodes.col(node) + s * set.translation;
                const double phi = body.distance(embedded(x)).distance;
                if (phi < 0.0)
                    o.fail("node " + std::to_string(node) + " of Dirichlet set '" + set.name + "' is " +
                           format_number(-phi) + " m inside the body at load factor " + format_number(s) +
                           "; a held node cannot be pushed out (leave it out of select)");
            }
        }
    }
    body.set_placement(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
}

/// "bodies": rigid collision bodies, optionally moving, held off either by
/// the seed's penalty or by exact gap constraints (docs/contact.md).
class BodiesPart final : public ScenePart {
public:
    std::string key() const override { return "bodies"; }
    std::string doc() const override
    {
        return "rigid collision bodies (OBJ surface, level set, plane, sphere) held off by a penalty or by gap constraints";
    }
    std::string kind() const override { return "constraints"; }
    int stage() const override { return 51; }
    std::vector<SceneKey> keys() const override
    {
        return {{"[].name", "string", "", "the file or kind", "the body's name in messages"},
                {"[].surface", "string or object",
                 "an OBJ file | {generator: icosphere, center, radius, subdivisions} | {generator: face-skull, target_tets, skull_gap}", "",
                 "the body's closed triangle surface, 3D scenes"},
                {"[].level_set", "string or object", "a .vdb file | {surface, voxel_size, half_width}", "",
                 "the body's signed distance on an OpenVDB grid (first float level set grid of the file, or the surface converted; half_width 3 voxels), 3D scenes"},
                {"[].plane", "object", "{point, normal}", "", "the half space n·(x − p) < 0 is the body"},
                {"[].sphere", "object", "{center, radius}", "", "the ball |x − c| < r is the body"},
                {"[].box", "object", "{lower, upper}", "", "the box lower < x < upper is the body (turned by rotation)"},
                {"[].rotation", "object", "{axis, angle_deg, center}", "", "turns the body by R(θ) about c at load factor 1"},
                {"[].translation", "vector", "", "0", "moves the body by t at load factor 1 (m)"},
                {"[].curve", "keyframes", "[[t, s], …], t increasing", "dynamics.load_curve",
                 "s(t) moving this body over time (a scene with dynamics)"},
                {"[].select", "selection", "", "every node", "the nodes that collide"},
                {"[].contact", "string", "penalty | gaps", "", "ε/2·depth² per node, or φ(x_i) ≥ 0 per node", true},
                {"[].stiffness", "number", "(0, inf)", "", "penalty: ε, N/m", false, 0.0},
                {"[].curvature", "string", "gauss-newton | projected", "gauss-newton",
                 "penalty: what the PSD-projected Hessian keeps of ε(∇φ∇φᵀ − δ∇²φ)"},
                {"[].margin", "number", "[0, inf)", "0.05 × scene size",
                 "gaps: nodes closer than this to the body are rows (m)", false, 0.0}};
    }
    void read(const JsonCursor& list, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor o = list[i];
            declared.expect_object(o, "[]");
            read_entry(o, declared, assembly);
        }
        assembly.options.constraints = assembly.scene.constraints;
    }

private:
    static void read_entry(const JsonCursor& o, const DeclaredKeys& declared, SceneAssembly& assembly)
    {
        Scene& scene = assembly.scene;
        const Mesh& mesh = scene.mesh;
        const int dimension = static_cast<int>(mesh.nodes.rows());
        const std::string contact = o.at("contact").string();
        if (contact != "penalty" && contact != "gaps")
            o.at("contact").fail("unknown contact '" + contact + "'; valid: penalty, gaps");
        for (const char* key : {"stiffness", "curvature"})
            if (contact == "gaps" && o.has(key))
                o.at(key).fail(std::string(key) + " is for contact \"penalty\"");
        if (contact == "penalty" && o.has("margin"))
            o.at("margin").fail("margin is for contact \"gaps\"");
        if (contact == "penalty" && !o.has("stiffness"))
            o.fail("contact \"penalty\" needs a stiffness");

        auto body = std::make_shared<PlacedBody>(read_body(o, dimension, assembly.base_folder),
                                                 o.has("name") ? o.at("name").string() : "");
        const PrescribedMotion motion = prescribed_motion(o, dimension);
        const std::vector<int> nodes =
            o.has("select") ? selected_nodes(o.at("select"), mesh, assembly.tolerance) : std::vector<int>{};
        check_held_nodes(o, assembly, *body, motion, nodes);
        assembly.add_scaled(body_motion(o, body, motion, dimension), o.has("curve") ? o.at("curve") : o);

        if (contact == "penalty") {
            const double stiffness = declared.number(o.at("stiffness"), "[].stiffness");
            ContactCurvature curvature = ContactCurvature::gauss_newton;
            if (auto c = o.find("curvature")) {
                const std::string text = c->string();
                if (text != "gauss-newton" && text != "projected")
                    c->fail("unknown curvature '" + text + "'; valid: gauss-newton, projected");
                curvature = text == "projected" ? ContactCurvature::projected : ContactCurvature::gauss_newton;
            }
            assembly.terms.push_back(at_place(o, [&] {
                return std::make_shared<ObstaclePenaltyPotential>(dimension, mesh.num_nodes(), body, stiffness, nodes,
                                                                  curvature);
            }));
            return;
        }
        const double margin = o.has("margin") ? declared.number(o.at("margin"), "[].margin")
                                              : kDefaultMarginFraction * scene.size;
        const Eigen::VectorXd rest = Eigen::Map<const Eigen::VectorXd>(mesh.nodes.data(), mesh.nodes.size());
        scene.constraints.push_back(at_place(o, [&] {
            return std::make_shared<BodyGaps>(dimension, mesh.num_nodes(), body, rest, nodes, scene.size, margin);
        }));
    }
};

const SceneRegistration<BodiesPart> bodies_part;

} // namespace
} // namespace sinew
