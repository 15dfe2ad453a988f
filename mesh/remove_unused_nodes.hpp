#pragma once
#include "sinew/mesh/mesh.hpp"

#include <vector>

namespace sinew {

/// Drops the nodes no element uses, keeping the others in their order, and
/// renumbers the elements. Returns, for each kept node, its old index (new →
/// old), so callers can carry per-node data along. Node indices must be in
/// range.
std::vector<int> remove_unused_nodes(Mesh& mesh);

} // namespace sinew
