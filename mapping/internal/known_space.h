#pragma once
// Known space, incrementally (paper Eq. 2, S_c = union of s(z_i) & s(z_h,i)).  An observation's S_c is
// recomputed only when what its hypothetical observation is built from changes: vertices or walls entering
// or leaving the map (at MCMC calls), a vertex becoming a seen candidate (known_space_candidates), or one of
// these drifting farther than the tolerance by Kalman updates.  An S_c that grew (or is new) is joined into
// the union directly; one that shrank makes the union be rebuilt from cached per-block unions.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mapping/internal/map_core.h"
#include "mapping/polygon_set.h"

namespace toponav::mapping::internal {

constexpr size_t kUnionBlock = 16;  // observations per cached partial union

class KnownSpace {
 public:
  // Brings the known space up to date with map state 'ms', rebuilding around vertices that drifted farther
  // than 'tolerance' (0: exact).
  void Update(const MapCore& m, const MapState& ms, double tolerance);
  const PolygonSet& total() const { return total_; }

 private:
  // An observation's S_c and what it was built from.
  struct Piece {
    std::vector<int> ids;        // the hypothetical observation
    std::vector<uint64_t> walls; // open region: the walls and open sides that bounded its polygon
    PolygonSet sc;
    bool valid = false;
  };
  struct Changes {
    std::vector<int> vertices, candidates;  // ascending
    std::vector<Wall> walls;
  };
  Changes FindChanges(const MapCore& m, const MapState& ms, const std::vector<Wall>& closing, double tolerance);
  bool NeedsCheck(const MapCore& m, size_t i, const Changes& c) const;
  // Recomputes observation i's piece; returns false if the new piece does not contain the old one.
  bool Recompute(const MapCore& m, size_t i, const MapState& ms, const std::vector<Wall>& closing, const Changes& c,
                 bool* changed);
  void RebuildUnion(const MapCore& m);

  std::vector<Piece> pieces_;                // per observation
  std::vector<PolygonSet> blocks_;           // union of kUnionBlock consecutive pieces
  std::vector<char> block_dirty_;
  std::vector<PolygonSet> union_tree_;       // binary tree over the blocks: node k = union of 2k and 2k+1
  std::vector<char> tree_dirty_;
  PolygonSet total_;
  bool total_valid_ = false;                 // false: rebuild from the blocks on the next update
  std::vector<char> snap_mapped_;            // map membership at the last update ...
  std::vector<char> snap_member_;            // ... and membership of hypothetical observations (map vertices,
                                             // and seen candidates with known_space_candidates)
  std::vector<core::Vec2> drift_ref_;        // where each vertex was when its drift was last flagged
  std::vector<Wall> snap_walls_;
};

}  // namespace toponav::mapping::internal
