#include "mapping/internal/known_space.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "core/error.h"
#include "mapping/internal/posterior.h"
#include "mapping/internal/stars.h"

namespace toponav::mapping::internal {

using core::Vec2;

namespace {

// Sight lines stop at the map's walls and the closing walls.
std::vector<Wall> SightWalls(const MapState& ms, const std::vector<Wall>& closing) {
  std::vector<Wall> mw = ms.walls;
  mw.insert(mw.end(), closing.begin(), closing.end());
  std::sort(mw.begin(), mw.end());
  mw.erase(std::unique(mw.begin(), mw.end()), mw.end());
  return mw;
}

bool WithCandidates(const MapperOptions& o) { return o.known_space_candidates && !o.open_region; }

}  // namespace

// What changed since the last update: vertices that entered or left the hypothetical observations (the map,
// and with candidates the seen candidates) or drifted farther than the tolerance since they were last
// flagged, and walls that entered or left the map.  A map vertex is in the hypothetical observation of every
// observation that sees it; a candidate only in those of the observations that detected it, so its changes
// send only those back.
KnownSpace::Changes KnownSpace::FindChanges(const MapCore& m, const MapState& ms, const std::vector<Wall>& closing,
                                            double tolerance) {
  Changes c;
  const size_t n = m.vertices.size();
  const bool with_candidates = WithCandidates(m.o);
  snap_mapped_.resize(n, 0);
  snap_member_.resize(n, 0);
  drift_ref_.resize(n, Vec2{std::numeric_limits<double>::quiet_NaN(), 0});
  for (size_t i = 0; i < n; ++i) {
    const Vec2 at = m.Pos(int(i));
    const bool drifted = std::isnan(drift_ref_[i].x) || core::Distance(drift_ref_[i], at) > tolerance;
    if (drifted) drift_ref_[i] = at;
    const bool mapped = ms.mapped[i];
    const bool member = mapped || (with_candidates && m.vertices.Seen(int(i)));
    if (mapped != bool(snap_mapped_[i]) || (drifted && mapped))
      c.vertices.push_back(int(i));
    else if (member != bool(snap_member_[i]) || (drifted && member))
      c.candidates.push_back(int(i));
    snap_mapped_[i] = mapped;
    snap_member_[i] = member;
  }
  const std::vector<Wall> mw = SightWalls(ms, closing);
  std::set_symmetric_difference(mw.begin(), mw.end(), snap_walls_.begin(), snap_walls_.end(),
                                std::back_inserter(c.walls));
  snap_walls_ = mw;
  return c;
}

bool KnownSpace::NeedsCheck(const MapCore& m, size_t i, const Changes& c) const {
  const Obs& ob = m.obs[i];
  if (!pieces_[i].valid) return true;
  for (int v : c.vertices)
    if (core::BoxHits(ob.box, m.Pos(v), 1e-6)) return true;
  for (const auto& w : c.walls)
    if (core::BoxHitsSegment(ob.box, m.Pos(w.first), m.Pos(w.second), 1e-6)) return true;
  if (c.candidates.empty()) return false;
  for (int id : ob.vid)
    if (std::binary_search(c.candidates.begin(), c.candidates.end(), id)) return true;
  return false;
}

bool KnownSpace::Recompute(const MapCore& m, size_t i, const MapState& ms, const std::vector<Wall>& closing,
                           const Changes& c, bool* changed) {
  const Obs& ob = m.obs[i];
  Piece& piece = pieces_[i];
  *changed = false;
  const std::vector<int> H = Hypothetical(m, i, ms, closing, WithCandidates(m.o));
  bool moved = false;  // a vertex of this S_c got a new known-space position
  for (int id : piece.ids)
    moved = moved || std::binary_search(c.vertices.begin(), c.vertices.end(), id) ||
            std::binary_search(c.candidates.begin(), c.candidates.end(), id);
  std::vector<uint64_t> hit_walls;
  const core::Ring sh = HypotheticalStar(m, ob, H, ms, closing, &hit_walls);
  if (piece.valid && piece.ids == H && piece.walls == hit_walls && !moved) return true;
  const core::Ring sz = RealStar(m, ob);
  PolygonSet sc;
  if (!sh.empty() && !sz.empty()) {
    try {
      sc = PolygonSet::FromRing(sz);
      sc.Intersect(PolygonSet::FromRing(sh));
    } catch (const core::DataError&) {
      sc = PolygonSet();  // a degenerate polygon adds nothing (the conservative choice)
    }
  }
  bool grew = true;  // a new S_c, or one that contains the old one: joining it is enough
  if (piece.valid && !piece.sc.empty()) {
    piece.sc.Difference(sc);  // what the old one loses (it is replaced below)
    grew = piece.sc.empty();
  }
  piece.sc = std::move(sc);
  piece.ids = H;
  piece.walls = std::move(hit_walls);
  piece.valid = true;
  block_dirty_[i / kUnionBlock] = 1;
  *changed = true;
  return grew;
}

void KnownSpace::Update(const MapCore& m, const MapState& ms, double tolerance) {
  const size_t block = kUnionBlock;
  pieces_.resize(m.obs.size());
  while (blocks_.size() * block < m.obs.size()) {
    blocks_.emplace_back();
    block_dirty_.push_back(1);
  }
  const std::vector<Wall> closing = ClosingWalls(m, ms);
  const Changes changes = FindChanges(m, ms, closing, tolerance);
  bool rebuild = false;
  std::vector<const PolygonSet*> grown;  // new pieces that only add to the known space
  for (size_t i = 0; i < m.obs.size(); ++i) {
    if (!NeedsCheck(m, i, changes)) continue;
    bool changed = false;
    const bool grew = Recompute(m, i, ms, closing, changes, &changed);
    if (!changed) continue;
    if (grew && total_valid_) {
      if (!pieces_[i].sc.empty()) grown.push_back(&pieces_[i].sc);
    } else {
      rebuild = true;
    }
  }
  if (!rebuild && total_valid_) {
    // The small pieces first, then one join with the big union.
    if (!grown.empty()) total_.Join(PolygonSet::JoinAll(grown));
    return;
  }
  RebuildUnion(m);
}

// Blocks are the leaves of a binary tree whose inner nodes cache the union of their subtree: a rebuild redoes
// the dirty blocks and the nodes above them only.
void KnownSpace::RebuildUnion(const MapCore& m) {
  const size_t block = kUnionBlock;
  size_t leaves = 1;
  while (leaves < blocks_.size()) leaves *= 2;
  if (union_tree_.size() != 2 * leaves) {  // more blocks than leaves: a bigger tree, every node redone
    union_tree_.assign(2 * leaves, PolygonSet());
    tree_dirty_.assign(2 * leaves, 1);
    for (size_t b = 0; b < blocks_.size(); ++b) union_tree_[leaves + b] = blocks_[b];
  }
  for (size_t b = 0; b < blocks_.size(); ++b) {
    if (!block_dirty_[b]) continue;
    std::vector<const PolygonSet*> members;
    for (size_t i = b * block; i < std::min(pieces_.size(), (b + 1) * block); ++i) members.push_back(&pieces_[i].sc);
    blocks_[b] = PolygonSet::JoinAll(members);
    block_dirty_[b] = 0;
    union_tree_[leaves + b] = blocks_[b];
    for (size_t node = (leaves + b) / 2; node >= 1; node /= 2) tree_dirty_[node] = 1;
  }
  for (size_t node = leaves - 1; node >= 1; --node) {
    if (!tree_dirty_[node]) continue;
    union_tree_[node] = union_tree_[2 * node];
    if (!union_tree_[2 * node + 1].empty()) union_tree_[node].Join(union_tree_[2 * node + 1]);
    tree_dirty_[node] = 0;
  }
  total_ = union_tree_[1];
  total_valid_ = true;
}

}  // namespace toponav::mapping::internal
