// One outcome for long computations (outcome.h): a SIVIA on a small budget
// stops with the paving so far (Status::Stopped and its reason), still an
// enclosure of the full paving's solution set; a ContractorNetwork's
// contract_run() reports every round to a progress hook and ends with a
// Summary instead of throwing.
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "example_args.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/figures/figure.h"
#include "sillage/paving/sivia_function.h"

using namespace sillage;

namespace {

// x = y and y = 0.9 x from [0, 1000] (the solution {0}), 12 contractor calls at most.
bool network_rounds(std::string& line) {
  ContractorNetwork cn;
  const auto x = cn.create_dom(Interval(0, 1000), "x");
  const auto y = cn.create_dom(Interval(0, 1000), "y");
  cn.add(std::make_shared<CtcFunction>(Function({"a", "b"}, "a - b")), {x, y});
  cn.add(std::make_shared<CtcFunction>(Function({"a", "b"}, "b - 0.9*a")), {x, y});
  std::vector<std::size_t> rounds;
  Budget b;
  b.max_boxes = 12;
  b.progress = [&](const Progress& p) {  // once per round
    rounds.push_back(p.round);
    std::printf("    %s round %zu: %zu contractor calls, x = %s\n", p.where, p.round, p.work, x->str().c_str());
  };
  cn.set_budget(b);
  const ContractStats stats = cn.contract_run();
  std::printf("  %s\n", stats.summary.str().c_str());
  bool in_order = true;
  for (std::size_t k = 0; k < rounds.size(); ++k) in_order = in_order && rounds[k] == k + 1;
  line = std::string(status_name(stats.summary.status)) + " after " + std::to_string(rounds.size()) + " rounds";
  return stats.summary.status == Status::Stopped && in_order && x->contains(0.0);
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  // The two-beacon set inversion (sivia_two_beacons), in full and on a budget of 400 boxes.
  const IntervalVector x0{{-10, 14}, {-10, 10}};
  const Function g({"x1", "x2"}, "(sqrt((x1 - 8)^2 + (x2 - 5)^2), sqrt((x1 - 7)^2 + (x2 - 2.2)^2))");
  const IntervalVector y{{9.03, 9.83}, {6.94, 7.74}};
  SiviaOptions small;
  small.budget.max_boxes = 400;
  const SiviaResult full = sivia_run(x0, g, y, 0.01);
  const SiviaResult partial = sivia_run(x0, g, y, 0.01, small);

  std::printf("SIVIA of the two-beacon problem (eps = 0.01), in full and on a budget of 400 boxes:\n");
  // The robot (0, 0) and its mirror image across the beacons' line: in X+ of both pavings.
  const std::vector<Vector> robot{{0.0, 0.0}, {11.0230, -3.9367}};
  bool ok = full.summary.status == Status::Converged && partial.summary.status == Status::Stopped &&
            partial.paving.outer_volume() >= full.paving.outer_volume();
  std::vector<std::pair<std::string, std::string>> figures;
  for (const auto& [label, r, file] : {std::tuple{"full", &full, "outcome_budget_full.svg"},
                                       std::tuple{"budget", &partial, "outcome_budget_stopped.svg"}}) {
    const Paving& p = r->paving;
    std::printf("  %-7s %-9s %5zu leaves, vol(X+) = %8.4f, vol(X-) = %7.4f  %s\n", label,
                status_name(r->summary.status), p.nb_leaves(), p.outer_volume(), p.volume(PavingTag::Inner),
                r->summary.reason.c_str());
    for (const Vector& q : robot) {
      const auto tag = p.tag_at(q);
      ok = ok && tag && *tag != PavingTag::Outside;
    }
    Figure fig(x0);
    fig.set_title(std::string(status_name(r->summary.status)) + ": " + std::to_string(p.nb_leaves()) + " leaves");
    fig.draw_paving(p);
    for (const Vector& q : robot) fig.draw_point(q, 3.0);
    fig.save((out / file).string());
    figures.push_back({file, std::string("SIVIA ") + status_name(r->summary.status) +
                                 ": inner green, boundary yellow (not yet classified once stopped), outside blue"});
  }

  std::printf("ContractorNetwork::contract_run() with a progress hook (once per round), 12 contractor calls at most:\n");
  std::string network;
  ok = network_rounds(network) && ok;
  example::print_result("outcome_budget",
                        std::string("SIVIA ") + status_name(full.summary.status) + " " +
                            std::to_string(full.paving.nb_leaves()) + " leaves, on a budget " +
                            status_name(partial.summary.status) + " " + std::to_string(partial.paving.nb_leaves()) +
                            "; network " + network,
                        ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
