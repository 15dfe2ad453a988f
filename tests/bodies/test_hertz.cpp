// Hertz contact (issue 32): a rigid ball of radius R pressed a depth δ into
// an elastic half-space (a block much wider and deeper than the contact)
// gives the force F = 4/3 E* √R δ^{3/2} and the contact radius a = √(Rδ),
// E* = E/(1 − ν²). The block's mesh is graded towards the contact; the
// errors must shrink as it is refined, and a penalty's force must approach
// the gap constraints' as 1/ε.
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/contact_summary.hpp"
#include "sinew/runs/refreshed_solve.hpp"
#include "sinew/runs/scene_vtu.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace sinew;

namespace {

constexpr double kE = 1e6, kNu = 0.3, kR = 1.0, kDelta = 0.0025;

/// hertz-sphere (scenes/) with 14 × 14 × 7 cells graded by 1.25² towards
/// the contact, each halved `halvings` times (nested meshes), and the given
/// contact.
std::string hertz_scene(int halvings, const std::string& contact)
{
    const double mu = kE / (2.0 * (1.0 + kNu)), lambda = kE * kNu / ((1.0 + kNu) * (1.0 - 2.0 * kNu));
    return R"({"mesh": {"generator": "box", "lower": [-1, -1, -1], "upper": [1, 1, 0], "cells": [14, 14, 7],
                "grading": {"focus": [0, 0, 0], "ratio": 1.5625}, "halvings": )" + std::to_string(halvings) + R"(},
      "materials": [{"model": "stable-neo-hookean", "parameters": {"mu": )" + std::to_string(mu) +
           R"(, "lambda": )" + std::to_string(lambda) + R"(}}],
      "boundary": [{"name": "bottom", "select": {"plane": {"point": [0, 0, -1], "normal": [0, 0, 1]}}}],
      "bodies": [{"sphere": {"center": [0, 0, 1], "radius": 1}, "translation": [0, 0, -0.0025],
                  "select": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}}, )" + contact + "}]}";
}

struct HertzSolve {
    ContactSummary contact;
    double energy = 0.0;  ///< the block's elastic energy, J
};

HertzSolve solve_hertz(int halvings, const std::string& contact, const std::string& solver)
{
    Scene scene = parse_scene(hertz_scene(halvings, contact), "hertz.json");
    SolverOptions options;
    if (solver == "ipopt")
        options.tolerance = 1e-10;  // Ipopt's scaled test at 1e-8 leaves 8e-6 of our KKT residual at eps = 1e8
    const bool exact = solver == "interior-point-exact";
    if (exact)
        options.backend["bound_relax_factor"] = "0";
    const Result result =
        solve_with_refreshed_rows(*scene.problem, exact ? "interior-point" : solver, options);
    CAPTURE(result.message);
    REQUIRE(result.status == Status::converged);
    const Eigen::VectorXd x = scene.problem->full_configuration(result.x);
    HertzSolve out;
    out.contact = contact_summary(scene_output_arrays(scene, x, result.constraint_multipliers),
                                  Eigen::Map<const Eigen::MatrixXd>(x.data(), 3, scene.mesh.num_nodes()));
    out.energy = scene.elastic->value(x);
    return out;
}

} // namespace

TEST_CASE("Hertz: the force and contact radius of a ball pressed into a block approach 4/3 E* sqrt(R) delta^1.5 and sqrt(R delta) under refinement")
{
    const double E_star = kE / (1.0 - kNu * kNu);
    const double F = 4.0 / 3.0 * E_star * std::sqrt(kR) * std::pow(kDelta, 1.5), a = std::sqrt(kR * kDelta);
    const double W = 8.0 / 15.0 * E_star * std::sqrt(kR) * std::pow(kDelta, 2.5);  // ∫ F dδ
    double previous_energy_error = HUGE_VAL, first_force_error = 0.0, force_error = 0.0;
    for (const int halvings : {0, 1}) {
        const HertzSolve h = solve_hertz(halvings, R"("contact": "gaps", "margin": 0.01)", "interior-point");
        const ContactSummary& s = h.contact;
        force_error = std::abs(-s.force.z() / F - 1.0);
        const double radius_error = std::abs(s.contact_radius / a - 1.0);
        const double energy_error = std::abs(h.energy / W - 1.0);
        CAPTURE(halvings, -s.force.z(), F, force_error, s.contact_radius, a, radius_error, h.energy, W, energy_error,
                s.contact_nodes);
        CHECK(s.force.z() < 0.0);  // the ball pushes the block down
        CHECK(std::abs(s.force.x()) < 1e-3 * F);
        CHECK(std::abs(s.force.y()) < 1e-3 * F);
        CHECK(s.max_penetration <= 1.01e-8 * 3.0);  // rows φ/L, L = 3, relaxed by 1e-8
        CHECK(radius_error < 0.1);
        // Nested meshes: the energy of a displacement-driven solve falls
        // towards the exact one as the mesh is refined.
        CHECK(energy_error < previous_energy_error);
        previous_energy_error = energy_error;
        if (halvings == 0)
            first_force_error = force_error;
    }
    CHECK(force_error < first_force_error);
    CHECK(force_error < 0.15);  // at a/h₀ ≈ 4 on a block 20 a deep (docs/contact.md has the table)
}

TEST_CASE("Hertz: the penalty's contact force approaches the gap constraints' as 1 over its stiffness")
{
    // Gap constraints held exactly (no bound relaxation), as the penalty's limit.
    const double exact = -solve_hertz(0, R"("contact": "gaps", "margin": 0.01)", "interior-point-exact").contact.force.z();
    double previous = HUGE_VAL;
    for (const double epsilon : {1e7, 1e8, 1e9}) {
        const ContactSummary s = solve_hertz(
            0, R"("contact": "penalty", "stiffness": )" + std::to_string(epsilon), "ipopt").contact;
        const double gap = std::abs(-s.force.z() - exact) / exact;
        CAPTURE(epsilon, -s.force.z(), exact, gap, s.max_penetration);
        CHECK(s.max_penetration > 0.0);
        if (previous < HUGE_VAL) {
            const double ratio = previous / gap;  // 10 for a first-order approach in 1/ε
            CHECK(ratio > 5.0);
            CHECK(ratio < 20.0);
        }
        previous = gap;
    }
}
