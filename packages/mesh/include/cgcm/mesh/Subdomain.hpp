#pragma once
// The subdomain of a mesh that one rank holds in a distributed run. ("Part"
// elsewhere means a summand of the residual: assembly::BulkPart.)
//
// A rank evaluates its own cells and holds the facets of the interaction
// surfaces that are sides of them; the other bodies' facets near its own come
// from their ranks during the run (assembly::GhostedSurfaces). Its subdomain
// therefore has its cells and the nodes they touch, each node carrying its
// index in the whole mesh as its global id (Mesh::nodeIds).
#include <vector>

#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::mesh {

/// The subdomain of `whole` (numbered as built: no node ids of its own) that
/// `rank` holds when `cellOwner` (per mesh-wide cell) gives the cells:
///   - blocks as in `whole` (empty ones kept) with this rank's cells, in mesh-wide order;
///   - nodes: those of these cells and the nodes `alsoKept`, in ascending global id;
///   - node sets: every name, restricted to the subdomain's nodes;
///   - surfaces: the facets of these cells (one surface per body, empty ones kept), in the whole
///     mesh's order, on the subdomain's node indices; facetCells names the subdomain's cell.
Mesh subdomain(const Mesh& whole, const std::vector<int>& cellOwner, int rank,
               const std::vector<LocalIndex>& alsoKept = {});

/// A mesh as bytes, to send to another rank (core::ByteWriter), and back.
std::vector<char> toBytes(const Mesh& mesh);
Mesh meshFromBytes(const std::vector<char>& bytes);

}  // namespace cgcm::mesh
