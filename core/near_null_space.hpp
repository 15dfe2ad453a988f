#pragma once
#include <Eigen/Core>

namespace sinew {

/// Vectors that a symmetric matrix nearly annihilates, and the block size of
/// its unknowns (the coordinates of one node): what an algebraic multigrid
/// preconditioner builds its coarse spaces from. For elasticity these are the
/// rigid-body modes (translations and infinitesimal rotations of the nodes),
/// with block size = dimension. No vectors: none is known.
struct NearNullSpace {
    Eigen::MatrixXd vectors;  ///< n × k
    int block_size = 1;
};

} // namespace sinew
