#pragma once
#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sinew {

/// The background grid of MPM, stored in blocks of 4^Dim nodes that exist
/// only where particles reach, so that memory follows the particles and not
/// their bounding box. Node i sits at i·dx. A node's data lives at its slot,
/// block · 4^Dim + its place in the block (last axis fastest); blocks are
/// numbered in the order they are first touched, so one input gives one
/// layout. Node indices are bounded by kMaxIndex in each axis (the key of a
/// block packs its coordinates into 64 bits).
template <int Dim>
class SparseGrid {
public:
    using Index = Eigen::Matrix<int, Dim, 1>;
    using Vector = Eigen::Matrix<double, Dim, 1>;
    static constexpr int kBlockWidth = 4;
    static constexpr int kBlockNodes = Dim == 2 ? 16 : 64;
    /// |node index| stays below this in each axis: 2²⁰ nodes of dx.
    static constexpr int kMaxIndex = 1 << 20;

    explicit SparseGrid(double dx);

    double dx() const { return dx_; }
    /// Whether a node index lies within the indices the grid can hold.
    static bool holds(const Index& node);
    /// The slot of `node`, creating its block (zeroed) if needed; node must be held.
    int touch(const Index& node);
    /// The slot of `node`, or −1 when its block does not exist.
    int find(const Index& node) const;
    /// The node at `slot`.
    Index node(int slot) const;
    Vector position(int slot) const { return node(slot).template cast<double>() * dx_; }
    /// The block holding `node` (floor division of each index by 4).
    static Index block_of(const Index& node);
    /// The number of the block at block coordinates `block`, or −1 when it does not exist.
    int block_number(const Index& block) const;
    /// A node's place in its block, last axis fastest.
    static int place_in_block(const Index& node, const Index& block);

    int blocks() const { return static_cast<int>(block_origin_.size()); }
    int slots() const { return blocks() * kBlockNodes; }
    /// Drops every block (the next transfer builds the grid afresh).
    void clear();

    // Node data, by slot: zero in a block just created.
    std::vector<double> mass;       ///< m_i
    std::vector<Vector> momentum;   ///< (m v)_i, then the grid update's forces and impulses
    std::vector<Vector> velocity;   ///< v_i after the grid update
    std::vector<Vector> velocity_transferred;  ///< v_i as the particles gave it (FLIP's increment)

    /// Arrays a step fills afresh and reads in the same step, kept with the
    /// grid so that a step allocates nothing (and the system zeroes no new
    /// pages) once the particles and the grid stop growing. Nothing in them
    /// is read across steps; transfers of a const grid may fill them.
    struct StepBuffers {
        std::vector<Eigen::Matrix<double, Dim + 1, 1>> mass_momentum;   ///< P2G's sums (m, m v) by slot
        std::vector<Eigen::Matrix<double, Dim == 3 ? 4 : Dim, 1>> velocity;  ///< G2P's v_i by slot, padded to 4 doubles in 3D
        std::vector<Eigen::Matrix<double, Dim, Dim>> impulse;         ///< the explicit step's S_p by particle
        std::vector<double> energy;                                   ///< the explicit step's ψ_p by particle
    };
    mutable StepBuffers buffers;

private:
    static std::uint64_t key(const Index& block);

    double dx_;
    std::unordered_map<std::uint64_t, int> block_index_;
    std::vector<Index> block_origin_;  ///< the first node of each block
};

} // namespace sinew
