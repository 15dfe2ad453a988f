#pragma once
// The rig of a generated face (mesh/face_mesh.hpp): its materials and muscles.
#include "sinew/inverse/muscle_rig.hpp"
#include "sinew/mesh/face_mesh.hpp"

namespace sinew {

/// Materials of the face rig (Pa): the tissue and the muscles share the
/// Mooney-Rivlin matrix of mooney-rivlin-muscle (shear modulus about
/// 2(A + B) = 4 kPa, soft tissue's order, nearly incompressible with K/μ = 25);
/// the muscles add fibers of peak active stress sigma_max (the passive fiber
/// curve as the model's defaults).
struct FaceMaterials {
    double A = 1500.0;
    double B = 500.0;
    double K = 1e5;
    double sigma_max = 3e4;
};

/// The rig of `face`: group 0 (tissue) without fibers, one muscle per muscle
/// group with its elements, the face's cranium and jaw nodes and landmarks.
RigDefinition face_rig(const FaceMesh& face, const FaceMaterials& materials = {});

} // namespace sinew
