#include "sinew/problems/quasistatic/builtin_scenes.hpp"

#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/element_model.hpp"
#include "sinew/energies/potentials/gravity_potential.hpp"
#include "sinew/energies/potentials/lumped_mass.hpp"
#include "sinew/mesh/box_tets.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <string>

namespace sinew {
namespace {

std::string cantilever_name(int cells_across, bool twisted)
{
    const int tets = 6 * 5 * cells_across * cells_across * cells_across;
    return std::string(twisted ? "twisted-cantilever-" : "cantilever-") + std::to_string((tets + 500) / 1000) + "k";
}

BuiltinProblem cantilever_scene(int cells_across, bool twisted, const std::string& suite)
{
    const int tets = 6 * 5 * cells_across * cells_across * cells_across;
    return {cantilever_name(cells_across, twisted),
            suite,
            std::string(twisted ? "twisted cantilever" : "cantilever") + ": " + std::to_string(tets) +
                " Mooney-Rivlin tets under gravity" + (twisted ? ", end turned 45° and pulled 0.1 m" : ""),
            [=]() -> std::unique_ptr<Nlp> { return make_cantilever(cells_across, twisted); },
            std::nullopt,
            "issue 4 scene (no published optimum)"};
}

} // namespace

std::unique_ptr<QuasistaticProblem> make_cantilever(int cells_across, bool twisted, DirichletStrategy dirichlet)
{
    const double length = 1.0, side = 0.2;
    const Mesh mesh = box_tets(Eigen::Vector3d::Zero(), Eigen::Vector3d(length, side, side), 5 * cells_across,
                               cells_across, cells_across);
    const ElementModel model = make_element_model(
        mesh.kind, "mooney-rivlin-muscle", ParameterValues{{"A", 1e4}, {"B", 1e3}, {"K", 1e5}, {"sigma_max", 0.0}});
    const size_t groups = mesh.group_names.size();
    auto elastic = std::make_shared<ElasticPotential>(mesh, std::vector<ElementModel>(groups, model));
    auto gravity = std::make_shared<GravityPotential>(3, lumped_masses(mesh, std::vector<double>(groups, 1000.0)),
                                                      Eigen::Vector3d(0, 0, -9.81));
    auto potential = std::make_shared<TotalPotential>(std::vector<std::shared_ptr<Potential>>{elastic, gravity});

    std::vector<int> clamped, end_face;
    const double tolerance = 1e-9 * length;
    for (int i = 0; i < mesh.num_nodes(); ++i) {
        if (std::abs(mesh.nodes(0, i)) <= tolerance)
            clamped.push_back(i);
        if (std::abs(mesh.nodes(0, i) - length) <= tolerance)
            end_face.push_back(i);
    }
    std::vector<DirichletSet> sets{fixed_at_rest("clamped end x = 0", clamped, 3)};
    if (twisted) {
        // x = R(X − c) + c + (0.1, 0, 0): M = R, t = c − R c + (0.1, 0, 0).
        const Eigen::Matrix3d rotation = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()).toRotationMatrix();
        const Eigen::Vector3d axis_point(0.0, side / 2, side / 2);
        sets.push_back(DirichletSet{"twisted end x = 1", end_face, rotation,
                                    axis_point - rotation * axis_point + Eigen::Vector3d(0.1, 0, 0)});
    }
    QuasistaticOptions options;
    options.name = cantilever_name(cells_across, twisted);
    options.dirichlet = dirichlet;
    return std::make_unique<QuasistaticProblem>(mesh.nodes, potential, sets, options);
}

std::vector<BuiltinProblem> quasistatic_scenes()
{
    return {cantilever_scene(6, false, "quasistatic"),      cantilever_scene(6, true, "quasistatic"),
            cantilever_scene(12, false, "quasistatic-large"), cantilever_scene(12, true, "quasistatic-large"),
            cantilever_scene(19, false, "quasistatic-large"), cantilever_scene(19, true, "quasistatic-large")};
}

} // namespace sinew
