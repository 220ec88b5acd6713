#include "cgcm/assembly/GhostedSurfaces.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "cgcm/core/Bytes.hpp"

namespace cgcm::assembly {

namespace {

using Box = std::array<Real, 6>;  // min x, y, z, max x, y, z (z = 0 in 2D)

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();

Box emptyBox() { return {kInfinity, kInfinity, kInfinity, -kInfinity, -kInfinity, -kInfinity}; }

void grow(Box& b, const Box& c) {
  for (int i = 0; i < 3; ++i) b[i] = std::min(b[i], c[i]), b[3 + i] = std::max(b[3 + i], c[3 + i]);
}

Real gap(const Box& a, const Box& b) {
  Real g2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Real g = std::max({0.0, a[i] - b[3 + i], b[i] - a[3 + i]});
    g2 += g * g;
  }
  return std::sqrt(g2);
}

bool curvedFacet(int dim, int nodesPerFacet) { return dim == 2 ? nodesPerFacet == 3 : nodesPerFacet > 4; }

// Boxes of groups of at most kFacetsPerBox of `facets` (their boxes given), by recursive bisection of
// the boxes' centres along the group's longest extent.
std::vector<Box> groupBoxes(std::vector<LocalIndex> facets, const std::vector<Box>& box) {
  std::vector<Box> out;
  std::vector<std::pair<std::size_t, std::size_t>> ranges;
  if (!facets.empty()) ranges.push_back({0, facets.size()});
  auto centre = [&](LocalIndex f, int i) { return box[std::size_t(f)][i] + box[std::size_t(f)][3 + i]; };
  while (!ranges.empty()) {
    const auto [begin, end] = ranges.back();
    ranges.pop_back();
    Box all = emptyBox();
    for (std::size_t k = begin; k < end; ++k) grow(all, box[std::size_t(facets[k])]);
    if (end - begin <= std::size_t(GhostedSurfaces::kFacetsPerBox)) {
      out.push_back(all);
      continue;
    }
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (all[3 + i] - all[i] > all[3 + axis] - all[axis]) axis = i;
    const std::size_t middle = begin + (end - begin) / 2;
    std::nth_element(facets.begin() + std::ptrdiff_t(begin), facets.begin() + std::ptrdiff_t(middle),
                     facets.begin() + std::ptrdiff_t(end),
                     [&](LocalIndex a, LocalIndex b) { return centre(a, axis) < centre(b, axis); });
    ranges.push_back({begin, middle});
    ranges.push_back({middle, end});
  }
  return out;
}

}  // namespace

GhostedSurfaces::GhostedSurfaces(Teuchos::RCP<const DofMap> dofs, const mesh::Mesh& mesh, Real lebesgue)
    : dofs_(std::move(dofs)), dim_(mesh.dim), lebesgue_(lebesgue) {
  if (!(lebesgue_ >= 1.0)) throw std::logic_error("GhostedSurfaces: a Lebesgue constant below 1");
  std::unordered_map<GlobalIndex, LocalIndex> held;
  for (const mesh::Surface& s : mesh.surfaces) {
    if (s.facetCells.size() != std::size_t(s.numFacets())) throw std::logic_error("surface without facet-to-cell map");
    mesh::Surface own{s.body, s.nodesPerFacet, {}, {}};
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      if (!dofs_->evaluatesCell(s.facetCells[std::size_t(f)])) continue;
      for (int a = 0; a < s.nodesPerFacet; ++a) {
        const LocalIndex n = s.facets[std::size_t(f) * s.nodesPerFacet + a];
        const auto [it, added] = held.emplace(dofs_->globalNode(n), LocalIndex(ids_.size()));
        if (added) {
          ids_.push_back(it->first);
          ownMeshNodes_.push_back(n);
          for (int i = 0; i < dim_; ++i) reference_.push_back(mesh.coord(n, i));
        }
        own.facets.push_back(it->second);
      }
      own.facetCells.push_back(s.facetCells[std::size_t(f)]);
    }
    numOwnFacets_.push_back(own.numFacets());
    surfaces_.push_back(std::move(own));
  }
  numOwnNodes_ = LocalIndex(ids_.size());
  current_ = reference_;
  atGather_ = reference_;
  if (dofs_->comm()->getSize() == 1) radius_ = kInfinity;  // every facet is this rank's own
  rebuildImport();
}

std::vector<std::vector<char>> GhostedSurfaces::ownFacetFlags() const {
  std::vector<std::vector<char>> own;
  for (std::size_t b = 0; b < surfaces_.size(); ++b) {
    own.emplace_back(std::size_t(surfaces_[b].numFacets()), 0);
    std::fill(own.back().begin(), own.back().begin() + numOwnFacets_[b], 1);
  }
  return own;
}

long GhostedSurfaces::numGhostFacets() const {
  long n = 0;
  for (std::size_t b = 0; b < surfaces_.size(); ++b) n += long(surfaces_[b].numFacets() - numOwnFacets_[b]);
  return n;
}

