#pragma once
#include "sinew/energies/output_arrays.hpp"
#include "sinew/mesh/vtu_writer.hpp"
#include "sinew/problems/quasistatic/scene.hpp"

#include <Eigen/Core>

#include <string>

namespace sinew {

/// The point and cell data of the scene at `configuration`: displacement,
/// force, fixed and group, and each potential's and constraint set's own
/// (add_output_data; the sets with their rows of `multipliers`).
OutputArrays scene_output_arrays(Scene& scene, const Eigen::VectorXd& configuration, const Eigen::VectorXd& multipliers);

/// Writes the scene's mesh at `configuration` (node-major, all coordinates)
/// as a VTU file with the point and cell data of docs/scenes.md, "Output":
/// displacement, force, fixed and group here, and whatever each potential
/// and constraint set of the scene adds through its add_output_data hook
/// (the sets with their rows of `multipliers`). `extra_point_data` adds
/// arrays (a time step's velocity).
void write_scene_vtu(const std::string& path, Scene& scene, const Eigen::VectorXd& configuration,
                     const Eigen::VectorXd& multipliers, VtuEncoding encoding = VtuEncoding::binary,
                     const VtuArrays& extra_point_data = {});

} // namespace sinew
