// The scene as a composition of declared parts: a potential added here
// registers, declares its keys, is read and validated from them, joins the
// NLP and writes its own cell data, with no edit of the reader or runs/.
#include "sinew/core/input_error.hpp"
#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/scene_vtu.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace sinew;

namespace {

/// E(x) = k/2 Σ_i ‖x_i − X_i‖²: every node tied to its rest position.
class TetherPotential final : public Potential {
public:
    TetherPotential(Eigen::VectorXd rest, int dimension, double stiffness)
        : rest_(std::move(rest)), dimension_(dimension), stiffness_(stiffness)
    {
    }
    std::string name() const override { return "tether"; }
    int dimension() const override { return dimension_; }
    int num_nodes() const override { return static_cast<int>(rest_.size()) / dimension_; }
    double value(ConstVectorRef x) override { return 0.5 * stiffness_ * (x - rest_).squaredNorm(); }
    void add_gradient(ConstVectorRef x, VectorRef gradient) override { gradient += stiffness_ * (x - rest_); }
    const Stencils& hessian_stencils() const override { return none_; }
    void add_hessian(ConstVectorRef, Projection, const StencilSlots&, VectorRef) override {}
    void add_output_data(ConstVectorRef x, OutputArrays& arrays) override
    {
        Eigen::MatrixXd stretch(1, arrays.num_points);
        for (int i = 0; i < arrays.num_points; ++i)
            stretch(0, i) = (x - rest_).segment(i * dimension_, dimension_).norm();
        arrays.points["tether_stretch"] = stretch;
        arrays.cells["tethered"] = Eigen::MatrixXd::Ones(1, arrays.num_cells);
    }

private:
    Eigen::VectorXd rest_;
    int dimension_;
    double stiffness_;
    Stencils none_;
};

/// "tether": {"stiffness": k}, read after the materials.
class TetherPart final : public ScenePart {
public:
    std::string key() const override { return "tether"; }
    std::string doc() const override { return "every node tied to its rest position"; }
    std::string kind() const override { return "potential"; }
    int stage() const override { return 34; }
    std::vector<SceneKey> keys() const override
    {
        SceneKey stiffness{"stiffness", "number", "[0, 1e9]", "", "k (N/m)", true};
        stiffness.lower = 0.0;
        stiffness.upper = 1e9;
        return {stiffness};
    }
    void read(const JsonCursor& value, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        declared.expect_object(value);
        const double k = declared.number(value.at("stiffness"), "stiffness");
        const Mesh& mesh = assembly.scene.mesh;
        const Eigen::VectorXd rest = Eigen::Map<const Eigen::VectorXd>(mesh.nodes.data(), mesh.nodes.size());
        assembly.terms.push_back(std::make_shared<TetherPotential>(rest, static_cast<int>(mesh.nodes.rows()), k));
    }
};

void register_tether_once()
{
    for (const auto& part : scene_parts())
        if (part->key() == "tether")
            return;
    register_scene_part(std::make_shared<TetherPart>());
}

std::string scene_with(const std::string& tether)
{
    return R"({"mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 0.5, 0.5], "cells": [2, 1, 1]},
  "materials": [{"model": "fixed-corotated", "parameters": {"mu": 1e4, "lambda": 1e4}}],
  "gravity": [0, 0, -9.81], )" +
           tether + "}";
}

} // namespace

TEST_CASE("scene parts: a potential registered outside the reader is declared, read, solved with and written", "[scene]")
{
    register_tether_once();
    Scene scene = parse_scene(scene_with(R"("tether": {"stiffness": 1e3})"), "tethered");
    REQUIRE(scene.problem->potential().terms().size() == 3);  // elastic, gravity, tether
    CHECK(scene.problem->potential().terms().back()->name() == "tether");

    // Its keys are declared once: listed, and validated from the declaration.
    const std::string listing = scene_keys_markdown();
    CHECK(listing.find("| `tether` | potential | no | 34 | every node tied to its rest position |") != std::string::npos);
    CHECK(listing.find("| `tether.stiffness` | number | [0, 1e9] |") != std::string::npos);
    CHECK_THROWS_WITH(parse_scene(scene_with(R"("tether": {"stifness": 1})"), "tethered"),
                      Catch::Contains("tether.stifness: unknown key; valid keys: stiffness"));
    CHECK_THROWS_WITH(parse_scene(scene_with(R"("tether": {"stiffness": -1})"), "tethered"),
                      Catch::Contains("tether.stiffness: must lie in [0, 1e+09], got -1"));
    CHECK_THROWS_WITH(parse_scene(scene_with(R"("tethr": {})"), "tethered"),
                      Catch::Contains("tethr: unknown key; valid keys: name, description, mesh, materials, gravity"));

    // The runner writes the part's own data without knowing it.
    const auto path = std::filesystem::temp_directory_path() / "sinew-scene-parts-tether.vtu";
    Eigen::VectorXd x = scene.problem->prescribed_configuration();
    x.array() += 0.01;
    write_scene_vtu(path.string(), scene, x, Eigen::VectorXd());
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str().find("Name=\"tether_stretch\"") != std::string::npos);
    CHECK(text.str().find("Name=\"tethered\"") != std::string::npos);
    std::filesystem::remove(path);
}

TEST_CASE("scene parts: each built-in part declares every key it reads, once", "[scene]")
{
    for (const auto& part : scene_parts()) {
        CAPTURE(part->key());
        std::vector<std::string> paths;
        for (const SceneKey& k : part->keys()) {
            CHECK(std::find(paths.begin(), paths.end(), k.path) == paths.end());
            CHECK_FALSE(k.doc.empty());
            CHECK_FALSE(k.type.empty());
            paths.push_back(k.path);
        }
        CHECK_FALSE(part->doc().empty());
    }
    // Reading order: what a part uses is read before it.
    std::vector<std::string> order;
    for (const auto& part : scene_parts())
        order.push_back(part->key());
    const auto at = [&](const std::string& key) { return std::find(order.begin(), order.end(), key) - order.begin(); };
    CHECK(at("mesh") < at("materials"));
    CHECK(at("materials") < at("gravity"));
    CHECK(at("materials") < at("dynamics"));
    CHECK(at("dynamics") < at("load_steps"));
    CHECK(at("materials") < at("constraints"));
}
