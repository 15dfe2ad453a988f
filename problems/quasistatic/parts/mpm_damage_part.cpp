#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/mpm/damage/driving_force.hpp"

#include <cmath>
#include <map>
#include <optional>

namespace sinew {
namespace {

/// One entry of "materials": its phase-field point, and what each particle
/// adds (its fiber as the director, unless directors are given; σ_c from
/// the stretch p at the particle's own point).
template <int Dim>
struct MaterialDamage {
    PhaseFieldPoint<Dim> field;
    bool directors_from_fiber = true;
    std::optional<JsonCursor> stretch;
    double p = 0.0;

    PhaseFieldPoint<Dim> point_of(const ConstitutiveModel<Dim, Dim>& model, const MaterialPoint<Dim>& point) const
    {
        PhaseFieldPoint<Dim> out = field;
        if (directors_from_fiber)
            out.director1 = point.fiber.normalized();
        if (stretch)
            out.sigma_crit = at_place(*stretch, [&] { return critical_stress_from_stretch(model, point, out, p); });
        return out;
    }
};

/// "mpm_damage": AnisoMPM's anisotropic phase-field damage on the particles
/// of the scene's "mpm" section (docs/mpm.md, "Damage"; seed 004 §1–2).
class MpmDamagePart final : public ScenePart {
public:
    std::string key() const override { return "mpm_damage"; }
    std::string doc() const override
    {
        return "AnisoMPM's anisotropic phase-field damage of the mpm particles (docs/mpm.md, \"Damage\")";
    }
    std::string kind() const override { return "run"; }
    bool mesh_free() const override { return true; }
    bool needs_mpm() const override { return true; }
    int stage() const override { return 36; }
    std::vector<SceneKey> keys() const override
    {
        return {{"integration", "string", "explicit | implicit", "implicit", "forward Euler on the particles (seed 004 §2.1) or backward Euler on the grid (§2.2)"},
                {"preconditioner", "string", "lumped | full_diagonal", "lumped", "implicit: Jacobi on A's lumped diagonal (the seed's) or on diag(A + B)"},
                {"transfer", "string", "increment | seed", "increment", "implicit: grid to particles as d_p + Σ w (d_i' − d_i) or as the seed's Σ w d_i'; kept in [d_p, 1] either way"},
                ranged({"cg_tolerance", "number", "[1e-14, 0.1]", "1e-8", "implicit: relative residual of the damage solve"}, 1e-14, 0.1),
                ranged({"cg_max_iterations", "integer", "[1, 1000000]", "1000", "implicit: iteration cap of the damage solve"}, 1, 1e6),
                {"materials", "array", "", "", "the mpm materials that damage; the others are never driven (ζ = 0)", true},
                {"materials[].name", "string", "mpm.materials[].name", "", "a material of the mpm section whose model degrades with d", true},
                ranged({"materials[].sigma_crit", "number", "(0, 1e12]", "", "σ_c (Pa): Φ = (Aσ⁺):(σ⁺A)/σ_c²; or stretch"}, 0.0, 1e12),
                ranged({"materials[].stretch", "number", "(0, 10]", "", "p: σ_c such that Φ = 1 at the uniform stretch (1 + p) I; or sigma_crit"}, 0.0, 10.0),
                ranged({"materials[].eta", "number", "(0, 1e12]", "", "η (s): the damage's viscosity, ηḋ = (1 − d)D̃ − (d − l₀²Δd)", true}, 0.0, 1e12),
                ranged({"materials[].zeta", "number", "[0, 1e12]", "1", "ζ: D̃ = ζ⟨Φ − 1⟩"}, 0.0, 1e12),
                ranged({"materials[].l0", "number", "(0, 1e6]", "0.5 dx", "l₀ (m): the crack's length scale"}, 0.0, 1e6),
                {"materials[].directors", "matrix", "1 (2D) or 1–2 (3D) unit rows", "the particles' fiber", "structural directors a_k in rest space (normalized)"},
                ranged({"materials[].weights", "vector", "[-1, 1e6], one per director", "-1 each", "α_k: A = I + Σ α_k (R a_k)(R a_k)ᵀ; −1 takes a_k's direction out of Φ"}, -1.0, 1e6)};
    }

    void read(const JsonCursor& value, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        declared.expect_object(value);
        auto scene = std::make_shared<MpmScene>(*assembly.scene.mpm);
        scene->damage = read_settings(value, declared);
        if (scene->dimension == 2)
            read_materials<2>(value.at("materials"), declared, *scene);
        else
            read_materials<3>(value.at("materials"), declared, *scene);
        assembly.scene.mpm = scene;
    }

private:
    static DamageSettings read_settings(const JsonCursor& value, const DeclaredKeys& declared)
    {
        DamageSettings settings;
        if (auto v = value.find("integration"))
            settings.integration = read_choice(*v, {"explicit", "implicit"}) == "explicit" ? DamageIntegration::explicit_damage
                                                                                      : DamageIntegration::implicit_damage;
        const bool implicit = settings.integration == DamageIntegration::implicit_damage;
        for (const char* key : {"preconditioner", "transfer", "cg_tolerance", "cg_max_iterations"})
            if (!implicit && value.has(key))
                value.at(key).fail("is for \"integration\": \"implicit\"");
        if (auto v = value.find("preconditioner"))
            settings.implicit.preconditioner = read_choice(*v, {"lumped", "full_diagonal"}) == "lumped"
                                                   ? DamagePreconditioner::lumped
                                                   : DamagePreconditioner::full_diagonal;
        if (auto v = value.find("transfer"))
            settings.implicit.transfer =
                read_choice(*v, {"increment", "seed"}) == "seed" ? DamageTransfer::seed : DamageTransfer::increment;
        if (auto v = value.find("cg_tolerance"))
            settings.cg_tolerance = declared.number(*v, "cg_tolerance");
        if (auto v = value.find("cg_max_iterations"))
            settings.cg_max_iterations = declared.integer(*v, "cg_max_iterations");
        return settings;
    }

