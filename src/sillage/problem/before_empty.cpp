#include "sillage/problem/before_empty.h"

namespace sillage::detail {

std::optional<BuiltProblem> before_empty(const Problem& p, const std::vector<double>& points, double delta,
                                         const SolveOptions& o, const ContractStats& failed) {
  if (failed.empty_node == static_cast<std::size_t>(-1) || failed.contractor_calls == 0) return std::nullopt;
  BuiltProblem b = points.empty() ? build_network(p, delta) : build_network(p, points);
  if (o.scheduling) b.cn->set_scheduling(*o.scheduling);
  if (failed.contractor_calls == 1) return b;  // the first run emptied: the domains as built
  Budget cut = o.budget;
  cut.max_boxes = failed.contractor_calls - 1;  // not 0: that is no limit
  b.cn->set_budget(cut);
  const ContractStats s = b.cn->contract_run();
  if (s.empty || s.summary.status == Status::Cancelled) return std::nullopt;
  return b;
}

}  // namespace sillage::detail
