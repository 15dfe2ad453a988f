#include "sinew/inverse/face_rig.hpp"

#include "sinew/energies/potentials/element_model.hpp"

namespace sinew {

RigDefinition face_rig(const FaceMesh& face, const FaceMaterials& materials)
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
    return rig;
}

} // namespace sinew
