#include "sillage/ctc/sep_ctc_pair.h"

namespace sillage {

namespace {

std::size_t pair_nb_vars(const std::shared_ptr<const Ctc>& in, const std::shared_ptr<const Ctc>& out) {
  if (!in || !out) throw Error("SepCtcPair: a contractor is null");
  if (in->nb_vars() != out->nb_vars()) {
    throw DimensionError("SepCtcPair: the inner contractor acts on " + std::to_string(in->nb_vars()) +
                         " variables, the outer one on " + std::to_string(out->nb_vars()));
  }
  return in->nb_vars();
}

}  // namespace

SepCtcPair::SepCtcPair(std::shared_ptr<const Ctc> ctc_in, std::shared_ptr<const Ctc> ctc_out)
    : Sep(pair_nb_vars(ctc_in, ctc_out)), in_(std::move(ctc_in)), out_(std::move(ctc_out)) {}

void SepCtcPair::separate(IntervalVector& x_in, IntervalVector& x_out) const {
  check_dim(x_in, x_out);
  in_->contract(x_in);
  out_->contract(x_out);
}

}  // namespace sillage
