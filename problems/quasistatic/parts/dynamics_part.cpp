#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/energies/potentials/lumped_mass.hpp"
#include "sinew/time/time_integrator.hpp"

#include <cmath>

namespace sinew {
namespace {

/// "dynamics": the scene is stepped in time (docs/dynamics.md); its inertia
/// and damping terms join the potentials.
class DynamicsPart final : public ScenePart {
public:
    std::string key() const override { return "dynamics"; }
    std::string doc() const override { return "integrate in time instead of load stepping (docs/dynamics.md)"; }
    std::string kind() const override { return "run"; }
    int stage() const override { return 33; }
    std::vector<SceneKey> keys() const override
    {
        constexpr double kMaxSpeed = 1e8;  // m/s, rad/s: anything beyond is a typo
        return {{"integrator", "string", "implicit-euler | bdf2 | newmark | implicit-midpoint", "implicit-euler",
                 "the time integrator"},
                {"time_step", "number", "(0, inf)", "", "h (s)", true},
                {"duration", "number", "(0, inf), at most 1e7 steps", "", "T (s): ⌈T/h⌉ steps", true},
                {"initial_velocity", "object", "", "0", "v₀ = linear + angular × (X − center) on every node"},
                ranged({"initial_velocity.linear", "vector", "[-1e8, 1e8]", "0", "m/s"}, -kMaxSpeed, kMaxSpeed),
                ranged({"initial_velocity.angular", "vector", "[-1e8, 1e8]", "0", "rad/s (2D: [ω])"}, -kMaxSpeed,
                       kMaxSpeed),
                {"initial_velocity.center", "vector", "", "0", "m"},
                {"damping", "object", "", "none", "Rayleigh damping D = αM + βK"},
                ranged({"damping.mass", "number", "[0, 1e12]", "0", "α (1/s)"}, 0.0, 1e12),
                ranged({"damping.stiffness", "number", "[0, 1e12]", "0", "β (s); K projected, at each step's start"},
                       0.0, 1e12),
                {"load_curve", "keyframes", "[[t, s], …], t increasing", "1",
                 "the load factor s(t), piecewise linear, of every scaled quantity without its own curve"}};
    }
    void read(const JsonCursor& d, SceneAssembly& assembly) const override
    {
        const int dimension = static_cast<int>(assembly.scene.mesh.nodes.rows());
        assembly.scene.dynamics = settings(d, dimension);
        assembly.load_curve_place = d.find("load_curve");
        add_terms(d, assembly);
    }

private:
    DynamicsSettings settings(const JsonCursor& d, int dimension) const
    {
        const DeclaredKeys declared(keys());
        declared.expect_object(d);
        DynamicsSettings out;
        out.linear_velocity = out.center = Eigen::VectorXd::Zero(dimension);
        out.angular_velocity = Eigen::VectorXd::Zero(dimension == 3 ? 3 : 1);
        if (auto v = d.find("integrator")) {
            out.integrator = v->string();
            at_place(*v, [&] { return make_integrator(out.integrator, 1.0); });
        }
        out.time_step = positive(d.at("time_step"));
        out.duration = positive(d.at("duration"));
        const double steps = std::ceil(out.duration / out.time_step * (1.0 - 1e-12));
        if (steps > kMaxTimeSteps)
            d.at("duration").fail("asks for " + format_number(steps) + " steps of time_step; at most 1e7");
        if (auto v = d.find("initial_velocity")) {
            declared.expect_object(*v, "initial_velocity");
            const SceneKey& speed = declared.at("initial_velocity.linear");
            if (auto linear = v->find("linear"))
                out.linear_velocity = linear->vector_in(dimension, speed.lower, speed.upper);
            if (auto angular = v->find("angular"))
                out.angular_velocity = angular->vector_in(dimension == 3 ? 3 : 1, speed.lower, speed.upper);
            if (auto center = v->find("center"))
                out.center = center->vector(dimension);
        }
        if (auto damping = d.find("damping")) {
            declared.expect_object(*damping, "damping");
            if (auto v = damping->find("mass"))
                out.mass_damping = declared.number(*v, "damping.mass");
            if (auto v = damping->find("stiffness"))
                out.stiffness_damping = declared.number(*v, "damping.stiffness");
        }
        if (auto curve = d.find("load_curve"))
            out.load_factor = keyframes(*curve);
        return out;
    }

    /// A finite number > 0.
    static double positive(const JsonCursor& v)
    {
        const double value = v.number();
        if (!(value > 0.0))
            v.fail("must be > 0, got " + format_number(value));
        return value;
    }

    /// The lumped masses (every density must be > 0: a node without mass has
    /// no inertia) and the step's inertia and Rayleigh damping terms.
    static void add_terms(const JsonCursor& d, SceneAssembly& assembly)
    {
        Scene& scene = assembly.scene;
        const int dimension = static_cast<int>(scene.mesh.nodes.rows());
        for (size_t g = 0; g < assembly.densities.size(); ++g)
            if (!(assembly.densities[g] > 0.0))
                d.fail("group '" + (g < scene.mesh.group_names.size() ? scene.mesh.group_names[g] : std::to_string(g)) +
                       "' has density 0; a scene with dynamics needs a density > 0 (mass) on every material");
        scene.node_masses = at_place(d, [&] { return lumped_masses(scene.mesh, assembly.densities); });
        const DynamicsSettings& settings = *scene.dynamics;
        scene.inertia = std::make_shared<InertiaPotential>("inertia", dimension, scene.node_masses);
        assembly.terms.push_back(scene.inertia);
        if (settings.mass_damping > 0.0) {
            scene.mass_damping = std::make_shared<InertiaPotential>("mass damping", dimension, scene.node_masses);
            assembly.terms.push_back(scene.mass_damping);
        }
        if (settings.stiffness_damping > 0.0) {
            scene.stiffness_damping =
                std::make_shared<StiffnessDampingPotential>(scene.elastic, settings.stiffness_damping);
            assembly.terms.push_back(scene.stiffness_damping);
        }
    }
};

const SceneRegistration<DynamicsPart> dynamics_part;

} // namespace
} // namespace sinew
