#include "sillage/error.h"
#include "sillage/paving/contour.h"

#include <algorithm>
#include <sstream>
#include <tuple>

namespace sillage {

namespace {

// Directions in counter-clockwise order, so that a left turn is d + 1.
enum Dir : int { kPosX = 0, kPosY = 1, kNegX = 2, kNegY = 3 };

struct RawEdge {
  Point2 a, b;
  int dir;
};

// A box side lying on an axis-parallel line; `plus` when the box is on the
// + side of the line (left or bottom side of the box).
struct Side {
  double line, lo, hi;
  bool plus;
};

RawEdge make_edge(bool vertical, double line, double lo, double hi, bool plus) {
  // The region must lie on the left of the edge: a vertical side with the
  // region on +x runs downwards, a horizontal side with the region on +y
  // runs towards +x.
  if (vertical) {
    return plus ? RawEdge{{line, hi}, {line, lo}, kNegY} : RawEdge{{line, lo}, {line, hi}, kPosY};
  }
  return plus ? RawEdge{{lo, line}, {hi, line}, kPosX} : RawEdge{{hi, line}, {lo, line}, kNegX};
}

// On each line, the boundary is where exactly one of the two sides (boxes on
// the + side, boxes on the - side) is covered.
void boundary_pieces(std::vector<Side>& sides, bool vertical, std::vector<RawEdge>& out) {
  std::sort(sides.begin(), sides.end(),
            [](const Side& s, const Side& t) { return std::tie(s.line, s.lo) < std::tie(t.line, t.lo); });
  struct Event {
    double at;
    bool plus;
    int delta;
  };
  std::vector<Event> events;
  for (std::size_t g = 0; g < sides.size();) {
    std::size_t h = g;
    events.clear();
    for (; h < sides.size() && sides[h].line == sides[g].line; ++h) {
      events.push_back({sides[h].lo, sides[h].plus, +1});
      events.push_back({sides[h].hi, sides[h].plus, -1});
    }
    std::sort(events.begin(), events.end(), [](const Event& e, const Event& f) { return e.at < f.at; });
    int cover[2] = {0, 0};
    bool open = false;  // a boundary piece is being extended
    bool open_plus = false;
    double open_lo = 0;
    for (std::size_t k = 0; k < events.size();) {
      const double at = events[k].at;
      for (; k < events.size() && events[k].at == at; ++k) cover[events[k].plus ? 1 : 0] += events[k].delta;
      if (cover[0] > 1 || cover[1] > 1) {
        throw Error("contour: overlapping boxes on the line " + std::string(vertical ? "x = " : "y = ") +
                    number_text(sides[g].line) + " near " + number_text(at));
      }
      const bool is_boundary = (cover[0] > 0) != (cover[1] > 0);
      const bool plus = cover[1] > 0;
      // Close the current piece when the boundary stops or changes side; a
      // straight run of pieces is one maximal segment.
      if (open && (!is_boundary || plus != open_plus)) {
        out.push_back(make_edge(vertical, sides[g].line, open_lo, at, open_plus));
        open = false;
      }
      if (is_boundary && !open) {
        open = true;
        open_plus = plus;
        open_lo = at;
      }
    }
    g = h;
  }
}

bool point_less(const Point2& p, const Point2& q) { return std::tie(p.x, p.y) < std::tie(q.x, q.y); }

}  // namespace

IntervalVector ContourEdge::box() const {
  return IntervalVector{Interval(std::min(a.x, b.x), std::max(a.x, b.x)),
                        Interval(std::min(a.y, b.y), std::max(a.y, b.y))};
}

double ContourEdge::length() const { return std::abs(b.x - a.x) + std::abs(b.y - a.y); }

std::vector<Point2> ContourLoop::vertices() const {
  std::vector<Point2> v;
  v.reserve(edges.size());
  for (const auto& e : edges) v.push_back(e.a);
  return v;
}

double ContourLoop::length() const {
  double s = 0;
  for (const auto& e : edges) s += e.length();
  return s;
}

std::string ContourLoop::str() const {
  std::ostringstream os;
  os << (is_hole ? "hole" : "outer") << ":";
  for (const auto& e : edges) os << " (" << number_text(e.a.x) << "," << number_text(e.a.y) << ")";
  return os.str();
}

std::vector<ContourLoop> contour(const std::vector<IntervalVector>& boxes, const CancelToken& cancel) {
  const auto check = [&](std::size_t i) {
    if (i % 1024 == 0) check_cancel(cancel, "contour");
  };
  std::vector<Side> vertical, horizontal;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    check(i);
    const IntervalVector& b = boxes[i];
    if (b.size() != 2) {
      throw DimensionError("contour: box " + std::to_string(i) + " has dimension " + std::to_string(b.size()) +
                           ", contours are defined for 2-D boxes");
    }
    if (b.is_empty()) continue;
    if (b.is_unbounded()) throw Error("contour: box " + std::to_string(i) + " " + b.str() + " is unbounded");
    if (b[0].is_degenerate() || b[1].is_degenerate()) continue;  // no interior
    vertical.push_back({b[0].lb(), b[1].lb(), b[1].ub(), true});
    vertical.push_back({b[0].ub(), b[1].lb(), b[1].ub(), false});
    horizontal.push_back({b[1].lb(), b[0].lb(), b[0].ub(), true});
    horizontal.push_back({b[1].ub(), b[0].lb(), b[0].ub(), false});
  }
  std::vector<RawEdge> edges;
  boundary_pieces(vertical, true, edges);
  check(0);  // between the sorts, each of tens of milliseconds on 10^5 boxes
  boundary_pieces(horizontal, false, edges);
  check(0);

