#include "sinew/mpm/sparse_grid.hpp"

#include <cstdlib>

namespace sinew {

template <int Dim>
SparseGrid<Dim>::SparseGrid(double dx) : dx_(dx)
{
}

template <int Dim>
bool SparseGrid<Dim>::holds(const Index& node)
{
    for (int a = 0; a < Dim; ++a)
        if (std::abs(node[a]) >= kMaxIndex)
            return false;
    return true;
}

template <int Dim>
typename SparseGrid<Dim>::Index SparseGrid<Dim>::block_of(const Index& node)
{
    Index block;
    for (int a = 0; a < Dim; ++a)  // floor division by 4, negative indices included
        block[a] = node[a] >= 0 ? node[a] / kBlockWidth : -((-node[a] + kBlockWidth - 1) / kBlockWidth);
    return block;
}

template <int Dim>
int SparseGrid<Dim>::place_in_block(const Index& node, const Index& block)
{
    int place = 0;
    for (int a = 0; a < Dim; ++a)
        place = place * kBlockWidth + (node[a] - block[a] * kBlockWidth);
    return place;
}

// 21 bits per axis: a block coordinate lies in (−2¹⁸, 2¹⁸), shifted to be non-negative.
template <int Dim>
std::uint64_t SparseGrid<Dim>::key(const Index& block)
{
    std::uint64_t k = 0;
    for (int a = 0; a < Dim; ++a)
        k = (k << 21) | static_cast<std::uint64_t>(block[a] + (kMaxIndex / kBlockWidth));
    return k;
}

template <int Dim>
int SparseGrid<Dim>::touch(const Index& node)
{
    const Index block = block_of(node);
    auto [it, inserted] = block_index_.try_emplace(key(block), blocks());
    if (inserted) {
        block_origin_.push_back(block * kBlockWidth);
        const std::size_t size = static_cast<std::size_t>(slots());
        mass.resize(size, 0.0);
        momentum.resize(size, Vector::Zero());
        velocity.resize(size, Vector::Zero());
        velocity_transferred.resize(size, Vector::Zero());
    }
    return it->second * kBlockNodes + place_in_block(node, block);
}

template <int Dim>
int SparseGrid<Dim>::find(const Index& node) const
{
    if (!holds(node))
        return -1;
    const Index block = block_of(node);
    const auto it = block_index_.find(key(block));
    if (it == block_index_.end())
        return -1;
    return it->second * kBlockNodes + place_in_block(node, block);
}

template <int Dim>
int SparseGrid<Dim>::block_number(const Index& block) const
{
    const auto it = block_index_.find(key(block));
    return it == block_index_.end() ? -1 : it->second;
}

template <int Dim>
typename SparseGrid<Dim>::Index SparseGrid<Dim>::node(int slot) const
{
    Index offset;
    int local = slot % kBlockNodes;
    for (int a = Dim - 1; a >= 0; --a) {
        offset[a] = local % kBlockWidth;
        local /= kBlockWidth;
    }
    return block_origin_[static_cast<std::size_t>(slot / kBlockNodes)] + offset;
}

template <int Dim>
void SparseGrid<Dim>::clear()
{
    block_index_.clear();
    block_origin_.clear();
    mass.clear();
    momentum.clear();
    velocity.clear();
    velocity_transferred.clear();
}

template class SparseGrid<2>;
template class SparseGrid<3>;

} // namespace sinew