void GhostedSurfaces::rebuildImport() {
  std::vector<GlobalIndex> gids;
  gids.reserve(ids_.size() * std::size_t(dim_));
  for (GlobalIndex id : ids_)
    for (int i = 0; i < dim_; ++i) gids.push_back(id * dim_ + i);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  const auto map = Teuchos::rcp(new Map(invalid, gids.data(), gids.size(), 0, dofs_->comm()));
  import_ = Teuchos::rcp(new Import(dofs_->ownedMap(), map));
  values_ = Teuchos::rcp(new Vector(map));
}

const std::vector<Real>& GhostedSurfaces::update(const Vector& u) {
  values_->doImport(u, *import_, Tpetra::INSERT);
  const auto v = values_->getLocalViewHost(Tpetra::Access::ReadOnly);
  current_.resize(reference_.size());
  for (std::size_t k = 0; k < reference_.size(); ++k) current_[k] = reference_[k] + v(k, 0);
  return current_;
}

bool GhostedSurfaces::covers(Real reach) const {
  if (radius_ == kInfinity) return true;  // on every rank at once: gather(infinity) is collective
  Real motion = 0.0;                      // of an own node since the last gather
  for (std::size_t n = 0; n < std::size_t(numOwnNodes_); ++n) {
    Real d2 = 0.0;
    for (int i = 0; i < dim_; ++i) {
      const Real d = current_[n * dim_ + i] - atGather_[n * dim_ + i];
      d2 += d * d;
    }
    motion = std::max(motion, std::sqrt(d2));
  }
  const Real mine[2] = {motion, reach};
  Real most[2] = {0.0, 0.0};
  Teuchos::reduceAll(*dofs_->comm(), Teuchos::REDUCE_MAX, 2, mine, most);
  // a facet within the reach now was within reach + 2 (lebesgue x motion) of an own point at the gather
  return radius_ >= 0.0 && most[1] + 2.0 * lebesgue_ * most[0] <= radius_;
}

void GhostedSurfaces::gather(const Vector& u, Real radius) {
  const Comm& comm = *dofs_->comm();
  const int p = comm.getSize(), rank = comm.getRank();
  if (!(radius >= 0.0)) throw std::logic_error("GhostedSurfaces::gather: radius " + std::to_string(radius));
  if (p == 1) return;
  // one radius on every rank (each may ask for its own): covers() compares the ranks' largest reach with it
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, radius, Teuchos::outArg(radius));
  update(u);
  const std::size_t nb = surfaces_.size();
  // the own facets' boxes at the current coordinates
  std::vector<std::vector<Box>> facetBox(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    const mesh::Surface& s = surfaces_[b];
    const bool curved = curvedFacet(dim_, s.nodesPerFacet);
    for (LocalIndex f = 0; f < numOwnFacets_[b]; ++f) {
      Box box = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      for (int i = 0; i < dim_; ++i) box[i] = kInfinity, box[3 + i] = -kInfinity;
      for (int a = 0; a < s.nodesPerFacet; ++a)
        for (int i = 0; i < dim_; ++i) {
          const Real x = current_[std::size_t(s.facets[std::size_t(f) * s.nodesPerFacet + a]) * dim_ + i];
          box[i] = std::min(box[i], x), box[3 + i] = std::max(box[3 + i], x);
        }
      if (curved)
        for (int i = 0; i < dim_; ++i) {
          const Real c = 0.5 * (box[i] + box[3 + i]), h = 0.5 * lebesgue_ * (box[3 + i] - box[i]);
          box[i] = c - h, box[3 + i] = c + h;
        }
      facetBox[b].push_back(box);
    }
  }
  // publish the boxes of groups of own facets
  core::ByteWriter published;
  for (std::size_t b = 0; b < nb; ++b) {
    std::vector<LocalIndex> all(std::size_t(numOwnFacets_[b]));
    for (LocalIndex f = 0; f < numOwnFacets_[b]; ++f) all[std::size_t(f)] = f;
    for (const Box& box : groupBoxes(std::move(all), facetBox[b])) {
      published.put(int(b));
      published.put(box);
    }
  }
  std::vector<std::vector<char>> toRank(static_cast<std::size_t>(p));
  const std::vector<char> mine = published.take();
  for (int r = 0; r < p; ++r)
    if (r != rank) toRank[std::size_t(r)] = mine;
  const std::vector<std::vector<char>> boxesOf = exchangeBytes(comm, toRank);

  // send each own facet to the ranks with a box of another body within the radius of it
  for (int r = 0; r < p; ++r) {
    if (r == rank) continue;
    std::vector<std::vector<Box>> theirs(nb);  // per body
    std::vector<Box> bound(nb, emptyBox());
    core::ByteReader in(boxesOf[std::size_t(r)]);
    while (!in.atEnd()) {
      const int b = in.get<int>();
      const Box box = in.get<Box>();
      if (b < 0 || std::size_t(b) >= nb) throw std::logic_error("GhostedSurfaces: a box of body " + std::to_string(b));
      theirs[std::size_t(b)].push_back(box);
      grow(bound[std::size_t(b)], box);
    }
    core::ByteWriter out;
    for (std::size_t b = 0; b < nb; ++b) {
      const mesh::Surface& s = surfaces_[b];
      for (LocalIndex f = 0; f < numOwnFacets_[b]; ++f) {
        const Box& box = facetBox[b][std::size_t(f)];
        bool wanted = false;
        for (std::size_t l = 0; l < nb && !wanted; ++l) {
          if (l == b || theirs[l].empty() || gap(box, bound[l]) > radius) continue;
          for (const Box& other : theirs[l])
            if (gap(box, other) <= radius) {
              wanted = true;
              break;
            }
        }
        if (!wanted) continue;
        out.put(int(b));
        for (int a = 0; a < s.nodesPerFacet; ++a) {
          const LocalIndex n = s.facets[std::size_t(f) * s.nodesPerFacet + a];
          out.put(ids_[std::size_t(n)]);
          for (int i = 0; i < dim_; ++i) out.put(reference_[std::size_t(n) * dim_ + i]);
        }
      }
    }
    toRank[std::size_t(r)] = out.take();
  }
  toRank[std::size_t(rank)].clear();
  const std::vector<std::vector<char>> facetsFrom = exchangeBytes(comm, toRank);

  // hold the own facets and the ghosts received
  for (std::size_t b = 0; b < nb; ++b) {
    surfaces_[b].facets.resize(std::size_t(numOwnFacets_[b]) * surfaces_[b].nodesPerFacet);
    surfaces_[b].facetCells.resize(std::size_t(numOwnFacets_[b]));
  }
  ids_.resize(std::size_t(numOwnNodes_));
  reference_.resize(std::size_t(numOwnNodes_) * dim_);
  std::unordered_map<GlobalIndex, LocalIndex> held;
  for (LocalIndex n = 0; n < numOwnNodes_; ++n) held.emplace(ids_[std::size_t(n)], n);
  for (int r = 0; r < p; ++r) {
    core::ByteReader in(facetsFrom[std::size_t(r)]);
    while (!in.atEnd()) {
      const int b = in.get<int>();
      if (b < 0 || std::size_t(b) >= nb) throw std::logic_error("GhostedSurfaces: a facet of body " + std::to_string(b));
      mesh::Surface& s = surfaces_[std::size_t(b)];
      for (int a = 0; a < s.nodesPerFacet; ++a) {
        const auto id = in.get<GlobalIndex>();
        Real X[3];
        for (int i = 0; i < dim_; ++i) X[i] = in.get<Real>();
        const auto [it, added] = held.emplace(id, LocalIndex(ids_.size()));
        if (added) {
          ids_.push_back(id);
          reference_.insert(reference_.end(), X, X + dim_);
        }
        s.facets.push_back(it->second);
      }
      s.facetCells.push_back(-1);
    }
  }
  rebuildImport();
  update(u);
  atGather_.assign(current_.begin(), current_.begin() + std::ptrdiff_t(numOwnNodes_) * dim_);
  radius_ = radius;
  ++gathers_;
}

