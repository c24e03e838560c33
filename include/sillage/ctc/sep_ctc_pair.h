#pragma once
// SepCtcPair: a separator from two contractors. C_in contracts with respect to
// the complement of X (what it removes is in X), C_out with respect to X
// (what it removes is out of X).
#include <memory>

#include "sillage/ctc/ctc.h"
#include "sillage/ctc/sep.h"

namespace sillage {

class SepCtcPair : public Sep {
 public:
  SepCtcPair(std::shared_ptr<const Ctc> ctc_in, std::shared_ptr<const Ctc> ctc_out);
  void separate(IntervalVector& x_in, IntervalVector& x_out) const override;
  std::string name() const override { return "SepCtcPair"; }

 private:
  std::shared_ptr<const Ctc> in_, out_;
};

}  // namespace sillage
