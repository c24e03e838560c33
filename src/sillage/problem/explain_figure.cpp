#include "sillage/problem/explain_figure.h"

#include <algorithm>
#include <cmath>

#include "sillage/figures/tube_figure.h"

namespace sillage::detail {

namespace {

const Style kStated{"#e53935", "#b71c1c", 1.5, 0.35, "", "stated (blamed)"};
const Style kProven{"#66bb6a", "#1b5e20", 1.5, 0.35, "", "proven when relaxed"};
const Style kRows{"#ffb74d", "#e65100", 1.0, 0.25, "", "blamed rows"};

// True when a proven value's "what" is component i of var ("p[1](0)", "psi(0)", "omega over [t0, tf]").
bool is_component(const std::string& what, const std::string& var, std::size_t i) {
  if (what.rfind(var, 0) != 0) return false;
  const std::string rest = what.substr(var.size());
  if (rest.empty() || rest[0] != '[') return i == 0 && (rest.empty() || rest[0] == '(' || rest[0] == ' ');
  return rest.rfind("[" + std::to_string(i) + "]", 0) == 0;
}

}  // namespace

std::vector<FigureMark> blamed_marks(const Problem& p, const Explanation& e, const std::string& var, std::size_t i) {
  std::vector<FigureMark> marks;
  const Interval all(p.time.t0, p.time.tf);
  for (const Relaxation& r : e.relaxations) {
    for (const std::size_t k : r.items) {
      const ExplainItem& it = e.items[k];
      if (it.kind == ItemKind::Rows && !it.all_rows) {
        const std::vector<std::string>& ys = p.constraints[it.index].ys;
        if (std::find(ys.begin(), ys.end(), var) != ys.end())
          marks.push_back({IntervalVector{it.time & all, Interval()}, kRows});
        continue;
      }
      if ((it.kind != ItemKind::Gate && it.kind != ItemKind::Bound) || it.var != var) continue;
      if (it.kind == ItemKind::Bound && it.index != i) continue;
      const Interval t = it.kind == ItemKind::Gate ? it.time : all;
      for (const ProvenValue& v : r.values) {
        // A value the relaxed problem leaves unbounded says nothing against the stated one: not marked.
        if (!is_component(v.what, var, i) || !v.proven.is_bounded()) continue;
        marks.push_back({IntervalVector{t, v.stated}, kStated});
        if (v.pieces.empty()) marks.push_back({IntervalVector{t, v.proven}, kProven});
        for (const Interval& piece : v.pieces) marks.push_back({IntervalVector{t, piece}, kProven});
      }
    }
  }
  return marks;
}

Figure marked_tube_figure(const Tube& x, const std::string& name, const std::string& title,
                          const std::vector<FigureMark>& marks) {
  std::vector<Interval> ys(x.slices().begin(), x.slices().end());
  ys.insert(ys.end(), x.gates().begin(), x.gates().end());
  for (const FigureMark& m : marks)
    if (m.box[1].is_bounded()) ys.push_back(m.box[1]);
  bool clipped = false;
  const Interval wy = finite_window(ys, clipped);
  const Interval wt = x.tdomain()->t0_tf();
  Figure fig(IntervalVector{wt, wy}, 600, 300);
  fig.set_title(title);
  if (clipped) fig.set_note("Unbounded: clipped to " + wy.str());
  fig.set_labels("t (s)", name);
  draw_tube(fig, x);
  // A mark at one time (a gate) is drawn 1/200 of the time axis wide, so that it shows.
  const double min_width = wt.diam() / 200;
  for (const FigureMark& m : marks) {
    Interval t = m.box[0] & wt, y = m.box[1] & wy;
    if (t.is_empty() || y.is_empty()) continue;
    if (t.diam() < min_width) t = Interval(t.mid()).inflate(min_width / 2) & wt;
    if (y.diam() < wy.diam() / 100) y = Interval(y.mid()).inflate(wy.diam() / 200);
    fig.draw_box(IntervalVector{t, y}, m.style);
    fig.add_legend(m.style.label, m.style);
  }
  return fig;
}

}  // namespace sillage::detail
