// The network node of CtcIvp: cn.add(ctc, {x}) or cn.add(ctc, {x, u}), x
// with the n states (a tube, tube components or a tube vector), u with the
// m inputs. It runs again when a gate or slice of x or u changes (a gate
// known better starts the integration again from it), and re-integrates
// only from the first change forward and from the last one backward: the
// node remembers its last run (ivp_memory.h), behind a mutex since a node
// may be shared; the memory checks itself, a stale one is never used. The
// network's cancel token stops a run within one integration step.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "sillage/cn/tube_node.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/dynamics/ivp_memory.h"
#include "sillage/error.h"

namespace sillage {


namespace {

class IvpNode : public TubeNode {
 public:
  IvpNode(const CtcIvp& ctc, const std::vector<BoundDomain>& args) : TubeNode(ctc.name(), args), ctc_(ctc) {
    const std::size_t n = ctc.nb_states(), m = ctc.nb_inputs();
    if (args.size() != n + m) {
      throw DimensionError(where() + ": expects x with " + std::to_string(n) + " components then u with " +
                           std::to_string(m) + ", got " + std::to_string(args.size()) + " tubes");
    }
    x_ = whole_tubes(0, n, "x");
    if (m > 0) u_ = whole_tubes(n, m, "u");
  }

  bool run(NodeRun& r) const override {
    std::vector<Tube> xs, us;
    for (const auto& d : x_) xs.push_back(d->tube());
    TubeVector x(std::move(xs));
    bool ok = true;
    {
      const std::lock_guard<std::mutex> lock(*mutex_);
      if (u_.empty()) {
        ok = ctc_.contract(x, nullptr, *memory_, r.cancel_token());
      } else {
        for (const auto& d : u_) us.push_back(d->tube());
        const TubeVector u(std::move(us));
        ok = ctc_.contract(x, &u, *memory_, r.cancel_token());
      }
    }
    for (std::size_t i = 0; i < x_.size(); ++i) {
      const bool alive = contract_tube(r, i, [&](Tube& xi) {
        xi &= x[i];
        return ok && !xi.is_empty();
      });
      if (!alive) return false;
    }
    return true;
  }

 private:
  CtcIvp ctc_;
  std::shared_ptr<std::mutex> mutex_ = std::make_shared<std::mutex>();
  std::shared_ptr<detail::IvpMemory> memory_ = std::make_shared<detail::IvpMemory>();
  std::vector<std::shared_ptr<TubeDomain>> x_, u_;
};

}  // namespace

std::shared_ptr<const CnNode> CtcIvp::make_node(const std::vector<BoundDomain>& args) const {
  return std::make_shared<IvpNode>(*this, args);
}

}  // namespace sillage