  // Deterministic edge order: by start point, then direction.
  std::sort(edges.begin(), edges.end(), [](const RawEdge& e, const RawEdge& f) {
    return std::tie(e.a.x, e.a.y, e.dir) < std::tie(f.a.x, f.a.y, f.dir);
  });
  const std::size_t m = edges.size();
  // next[e]: the outgoing edge at e.b with the rightmost turn (right, straight, left).
  std::vector<std::size_t> next(m), prev_count(m, 0);
  for (std::size_t e = 0; e < m; ++e) {
    check(e);
    auto lo = std::lower_bound(edges.begin(), edges.end(), edges[e].b,
                               [](const RawEdge& f, const Point2& p) { return point_less(f.a, p); });
    std::size_t best = m;
    int best_rank = 4;
    for (auto it = lo; it != edges.end() && it->a == edges[e].b; ++it) {
      const int turn = (it->dir - edges[e].dir + 4) % 4;  // 1 left, 0 straight, 3 right, 2 back
      const int rank = turn == 3 ? 0 : turn == 0 ? 1 : turn == 1 ? 2 : 3;
      if (rank < best_rank) {
        best_rank = rank;
        best = static_cast<std::size_t>(it - edges.begin());
      }
    }
    if (best == m || best_rank == 3) {
      throw Error("contour: open boundary at (" + number_text(edges[e].b.x) + ", " + number_text(edges[e].b.y) +
                  "); are the boxes a valid subpaving?");
    }
    next[e] = best;
    ++prev_count[best];
  }
  for (std::size_t e = 0; e < m; ++e) {
    if (prev_count[e] != 1) {
      throw Error("contour: inconsistent boundary at (" + number_text(edges[e].a.x) + ", " + number_text(edges[e].a.y) + ")");
    }
  }

  std::vector<ContourLoop> loops;
  std::vector<bool> used(m, false);
  for (std::size_t s = 0; s < m; ++s) {
    check(s);
    if (used[s]) continue;
    std::vector<std::size_t> cycle;
    for (std::size_t e = s; !used[e]; e = next[e]) {
      used[e] = true;
      cycle.push_back(e);
    }
    // Merge collinear consecutive edges (a safety net: pieces are already maximal).
    std::vector<RawEdge> merged;
    for (std::size_t e : cycle) {
      if (!merged.empty() && merged.back().dir == edges[e].dir) {
        merged.back().b = edges[e].b;
      } else {
        merged.push_back(edges[e]);
      }
    }
    if (merged.size() > 1 && merged.back().dir == merged.front().dir) {
      merged.front().a = merged.back().a;
      merged.pop_back();
    }
    // Start at the smallest vertex; there the loop turns left (outer, goes +x)
    // or right (hole, goes +y).
    std::size_t start = 0;
    for (std::size_t k = 1; k < merged.size(); ++k) {
      if (point_less(merged[k].a, merged[start].a)) start = k;
    }
    std::rotate(merged.begin(), merged.begin() + static_cast<std::ptrdiff_t>(start), merged.end());
    ContourLoop loop;
    loop.is_hole = merged.front().dir == kPosY;
    for (const auto& e : merged) loop.edges.push_back({e.a, e.b});
    loops.push_back(std::move(loop));
  }
  std::sort(loops.begin(), loops.end(), [](const ContourLoop& p, const ContourLoop& q) {
    const Point2 &a = p.edges.front().a, &b = q.edges.front().a;
    return std::tie(p.is_hole, a.x, a.y) < std::tie(q.is_hole, b.x, b.y);
  });
  return loops;
}

}  // namespace sillage
