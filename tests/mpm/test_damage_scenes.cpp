// AnisoMPM's damage in scenes (issue 34): the "mpm_damage" part, its bad
// input, and the explicit damage's stability bound.
#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/qr_anisotropic.hpp"
#include "sinew/mpm/damage/damage_update.hpp"
#include "sinew/mpm/damage/driving_force.hpp"
#include "sinew/mpm/explicit_step.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/jacobi_cg.hpp"
#include "sinew/runs/mpm_run.hpp"
#include "sinew/runs/scene_run_settings.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <string>

using namespace sinew;

namespace {

/// A 2D block of two materials, "tissue" (qr-anisotropic) and "support"
/// (stable Neo-Hookean), and the given mpm_damage section.
std::string two_materials(const std::string& damage, const std::string& time_step = "0.001")
{
    return R"({"mpm": {"dimension": 2, "dx": 0.05,
      "materials": [{"name": "tissue", "model": "qr-anisotropic", "parameters": {"mu": 40, "lambda": 80, "kx": 100}, "density": 2},
                    {"name": "support", "model": "stable-neo-hookean", "parameters": {"mu": 40, "lambda": 40}, "density": 2}],
      "particles": [{"shape": "box", "lower": [0.2, 0.2], "upper": [0.5, 0.4], "material": "tissue", "fiber": [0, 2]},
                    {"shape": "box", "lower": [0.5, 0.2], "upper": [0.6, 0.4], "material": "support"}],
      "time_step": )" + time_step + R"(, "duration": 0.01, "frames": 2},
      "mpm_damage": )" + damage + "}";
}

std::string input_error(const std::string& text)
{
    try {
        const Scene scene = parse_scene(text, "scene.json");
        if (scene.mpm)
            check_mpm_run(*scene.mpm, SceneRunSettings{});
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

} // namespace

TEST_CASE("mpm_damage: every particle gets a phase-field point, the listed materials as read")
{
    const Scene scene = parse_scene(
        two_materials(R"({"materials": [{"name": "tissue", "stretch": 0.35, "eta": 0.1, "zeta": 2}]})"), "scene.json");
    REQUIRE(scene.mpm);
    REQUIRE(scene.mpm->damage);
    CHECK(scene.mpm->damage->integration == DamageIntegration::implicit_damage);
    CHECK(scene.mpm->damage->implicit.preconditioner == DamagePreconditioner::lumped);
    const MpmSetup<2>& setup = std::get<MpmSetup<2>>(scene.mpm->setup);
    const Particles<2>& particles = setup.particles;
    REQUIRE(particles.phase_field.size() == particles.x.size());
    int tissue = 0;
    for (std::size_t p = 0; p < particles.x.size(); ++p) {
        const PhaseFieldPoint<2>& field = particles.phase_field[p];
        CHECK(field.l0 == 0.5 * 0.05);  // the default l₀ = dx/2
        if (particles.material[p] == 1) {
            CHECK(field.zeta == 0.0);  // not listed: never driven
            continue;
        }
        ++tissue;
        CHECK(field.zeta == 2.0);
        CHECK(field.eta == 0.1);
        CHECK(field.weight1 == -1.0);
        CHECK((field.director1 - Eigen::Vector2d::UnitY()).norm() < 1e-15);  // the particles' fiber, normalized
        // σ_c from the stretch: Φ = 1 at (1 + p) I for this model and point.
        const auto force = driving_force(*setup.models[0], (1.35 * Eigen::Matrix2d::Identity()).eval(),
                                         particles.point[p], field);
        REQUIRE(force);
        CHECK(force->phi == Approx(1.0).epsilon(1e-12));
    }
    CHECK(tissue > 0);
}

TEST_CASE("mpm_damage: directors, weights and sigma_crit as given")
{
    const Scene scene = parse_scene(
        two_materials(R"({"integration": "explicit", "materials": [{"name": "tissue", "sigma_crit": 7, "eta": 0.5,
                         "l0": 0.03, "directors": [[3, 4]], "weights": [2]}]})"),
        "scene.json");
    const Particles<2>& particles = std::get<MpmSetup<2>>(scene.mpm->setup).particles;
    CHECK(scene.mpm->damage->integration == DamageIntegration::explicit_damage);
    const PhaseFieldPoint<2>& field = particles.phase_field[0];
    REQUIRE(particles.material[0] == 0);
    CHECK(field.sigma_crit == 7.0);
    CHECK(field.l0 == 0.03);
    CHECK(field.weight1 == 2.0);
    CHECK((field.director1 - Eigen::Vector2d(0.6, 0.8)).norm() < 1e-15);
}

