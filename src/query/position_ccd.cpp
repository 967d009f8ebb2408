#include "sscc/query/position_ccd.hpp"

#include <memory>
#include <utility>

namespace sscc {

// A model with no modes: its hierarchy groups triangles by rest position alone, and
// SelfCcd::query_positions, which refits every box from the positions it is given, is the
// whole query.
PositionCcd::PositionCcd(TriangleMesh mesh, ExcludedPairs excluded)
    : detector_(std::make_shared<const SubspaceBvh>(
          SubspaceModel::without_basis(std::move(mesh)).excluding(std::move(excluded)))) {}

}  // namespace sscc
