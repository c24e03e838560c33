#pragma once
// TubeComponents: the components of a TubeVector, each a heap object of its
// own. A component keeps its address for the life of the vector, whatever is
// assigned to the vector: assignment assigns into the existing components
// (adding or dropping components at the end when the sizes differ). So a
// reference to a component, a shared_ptr to it (shared()) or a network domain
// on it stays valid; only the slot array, never a Tube, is reallocated.
//
// Value semantics like std::vector<Tube>: copies never share components.
#include <cstddef>
#include <iterator>
#include <memory>
#include <vector>

#include "sillage/tube/tube.h"

namespace sillage {

class TubeComponents {
 public:
  // Iterates the tubes (Tube& or const Tube&), not the pointers.
  template <class T>
  class Iterator {
   public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = Tube;
    using difference_type = std::ptrdiff_t;
    using pointer = T*;
    using reference = T&;
    using Base = std::vector<std::shared_ptr<Tube>>::const_iterator;
    Iterator() = default;
    explicit Iterator(Base it) : it_(it) {}
    T& operator*() const { return **it_; }
    T* operator->() const { return it_->get(); }
    T& operator[](difference_type n) const { return *it_[n]; }
    Iterator& operator++() { return ++it_, *this; }
    Iterator operator++(int) { return Iterator(it_++); }
    Iterator& operator--() { return --it_, *this; }
    Iterator operator--(int) { return Iterator(it_--); }
    Iterator& operator+=(difference_type n) { return it_ += n, *this; }
    Iterator& operator-=(difference_type n) { return it_ -= n, *this; }
    friend Iterator operator+(Iterator a, difference_type n) { return a += n; }
    friend Iterator operator+(difference_type n, Iterator a) { return a += n; }
    friend Iterator operator-(Iterator a, difference_type n) { return a -= n; }
    friend difference_type operator-(const Iterator& a, const Iterator& b) { return a.it_ - b.it_; }
    friend bool operator==(const Iterator& a, const Iterator& b) { return a.it_ == b.it_; }
    friend auto operator<=>(const Iterator& a, const Iterator& b) { return a.it_ <=> b.it_; }

   private:
    Base it_;
  };
  using iterator = Iterator<Tube>;
  using const_iterator = Iterator<const Tube>;

  TubeComponents() = default;
  // Each tube moved into a heap object of its own.
  TubeComponents(std::vector<Tube> tubes);  // NOLINT: implicit, as the vector it replaces
  TubeComponents(const TubeComponents& x);
  TubeComponents(TubeComponents&& x) noexcept = default;
  TubeComponents& operator=(const TubeComponents& x);
  TubeComponents& operator=(TubeComponents&& x);
  ~TubeComponents() = default;

  std::size_t size() const { return p_.size(); }
  bool empty() const { return p_.empty(); }
  Tube& operator[](std::size_t i) { return *p_[i]; }
  const Tube& operator[](std::size_t i) const { return *p_[i]; }
  Tube& front() { return *p_.front(); }
  const Tube& front() const { return *p_.front(); }
  // Component i, shared (i < size() unchecked).
  const std::shared_ptr<Tube>& shared(std::size_t i) const { return p_[i]; }

  iterator begin() { return iterator(p_.cbegin()); }
  iterator end() { return iterator(p_.cend()); }
  const_iterator begin() const { return const_iterator(p_.cbegin()); }
  const_iterator end() const { return const_iterator(p_.cend()); }

  // Component-wise (Tube::operator==).
  bool operator==(const TubeComponents& y) const;

 private:
  std::vector<std::shared_ptr<Tube>> p_;
};

}  // namespace sillage