    /// Every particle gets a phase-field point: the listed materials' as read,
    /// the others' never driven (ζ = 0; the field is one over all particles).
    template <int Dim>
    static void read_materials(const JsonCursor& list, const DeclaredKeys& declared, MpmScene& scene)
    {
        MpmSetup<Dim>& setup = std::get<MpmSetup<Dim>>(scene.setup);
        Particles<Dim>& particles = setup.particles;
        PhaseFieldPoint<Dim> inert;
        inert.zeta = 0.0;
        inert.l0 = 0.5 * scene.dx;
        particles.phase_field.assign(particles.x.size(), inert);
        if (list.size() == 0)
            list.fail("needs at least one material");
        std::map<std::string, int> seen;
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor o = list[i];
            declared.expect_object(o, "materials[]");
            const JsonCursor name = o.at("name");
            const int material = mpm_material_index(name, scene.materials);
            if (!seen.emplace(name.string(), material).second)
                name.fail("a second entry for material '" + name.string() + "'");
            const ConstitutiveModel<Dim, Dim>& model = *setup.models[static_cast<std::size_t>(material)];
            check_degrades<Dim>(name, model);
            const MaterialDamage<Dim> entry = read_entry<Dim>(o, declared, scene.dx);
            for (std::size_t p = 0; p < particles.x.size(); ++p)
                if (particles.material[p] == material)
                    particles.phase_field[p] = entry.point_of(model, particles.point[p]);
        }
    }

    /// Damage must change something: ψ at a stretch differs between d = 0 and d = 1.
    template <int Dim>
    static void check_degrades(const JsonCursor& name, const ConstitutiveModel<Dim, Dim>& model)
    {
        const Eigen::Matrix<double, Dim, Dim> F = 1.5 * Eigen::Matrix<double, Dim, Dim>::Identity();
        MaterialPoint<Dim> point;
        const double intact = model.energy(F, point);
        point.damage = 1.0;
        if (model.energy(F, point) == intact)
            name.fail("material '" + name.string() + "': its model " + model.name() +
                      " does not degrade with damage (ψ is the same at d = 0 and d = 1)");
    }

    template <int Dim>
    static MaterialDamage<Dim> read_entry(const JsonCursor& o, const DeclaredKeys& declared, double dx)
    {
        MaterialDamage<Dim> entry;
        PhaseFieldPoint<Dim>& field = entry.field;
        if (auto v = o.find("directors")) {
            read_directors<Dim>(*v, field);
            entry.directors_from_fiber = false;
        }
        if (auto v = o.find("weights")) {
            const Eigen::VectorXd weights = v->vector_in(field.directors_used, -1.0, declared.at("materials[].weights").upper);
            field.weight1 = weights[0];
            if (field.directors_used == 2)
                field.weight2 = weights[1];
        }
        field.eta = declared.number(o.at("eta"), "materials[].eta");
        field.l0 = o.has("l0") ? declared.number(o.at("l0"), "materials[].l0") : 0.5 * dx;
        if (auto v = o.find("zeta"))
            field.zeta = declared.number(*v, "materials[].zeta");
        const auto sigma = o.find("sigma_crit");
        entry.stretch = o.find("stretch");
        if (sigma.has_value() == entry.stretch.has_value())
            o.fail("needs exactly one of sigma_crit and stretch");
        if (sigma)
            field.sigma_crit = declared.number(*sigma, "materials[].sigma_crit");
        else
            entry.p = declared.number(*entry.stretch, "materials[].stretch");
        const std::string error = phase_field_point_error(field);
        if (!error.empty())
            o.fail(error);
        return entry;
    }

    template <int Dim>
    static void read_directors(const JsonCursor& v, PhaseFieldPoint<Dim>& field)
    {
        const int rows = v.is_array() ? static_cast<int>(v.size()) : 0;
        if (rows < 1 || rows > (Dim == 3 ? 2 : 1))
            v.fail(Dim == 3 ? "must hold one director (transverse isotropy) or two (orthotropy)"
                            : "must hold one director in 2D (orthotropy needs 3D)");
        const Eigen::MatrixXd directors = v.matrix(rows, Dim);
        for (int k = 0; k < rows; ++k)
            if (!(directors.row(k).norm() > 0.0))
                v[static_cast<size_t>(k)].fail("must be a nonzero vector");
        field.directors_used = rows;
        field.director1 = directors.row(0).transpose().normalized();
        if (rows == 2) {
            field.director2 = directors.row(1).transpose().normalized();
            if (std::abs(field.director1.dot(field.director2)) > 1e-9)
                v.fail("the two directors must be orthogonal");
        }
    }
};

const SceneRegistration<MpmDamagePart> mpm_damage_part;

} // namespace
} // namespace sinew
