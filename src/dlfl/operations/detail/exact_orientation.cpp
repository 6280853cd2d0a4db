// Exact signs by expansion arithmetic: a value is kept as a sum of doubles of increasing magnitude whose
// bits do not overlap, so that adding a double or a product of two doubles to it loses nothing (Knuth's
// two-sum, Dekker's two-product, Shewchuk's grow-expansion with zero elimination), and its sign is that of
// its largest term.

#include <dlfl/operations/detail/exact_orientation.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace dlfl::detail {
namespace {

// hi + lo, exactly, with hi the rounded value.
struct Pair {
  double hi, lo;
};

Pair two_sum(double a, double b) {
  const double x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  return {x, (a - a_virtual) + (b - b_virtual)};
}

// a = hi + lo with hi and lo of at most 26 significant bits each, so that their products are exact.
Pair split(double a) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  const double hi = c - (c - a);
  return {hi, a - hi};
}

Pair two_product(double a, double b) {
  const double x = a * b;
  const Pair sa = split(a), sb = split(b);
  return {x, sa.lo * sb.lo - (((x - sa.hi * sb.hi) - sa.lo * sb.hi) - sa.hi * sb.lo)};
}

// Sums of products of the coordinates span fewer than 1100 binary orders of magnitude in the range the
// header states (from 2^-1074 up), and terms do not overlap, so they never number more.
constexpr std::size_t capacity = 1100;

class Expansion {
 public:
  // Grow-expansion: the new double runs through the terms from the smallest, each two-sum leaving an exact
  // remainder behind; zero remainders are dropped.
  void add(double b) {
    double q = b;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < size_; ++i) {
      const Pair s = two_sum(q, terms_[i]);
      q = s.hi;
      if (s.lo != 0.0) terms_[kept++] = s.lo;
    }
    if (q != 0.0) {
      if (kept == capacity) throw std::logic_error("exact_orientation: expansion capacity exceeded");
      terms_[kept++] = q;
    }
    size_ = kept;
  }

  void add_product(double a, double b) {
    const Pair p = two_product(a, b);
    add(p.lo);
    add(p.hi);
  }

  std::size_t size() const { return size_; }
  double operator[](std::size_t i) const { return terms_[i]; }

  int sign() const {
    if (size_ == 0) return 0;
    return terms_[size_ - 1] > 0.0 ? 1 : -1;
  }

 private:
  std::array<double, capacity> terms_;
  std::size_t size_ = 0;
};

// b - a, exactly.
Pair difference(double b, double a) { return two_sum(b, -a); }

// Adds sign x p x q to e, p and q exact pairs.
void add_product(Expansion& e, const Pair& p, const Pair& q, double sign) {
  e.add_product(sign * p.hi, q.hi);
  e.add_product(sign * p.hi, q.lo);
  e.add_product(sign * p.lo, q.hi);
  e.add_product(sign * p.lo, q.lo);
}

std::array<Pair, 3> difference(const glm::dvec3& b, const glm::dvec3& a) {
  return {difference(b.x, a.x), difference(b.y, a.y), difference(b.z, a.z)};
}

}  // namespace

int orient3d_exact(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  const std::array<Pair, 3> u = difference(b, a), v = difference(c, a), w = difference(d, a);
  // det = sum over k of w_k (u x v)_k, each minor (u x v)_k exact, then multiplied term by term.
  Expansion det;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    Expansion minor;
    add_product(minor, u[i], v[j], 1.0);
    add_product(minor, u[j], v[i], -1.0);
    for (std::size_t t = 0; t < minor.size(); ++t) {
      det.add_product(w[k].hi, minor[t]);
      det.add_product(w[k].lo, minor[t]);
    }
  }
  return det.sign();
}

int orient3d_filter(const glm::dvec3& u, const glm::dvec3& v, const glm::dvec3& w) {
  const double m0 = u.y * v.z, m1 = u.z * v.y, m2 = u.z * v.x, m3 = u.x * v.z, m4 = u.x * v.y, m5 = u.y * v.x;
  const double det = w.x * (m0 - m1) + w.y * (m2 - m3) + w.z * (m4 - m5);
  const double permanent = std::abs(w.x) * (std::abs(m0) + std::abs(m1)) +
                           std::abs(w.y) * (std::abs(m2) + std::abs(m3)) +
                           std::abs(w.z) * (std::abs(m4) + std::abs(m5));
  const double bound = orient3d_error_bound * permanent;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  if (permanent == 0.0) return 0;  // every product has a zero factor: the determinant is exactly 0
  return 2;
}

int orient3d(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  const int sign = orient3d_filter(b - a, c - a, d - a);
  return sign != 2 ? sign : orient3d_exact(a, b, c, d);
}

bool collinear(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const std::array<Pair, 3> u = difference(b, a), v = difference(c, a);
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    Expansion area;
    add_product(area, u[i], v[j], 1.0);
    add_product(area, u[j], v[i], -1.0);
    if (area.sign() != 0) return false;
  }
  return true;
}

}  // namespace dlfl::detail
