#pragma once
// TetGen (libtet, Debian package libtet1.5-dev) behind a process boundary.
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

#include <string>

namespace sinew {

/// The arrays of a TetGen run, with 0-based indices into `points`.
struct TetgenOutput {
    Eigen::MatrixXd points;      ///< 3 × number of points
    Eigen::MatrixXi tetrahedra;  ///< 4 × number of tets (empty with switch d)
    Eigen::MatrixXi faces;       ///< 3 × number of faces: with switch d, the input triangles that intersect others
};

/// Runs TetGen with the command-line `switches` (e.g. "pQq2") on the
/// triangle_3d `surface`, one triangular facet per element, and returns its
/// output. TetGen runs in a child process with its output silenced: the
/// Debian build of TetGen 1.5.0 frees its memory twice when it stops on an
/// error and crashes its process, so a failing surface must not take sinew
/// down with it. Throws InputError naming `source` when TetGen rejects the
/// switches, stops on an error, or its process dies; std::runtime_error when
/// the child process cannot be started.
TetgenOutput run_tetgen(const Mesh& surface, const std::string& switches, const std::string& source);

} // namespace sinew
