#pragma once
// Helpers the scene parts share: error places, paths, node selections,
// parameter text and group names.
#include "sinew/bodies/collision_body.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/model_parameters.hpp"
#include "sinew/mesh/face_mesh.hpp"
#include "sinew/mesh/mesh.hpp"
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/problems/quasistatic/strict_json.hpp"
#include "sinew/time/keyframe_curve.hpp"

#include <initializer_list>
#include <string>
#include <vector>

namespace sinew {

/// Runs `work`, prefixing any InputError it throws with the cursor's place.
template <typename Work>
auto at_place(const JsonCursor& cursor, const Work& work) -> decltype(work())
{
    try {
        return work();
    } catch (const InputError& e) {
        throw InputError(cursor.where() + ": " + e.what());
    }
}

/// `path` resolved against `base_folder` when relative.
std::string resolve_path(const std::string& path, const std::string& base_folder);

/// The nodes a selection object picks ({"all"}, {"nodes"}, {"box"},
/// {"plane"}, {"half_space"}, {"group"}; docs/scenes.md), within
/// `tolerance` of planes and boxes. InputError when it picks none.
std::vector<int> selected_nodes(const JsonCursor& s, const Mesh& mesh, double tolerance);

/// An object of parameters as text, numbers as written.
ParameterText parameter_text(const JsonCursor& p);

/// [[t₀, v₀], [t₁, v₁], …]: at least one keyframe, times strictly
/// increasing, every number finite; an error at the keyframe otherwise.
KeyframeCurve keyframes(const JsonCursor& list);

/// The motion at load factor 1 of an object with "rotation" ({axis,
/// angle_deg, center}; no axis in 2D) or "map", and "translation" (each
/// optional; not both rotation and map), as Dirichlet sets and bodies give it.
PrescribedMotion prescribed_motion(const JsonCursor& b, int dimension);

/// The generated face's shape (mesh/face_mesh.hpp) from an object's optional
/// "target_tets" (integer) and "skull_gap" (m), FaceShape's defaults
/// otherwise: the "face" mesh and the "face-skull" body read the same keys,
/// so the same numbers give the face and its skull.
FaceShape face_shape(const JsonCursor& o);

/// The collision body of an object with exactly one of "surface" (an OBJ
/// file or a generator, 3D), "level_set" (a .vdb file or a surface
/// converted, 3D), "plane" ({point, normal}), "sphere" ({center, radius}) or "box" ({lower, upper}),
/// as "bodies" and the colliders of "mpm" give it (docs/contact.md).
std::shared_ptr<const CollisionBody> read_body(const JsonCursor& o, int dimension, const std::string& base_folder);

/// The string at `v`, which must be one of `valid`; an error listing them otherwise.
std::string read_choice(const JsonCursor& v, std::initializer_list<const char*> valid);

/// The index of the mpm material called by the string at `name`; an error listing the materials otherwise.
int mpm_material_index(const JsonCursor& name, const std::vector<std::string>& materials);

/// The index of the mesh group called `name`; an error at `where` listing the groups otherwise.
int group_index(const JsonCursor& where, const Mesh& mesh, const std::string& name);

} // namespace sinew
