#include "sillage/cn/domain.h"

#include "sillage/error.h"

namespace sillage {

EmptyOnInput Domain::empty_on_input() const {
  if (!is_empty()) return {};
  for (std::size_t a = 0; a < nb_atoms(); ++a) {
    if (atom(a).is_empty()) return {true, a};
  }
  return {true};
}

IntervalDomain::IntervalDomain(std::shared_ptr<Interval> x) : x_(std::move(x)) {
  if (!x_) throw Error("ContractorNetwork: null Interval domain");
}

BoxDomain::BoxDomain(std::shared_ptr<IntervalVector> x) : x_(std::move(x)), size_(x_ ? x_->size() : 0) {
  if (!x_) throw Error("ContractorNetwork: null IntervalVector domain");
}

void BoxDomain::set_atom(std::size_t i, const Interval& x) {
  if (x.is_empty()) {
    x_->set_empty();
  } else {
    (*x_)[i] = x;
  }
}

std::string AtomPlace::str() const {
  if (kind.empty()) return "";
  std::string s = kind + " " + std::to_string(index);
  if (kind == "slice") s.append(" ").append(time.str());
  if (kind == "gate") s.append(" (t = ").append(number_text(time.lb())).append(")");
  return s;
}

AtomPlace BoxDomain::place(std::size_t i) const {
  if (size_ == 1) return {};
  return {"component", i, Interval::empty()};
}

std::string BoxDomain::kind() const { return "IntervalVector(" + std::to_string(size_) + ")"; }

void BoxDomain::check_layout(const std::string& label) const {
  if (x_->size() != size_) {
    throw DimensionError("ContractorNetwork: " + label + " was registered with size " + std::to_string(size_) +
                         " but now has size " + std::to_string(x_->size()));
  }
}

}  // namespace sillage
