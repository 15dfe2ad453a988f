#include "sinew/inverse/face_rig.hpp"

#include "sinew/bodies/surface_body.hpp"
#include "sinew/energies/potentials/element_model.hpp"

#include <set>
#include <utility>

namespace sinew {
namespace {

/// h̄: the mean length of the tets' edges (each edge once).
double mean_edge_length(const Mesh& mesh)
{
    std::set<std::pair<int, int>> edges;
    double total = 0.0;
    for (int e = 0; e < mesh.num_elements(); ++e)
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b) {
                const int i = mesh.elements(a, e), j = mesh.elements(b, e);
                if (edges.insert(std::minmax(i, j)).second)
                    total += (mesh.nodes.col(i) - mesh.nodes.col(j)).norm();
            }
    return total / static_cast<double>(edges.size());
}

} // namespace

RigDefinition face_rig(const FaceMesh& face, const FaceMaterials& materials, bool skull_contact)
{
    RigDefinition rig;
    rig.mesh = face.mesh;
    const ParameterValues tissue{{"A", materials.A}, {"B", materials.B}, {"K", materials.K}, {"sigma_max", 0.0}};
    const ParameterValues muscle{
        {"A", materials.A}, {"B", materials.B}, {"K", materials.K}, {"sigma_max", materials.sigma_max}};
    rig.group_models.push_back(make_element_model(ElementKind::tetrahedron, "mooney-rivlin-muscle", tissue));
    for (std::size_t m = 0; m < face.muscle_names.size(); ++m)
        rig.group_models.push_back(make_element_model(ElementKind::tetrahedron, "mooney-rivlin-muscle", muscle));
    rig.muscle_names = face.muscle_names;
    rig.muscle_elements = face.muscle_elements;
    rig.cranium_nodes = face.cranium_nodes;
    rig.jaw_nodes = face.jaw_nodes;
    rig.landmarks = face.landmarks;
    if (skull_contact) {
        const double mu = 2.0 * (materials.A + materials.B);
        // ε = factor · μ h̄ (seed 000 §5.7: a force scaled by depth, f = ε δ ∇φ).
        const double stiffness = materials.skull_stiffness_factor * mu * mean_edge_length(face.mesh);
        rig.contact = RigContact{std::make_shared<SurfaceBody>(face.maxilla, "maxilla"), stiffness,
                                 face.skull_contact_nodes};
        rig.jaw_contact = RigContact{std::make_shared<SurfaceBody>(face.mandible, "mandible"), stiffness,
                                     face.skull_contact_nodes};
    }
    return rig;
}

} // namespace sinew