TEST_CASE("mpm_damage: bad input is one line naming the key")
{
    struct Case {
        std::string damage, expected;
    };
    const std::string ok = R"("stretch": 0.35, "eta": 0.1)";
    const Case c = GENERATE_COPY(
        Case{R"({"materials": [{"name": "bone", )" + ok + "}]}", "no mpm material called 'bone'"},
        Case{R"({"materials": [{"name": "support", )" + ok + "}]}", "does not degrade with damage"},
        Case{R"({"materials": [{"name": "tissue", "eta": 0.1}]})", "needs exactly one of sigma_crit and stretch"},
        Case{R"({"materials": [{"name": "tissue", "eta": 0.1, "stretch": 0.3, "sigma_crit": 4}]})",
             "needs exactly one of sigma_crit and stretch"},
        Case{R"({"materials": [{"name": "tissue", "stretch": 0.35}]})", "eta"},
        Case{R"({"materials": [{"name": "tissue", "stretch": 0.35, "eta": 0}]})", "eta"},
        Case{R"({"materials": [{"name": "tissue", "stretch": -0.2, "eta": 0.1}]})", "stretch"},
        Case{R"({"materials": [{"name": "tissue", "sigma_crit": "big", "eta": 0.1}]})", "sigma_crit"},
        Case{R"({"materials": [{"name": "tissue", )" + ok + R"(, "weights": [-2]}]})", "weights"},
        Case{R"({"materials": [{"name": "tissue", )" + ok + R"(, "directors": [[1, 0], [0, 1]]}]})", "needs 3D"},
        Case{R"({"materials": [{"name": "tissue", )" + ok + R"(, "directors": [[0, 0]]}]})", "nonzero"},
        Case{R"({"materials": [{"name": "tissue", )" + ok + R"(, "l0": 1e300}]})", "l0"},
        Case{R"({"materials": [{"name": "tissue", )" + ok + "}, {\"name\": \"tissue\", " + ok + "}]}",
             "a second entry for material 'tissue'"},
        Case{R"({"materials": []})", "needs at least one material"},
        Case{R"({"materials": [{"name": "tissue", )" + ok + R"(, "colour": 1}]})", "colour"},
        Case{R"({"integration": "explicit", "preconditioner": "lumped", "materials": [{"name": "tissue", )" + ok + "}]}",
             "is for \"integration\": \"implicit\""},
        Case{R"({"integration": "sideways", "materials": [{"name": "tissue", )" + ok + "}]}", "unknown value 'sideways'"},
        Case{R"({"cg_tolerance": 0, "materials": [{"name": "tissue", )" + ok + "}]}", "cg_tolerance"});
    CAPTURE(c.damage);
    const std::string error = input_error(two_materials(c.damage));
    CHECK_THAT(error, Catch::Contains("mpm_damage"));
    CHECK_THAT(error, Catch::Contains(c.expected));
    CHECK(error.find('\n') == std::string::npos);
}

TEST_CASE("mpm_damage: needs the mpm section, and explicit damage refuses a step above its bound")
{
    const std::string mesh_scene = R"({"mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 1, 1], "cells": [1, 1, 1]},
        "materials": [{"model": "qr-anisotropic"}], "mpm_damage": {"materials": []}})";
    CHECK_THAT(input_error(mesh_scene), Catch::Contains("mpm_damage: acts on the particles of an \"mpm\" section"));
    // η = 1e-4 s, l₀ = dx/2: the bound 2η/(1 + 4·2·¼) = 6.7e-5 s is below the step of 1e-3 s.
    const std::string fast = R"({"integration": "explicit", "materials": [{"name": "tissue", "stretch": 0.35, "eta": 1e-4}]})";
    CHECK_THAT(input_error(two_materials(fast)), Catch::Contains("exceeds the explicit damage's stability bound"));
    CHECK(input_error(two_materials(fast, "5e-5")) == "no error");
    // Implicit damage has no such bound.
    const std::string implicit = R"({"materials": [{"name": "tissue", "stretch": 0.35, "eta": 1e-4}]})";
    CHECK(input_error(two_materials(implicit)) == "no error");
}

TEST_CASE("explicit damage: stable below its time-step bound, unstable well above it")
{
    // A driving force D̃ = 1 held by the history (F = I), d random in
    // [0.4, 0.6] about the equilibrium D̃/(1 + D̃) = 0.5: explicit damage is
    // forward Euler of ηḋ = ⟨1 − 2d + l₀²Δd⟩ on the particles. Below the
    // bound the particles under their neighbours rise without overshooting
    // and d stays within its initial range; far above it the Laplacian's
    // high-frequency modes overshoot and, with the Macaulay bracket letting
    // d only rise, ratchet d up to 1. The bound is
    // sufficient, not sharp: power iteration on these particles gives
    // ρ(Δ_h) ≈ 1.05/dx² (1.2–1.6/dx² jittered, 1.0–1.1/dx² in 3D) against the
    // bound's 4·Dim/dx², so the instability starts some 5 times above it.
    const double dx = 0.05;
    Particles<2> particles;
    for (int i = 0; i < 24; ++i)
        for (int j = 0; j < 24; ++j)
            particles.add(Eigen::Vector2d((i + 0.5) * dx / 2, (j + 0.5) * dx / 2), Eigen::Vector2d::Zero(), 1.0, 1.0);
    PhaseFieldPoint<2> field;
    field.eta = 1.0;
    field.l0 = 2.0 * dx;  // diffusion-dominated: the bound is set by the Laplacian
    field.history = 1.0;  // D̃ = max(ζ⟨Φ − 1⟩, D̃ᴴ) = 1
    particles.phase_field.assign(particles.x.size(), field);
    std::mt19937 rng(34);
    std::uniform_real_distribution<double> u(0.4, 0.6);
    for (auto& point : particles.point)
        point.damage = u(rng);
    const double bound = explicit_damage_time_step(particles, dx);
    CHECK(bound == Approx(2.0 / (1.0 + 4.0 * 2.0 * 4.0)));
    const auto largest_after = [&](double dt, int steps) {
        Particles<2> copy = particles;
        const QrAnisotropic<2> model(ParameterValues{{"mu", 40.0}, {"lambda", 80.0}});
        const std::vector<const ConstitutiveModel<2, 2>*> models{&model};
        DamageGrid<2> grid(dx);
        DamageSettings settings;
        settings.integration = DamageIntegration::explicit_damage;
        double largest = 0.0;
        for (int k = 0; k < steps; ++k)
            update_damage(copy, models, dt, settings, grid, jacobi_cg(1e-10, 1000));
        for (const auto& point : copy.point)
            largest = std::max(largest, point.damage);
        return largest;
    };
    CHECK(largest_after(0.95 * bound, 200) <= 0.6);
    CHECK(largest_after(20.0 * bound, 200) == 1.0);
}
