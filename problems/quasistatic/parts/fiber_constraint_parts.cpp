#include "sinew/problems/quasistatic/parts/constraint_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/energies/constraints/fiber_inextensibility.hpp"
#include "sinew/energies/constraints/weak_fiber_inextensibility.hpp"

namespace sinew {
namespace {

/// {"type": "fiber_inextensibility", "groups": [...]}: a₀ᵀCa₀ = 1 on every
/// element of the groups (all groups when absent), a₀ the elastic
/// potential's fiber of each element (seed 004 §4.1). With `weak`,
/// {"type": "weak_fiber_inextensibility", "groups", "cells": [n...]}: one
/// constraint Σ V_e(a₀ᵀC_e a₀ − 1) per cell of a coarse grid (seed 004 §4.2.2).
std::shared_ptr<ConstraintSet> fiber_constraints(const JsonCursor& c, const SceneAssembly& assembly, bool weak)
{
    if (weak)
        c.expect_object({"type", "groups", "cells"});
    else
        c.expect_object({"type", "groups"});
    const Scene& scene = assembly.scene;
    const Mesh& mesh = scene.mesh;
    std::vector<char> chosen(mesh.group_names.size(), c.has("groups") ? 0 : 1);
    if (auto groups = c.find("groups")) {
        if (groups->size() == 0)
            groups->fail("selects no group");
        for (size_t i = 0; i < groups->size(); ++i)
            chosen[static_cast<size_t>(group_index((*groups)[i], mesh, (*groups)[i].string()))] = 1;
    }
    for (size_t g = 0; g < chosen.size(); ++g) {
        if (chosen[g] && !assembly.group_has_fiber[g])
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

class FiberInextensibilityPart final : public ConstraintPart {
public:
    std::string type() const override { return "fiber_inextensibility"; }
    std::string doc() const override { return "a₀ᵀCa₀ = 1 on every element of the groups (seed 004 §4.1)"; }
    int order() const override { return 0; }
    std::vector<SceneKey> keys() const override
    {
        return {{"groups", "strings", "groups of the mesh", "every group", "the elements kept inextensible"}};
    }
    std::shared_ptr<ConstraintSet> read(const JsonCursor& c, SceneAssembly& assembly) const override
    {
        return fiber_constraints(c, assembly, false);
    }
};

class WeakFiberInextensibilityPart final : public ConstraintPart {
public:
    std::string type() const override { return "weak_fiber_inextensibility"; }
    std::string doc() const override
    {
        return "Σ V_e(a₀ᵀC_e a₀ − 1) = 0 per cell of a coarse grid (seed 004 §4.2.2)";
    }
    int order() const override { return 1; }
    std::vector<SceneKey> keys() const override
    {
        return {{"groups", "strings", "groups of the mesh", "every group", "the elements kept inextensible"},
                {"cells", "integers", "[1, 10000] each", "", "grid cells per dimension", true}};
    }
    std::shared_ptr<ConstraintSet> read(const JsonCursor& c, SceneAssembly& assembly) const override
    {
        return fiber_constraints(c, assembly, true);
    }
};

const ConstraintRegistration<FiberInextensibilityPart> fiber_part;
const ConstraintRegistration<WeakFiberInextensibilityPart> weak_fiber_part;

} // namespace
} // namespace sinew
