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
    /// The skull's penalty stiffness ε per node (seed 000 §5.7) as a
    /// multiple of a node's own stiffness in the tissue, μ h̄ (μ = 2(A + B),
    /// h̄ the mean edge of the tets): depths stay about this factor below
    /// the tissue's displacements.
    double skull_stiffness_factor = 1e3;
};

/// The rig of `face`: group 0 (tissue) without fibers, one muscle per muscle
/// group with its elements, the face's cranium and jaw nodes and landmarks;
/// with `skull_contact`, its maxilla as a collision body in the cranium
/// frame and its mandible as one the jaw carries (SurfaceBody, CGAL), both
/// for the face's skull contact nodes.
RigDefinition face_rig(const FaceMesh& face, const FaceMaterials& materials = {}, bool skull_contact = false);

} // namespace sinew
