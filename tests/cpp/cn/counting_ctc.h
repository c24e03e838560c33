#pragma once
// Test helper: a contractor that counts the boxes it contracts.
#include <atomic>
#include <memory>
#include <string>

#include "sillage/ctc/ctc.h"

namespace sillage::test {

class Counting : public Ctc {
 public:
  explicit Counting(std::shared_ptr<const Ctc> c) : Ctc(c->nb_vars()), c_(std::move(c)) {}
  void contract(IntervalVector& x) const override {
    ++calls;
    c_->contract(x);
  }
  std::string name() const override { return "Counting(" + c_->name() + ")"; }
  mutable std::atomic<int> calls{0};

 private:
  std::shared_ptr<const Ctc> c_;
};

}  // namespace sillage::test
