#pragma once
// The subdomain of a mesh that one rank holds in a distributed run. ("Part"
// elsewhere means a summand of the residual: assembly::BulkPart.)
//
// A rank evaluates its own cells and reads the whole interaction surfaces
// (every body's surface, on every rank: the closest-point search needs the
// other bodies wherever their cells are evaluated). Its subdomain therefore has
// its cells and the nodes they touch, plus every surface node, each node
// carrying its index in the whole mesh as its global id (Mesh::nodeIds).
#include <vector>

#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::mesh {

/// The subdomain of `whole` (numbered as built: no node ids of its own) that
/// `rank` holds when `cellOwner` (per mesh-wide cell) gives the cells:
///   - blocks as in `whole` (empty ones kept) with this rank's cells, in mesh-wide order;
///   - nodes: those of these cells, every surface node and the nodes `alsoKept`, in ascending global id;
///   - node sets: every name, restricted to the subdomain's nodes;
///   - surfaces: whole, on the subdomain's node indices; facetCells names the subdomain's
///     cell, or is -1 where another rank holds the cell.
Mesh subdomain(const Mesh& whole, const std::vector<int>& cellOwner, int rank,
               const std::vector<LocalIndex>& alsoKept = {});

/// A mesh as bytes, to send to another rank (core::ByteWriter), and back.
std::vector<char> toBytes(const Mesh& mesh);
Mesh meshFromBytes(const std::vector<char>& bytes);

}  // namespace cgcm::mesh
