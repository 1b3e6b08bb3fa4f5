// The only translation unit that includes CGAL (it costs ~85 s to compile: keep it that way).
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/version.h>

#include "core/error.h"
#include "mapping/polygon_set.h"

namespace toponav::mapping {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using CPoint = Kernel::Point_2;
using CPolygon = CGAL::Polygon_2<Kernel>;
using CPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using CPolygonSet = CGAL::Polygon_set_2<Kernel>;

struct PolygonSet::Impl {
  CPolygonSet set;
};

namespace {
CPolygon ToCgal(const core::Ring& ring, bool want_ccw, bool check_simple = true) {
  if (ring.size() < 3) throw core::DataError("<polygon>", "a polygon needs at least 3 points");
  CPolygon p;
  for (const auto& v : ring) p.push_back(CPoint(v.x, v.y));
  if (check_simple && !p.is_simple()) throw core::DataError("<polygon>", "polygon is not simple (self-intersecting)");
  if ((p.orientation() == CGAL::COUNTERCLOCKWISE) != want_ccw) p.reverse_orientation();
  // The Boolean operations' own validity test (they crash, not throw, on input that fails it).
  if (check_simple && want_ccw && !CGAL::is_valid_polygon(p, CPolygonSet::Traits_2()))
    throw core::DataError("<polygon>", "polygon is not valid for exact Booleans (degenerate edges)");
  return p;
}
core::Ring ToRing(const CPolygon& p) {
  core::Ring r;
  for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it)
    r.push_back({CGAL::to_double(it->x()), CGAL::to_double(it->y())});
  return r;
}
}  // namespace

PolygonSet::PolygonSet() : impl_(std::make_unique<Impl>()) {}
PolygonSet::~PolygonSet() = default;
PolygonSet::PolygonSet(const PolygonSet& o) : impl_(std::make_unique<Impl>(*o.impl_)) {}
PolygonSet& PolygonSet::operator=(const PolygonSet& o) {
  if (this != &o) *impl_ = *o.impl_;
  return *this;
}
PolygonSet::PolygonSet(PolygonSet&&) noexcept = default;
PolygonSet& PolygonSet::operator=(PolygonSet&&) noexcept = default;

PolygonSet PolygonSet::FromRing(const core::Ring& ring) {
  PolygonSet s;
  s.impl_->set.insert(ToCgal(ring, true));
  return s;
}

PolygonSet PolygonSet::FromPolygon(const core::Polygon& polygon, bool check_simple) {
  CPolygonWithHoles pwh(ToCgal(polygon.outer, true, check_simple));
  for (const auto& h : polygon.holes) pwh.add_hole(ToCgal(h, false, check_simple));
  PolygonSet s;
  s.impl_->set.insert(pwh);
  return s;
}

void PolygonSet::Join(const PolygonSet& o) { impl_->set.join(o.impl_->set); }
void PolygonSet::Intersect(const PolygonSet& o) { impl_->set.intersection(o.impl_->set); }
void PolygonSet::Difference(const PolygonSet& o) { impl_->set.difference(o.impl_->set); }

PolygonSet PolygonSet::JoinAll(const std::vector<PolygonSet>& sets) {
  std::vector<const PolygonSet*> p;
  p.reserve(sets.size());
  for (const auto& s : sets) p.push_back(&s);
  return JoinAll(p);
}

PolygonSet PolygonSet::JoinAll(const std::vector<const PolygonSet*>& sets) {
  // Pairwise joins in a balanced tree: each is an overlay of two arrangements.  (Re-inserting the sets'
  // polygons with holes into one aggregated join crashes inside CGAL 5.5 when a boundary touches itself at a
  // vertex, which the sets' own output may do.)  CGAL's sets have no move constructor (a "move" copies the
  // arrangement), so the tree holds PolygonSets, whose moves pass a pointer: the inputs are copied once, as
  // the left operand of each first-level pair, and nothing after.
  std::vector<const PolygonSet*> in;
  for (const PolygonSet* s : sets)
    if (s && !s->impl_->set.is_empty()) in.push_back(s);
  if (in.empty()) return PolygonSet();
  std::vector<PolygonSet> level;
  level.reserve((in.size() + 1) / 2);
  for (size_t i = 0; i + 1 < in.size(); i += 2) {
    level.push_back(*in[i]);
    level.back().impl_->set.join(in[i + 1]->impl_->set);
  }
  if (in.size() % 2) level.push_back(*in.back());
  while (level.size() > 1) {
    std::vector<PolygonSet> next;
    next.reserve((level.size() + 1) / 2);
    for (size_t i = 0; i + 1 < level.size(); i += 2) {
      next.push_back(std::move(level[i]));
      next.back().impl_->set.join(level[i + 1].impl_->set);
    }
    if (level.size() % 2) next.push_back(std::move(level.back()));
    level = std::move(next);
  }
  return std::move(level[0]);
}

PolygonSet PolygonSet::Holes() const {
  // The bounded faces of the complement, taken exactly (converting the hole rings to doubles and back could
  // make a ring that touches itself cross itself).
  CPolygonSet complement = impl_->set;
  complement.complement();
  std::vector<CPolygonWithHoles> parts;
  complement.polygons_with_holes(std::back_inserter(parts));
  PolygonSet out;
  for (const auto& p : parts)
    if (!p.is_unbounded()) out.impl_->set.join(p);
  return out;
}

bool PolygonSet::empty() const { return impl_->set.is_empty(); }

double PolygonSet::Area() const {
  std::vector<CPolygonWithHoles> pwhs;
  impl_->set.polygons_with_holes(std::back_inserter(pwhs));
  double a = 0;
  for (const auto& p : pwhs) {
    a += CGAL::to_double(p.outer_boundary().area());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += CGAL::to_double(h->area());  // clockwise: negative
  }
  return a;
}

std::vector<PolygonSet> PolygonSet::Components() const {
  std::vector<CPolygonWithHoles> pwhs;
  impl_->set.polygons_with_holes(std::back_inserter(pwhs));
  std::vector<PolygonSet> out(pwhs.size());
  for (size_t i = 0; i < pwhs.size(); ++i) out[i].impl_->set.join(pwhs[i]);
  return out;
}

std::vector<core::Polygon> PolygonSet::Polygons() const {
  std::vector<CPolygonWithHoles> pwhs;
  impl_->set.polygons_with_holes(std::back_inserter(pwhs));
  std::vector<core::Polygon> out;
  for (const auto& p : pwhs) {
    core::Polygon poly;
    poly.outer = ToRing(p.outer_boundary());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) poly.holes.push_back(ToRing(*h));
    out.push_back(std::move(poly));
  }
  return out;
}

bool PolygonSet::Contains(const core::Vec2& p) const {
  return impl_->set.oriented_side(CPoint(p.x, p.y)) != CGAL::ON_NEGATIVE_SIDE;
}

double IoU(const PolygonSet& a, const PolygonSet& b) {
  PolygonSet i = a, u = a;
  i.Intersect(b);
  u.Join(b);
  const double ua = u.Area();
  return ua > 0 ? i.Area() / ua : 0.0;
}

std::string PolygonLibraryInfo() { return "CGAL " CGAL_STRINGIZE(CGAL_VERSION); }

}  // namespace toponav::mapping