std::vector<std::vector<char>> exchangeBytes(const Comm& comm, const std::vector<std::vector<char>>& toRank) {
  const int p = comm.getSize();
  if (toRank.size() != std::size_t(p)) throw std::logic_error("exchangeBytes: one buffer per rank expected");
  if (p == 1) return toRank;
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  if (!mpi) throw std::logic_error("exchangeBytes: several ranks without MPI");
  const MPI_Comm raw = *mpi->getRawMpiComm();
  const auto n = static_cast<std::size_t>(p);
  std::vector<int> sendCounts(n), receiveCounts(n), sendAt(n), receiveAt(n);
  long long sent = 0, received = 0;
  for (int r = 0; r < p; ++r) {
    sendAt[std::size_t(r)] = int(sent);
    sent += (long long)toRank[std::size_t(r)].size();
    if (sent > INT_MAX) throw std::runtime_error("exchangeBytes: more than 2 GiB to send");
    sendCounts[std::size_t(r)] = int(toRank[std::size_t(r)].size());
  }
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT, raw);
  for (int r = 0; r < p; ++r) {
    receiveAt[std::size_t(r)] = int(received);
    received += receiveCounts[std::size_t(r)];
    if (received > INT_MAX) throw std::runtime_error("exchangeBytes: more than 2 GiB to receive");
  }
  std::vector<char> send(static_cast<std::size_t>(sent)), receive(static_cast<std::size_t>(received));
  for (int r = 0; r < p; ++r)
    std::copy(toRank[std::size_t(r)].begin(), toRank[std::size_t(r)].end(), send.begin() + sendAt[std::size_t(r)]);
  MPI_Alltoallv(send.data(), sendCounts.data(), sendAt.data(), MPI_CHAR, receive.data(), receiveCounts.data(),
                receiveAt.data(), MPI_CHAR, raw);
  std::vector<std::vector<char>> fromRank(n);
  for (int r = 0; r < p; ++r)
    fromRank[std::size_t(r)].assign(receive.begin() + receiveAt[std::size_t(r)],
                                    receive.begin() + receiveAt[std::size_t(r)] + receiveCounts[std::size_t(r)]);
  return fromRank;
}

}  // namespace cgcm::assembly
