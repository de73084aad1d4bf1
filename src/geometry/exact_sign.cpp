#include "geometry/exact_sign.hpp"

#include <array>
#include <cassert>
#include <cstddef>

namespace cardemo {
namespace {

constexpr std::size_t kMaxTerms = 8;

// x + y == a + b exactly, with x = fl(a + b) (Knuth's TwoSum).
void twoSum(double a, double b, double& x, double& y) {
  x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  y = (a - a_virtual) + (b - b_virtual);
}

// a == hi + lo, each with at most 26 significant bits (Dekker's split; 2^27 + 1).
void split(double a, double& hi, double& lo) {
  const double c = 134217729.0 * a;
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// x + y == a * b exactly, with x = fl(a * b), without a fused multiply-add (Dekker).
void twoProduct(double a, double b, double& x, double& y) {
  x = a * b;
  double a_hi = 0.0;
  double a_lo = 0.0;
  double b_hi = 0.0;
  double b_lo = 0.0;
  split(a, a_hi, a_lo);
  split(b, b_hi, b_lo);
  const double err1 = x - a_hi * b_hi;
  const double err2 = err1 - a_lo * b_hi;
  const double err3 = err2 - a_hi * b_lo;
  y = a_lo * b_lo - err3;
}

// An expansion: components of increasing magnitude that do not overlap; its value is their sum
// and its sign is that of its largest nonzero component.
class Expansion {
 public:
  void add(double b) {
    // Grow-Expansion (Shewchuk, section 2.5), dropping zero components.
    double q = b;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < size_; ++i) {
      double h = 0.0;
      twoSum(q, parts_[i], q, h);
      if (h != 0.0) parts_[kept++] = h;
    }
    if (q != 0.0) parts_[kept++] = q;
    size_ = kept;
  }
  [[nodiscard]] int sign() const {
    if (size_ == 0) return 0;
    return parts_[size_ - 1] > 0.0 ? 1 : -1;
  }

 private:
  std::array<double, 2 * kMaxTerms + 1> parts_{};
  std::size_t size_ = 0;
};

}  // namespace

int signOfProductSum(std::span<const ProductTerm> terms) {
  assert(terms.size() <= kMaxTerms);
  Expansion sum;
  for (const auto& [a, b] : terms) {
    double x = 0.0;
    double y = 0.0;
    twoProduct(a, b, x, y);
    sum.add(y);
    sum.add(x);
  }
  return sum.sign();
}

int orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  // (b - a) x (c - a) multiplied out; the a.x * a.y terms cancel, so no difference is rounded.
  const std::array<ProductTerm, 6> terms{{{b.x(), c.y()},
                                          {-b.x(), a.y()},
                                          {-a.x(), c.y()},
                                          {-b.y(), c.x()},
                                          {b.y(), a.x()},
                                          {a.y(), c.x()}}};
  return signOfProductSum(terms);
}

int signOfAdvance(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                  const Eigen::Vector2d& direction) {
  const std::array<ProductTerm, 4> terms{{{to.x(), direction.x()},
                                          {-from.x(), direction.x()},
                                          {to.y(), direction.y()},
                                          {-from.y(), direction.y()}}};
  return signOfProductSum(terms);
}

}  // namespace cardemo
