#pragma once
/// Seeded generators of 3D box pairs for the OBB SAT property tests (std::mt19937_64, fixed seeds).

#include <cmath>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>

#include "../support/random_draws.hpp"
#include "../support/test_scale.hpp"
#include "geometry/obb3.hpp"

namespace cardemo::test3 {

/// One generated pair.
struct Pair3 {
  Obb3 a;  ///< First box.
  Obb3 b;  ///< Second box.
};

using testing::logUniform;
using testing::randomSign;
using testing::scaledCount;
using testing::testScale;
using testing::uniform;

/// Uniformly distributed unit vector.
inline Eigen::Vector3d randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Eigen::Vector3d v{g(rng), g(rng), g(rng)};
    const double n = v.norm();
    if (n > 1e-3) return v / n;
  }
}

/// Uniformly distributed rotation (normalised Gaussian 4-vector), not normalised exactly.
inline Eigen::Quaterniond randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Eigen::Quaterniond q{g(rng), g(rng), g(rng), g(rng)};
    if (q.norm() > 1e-3) return q;
  }
}

/// Rotation by `angle` radians about unit `axis`.
inline Eigen::Quaterniond axisAngle(const Eigen::Vector3d& axis, double angle) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
}

/// Full sizes, each log-uniform in 1 cm..100 m (aspect ratios up to 1e4).
inline Eigen::Vector3d randomSize(std::mt19937_64& rng) {
  return {logUniform(rng, 0.01, 100.0), logUniform(rng, 0.01, 100.0), logUniform(rng, 0.01, 100.0)};
}

/// Random direction (drawn first) times a distance uniform in [lo, hi).
inline Eigen::Vector3d randomOffset(std::mt19937_64& rng, double lo, double hi) {
  const Eigen::Vector3d u = randomUnit(rng);
  return u * uniform(rng, lo, hi);
}

/// Coordinate 1e6..1e7 m from the origin on either side (the sign drawn first).
inline double farCoordinate(std::mt19937_64& rng) {
  const double sign = randomSign(rng);
  return sign * uniform(rng, 1e6, 1e7);
}

/// Centre anywhere up to 1e7 m from the origin: a third near the origin, a third at log-uniform
/// distance, a third far out (1e6..1e7 m).
inline Eigen::Vector3d randomCenter(std::mt19937_64& rng) {
  switch (rng() % 3) {
    case 0:
      return randomOffset(rng, 0.0, 10.0);
    case 1: {
      const Eigen::Vector3d u = randomUnit(rng);
      return u * logUniform(rng, 1.0, 1e7);
    }
    default:
      return {farCoordinate(rng), farCoordinate(rng), farCoordinate(rng)};
  }
}

/// Box with a random rotation and size, drawn in that order, centred at `center`.
inline Obb3 randomBoxAt(std::mt19937_64& rng, const Eigen::Vector3d& center) {
  const Eigen::Quaterniond q = randomRotation(rng);
  const Eigen::Vector3d size = randomSize(rng);
  return Obb3::fromQuaternion(center, q, size);
}

/// Box with a random centre, rotation and size, drawn in that order.
inline Obb3 randomBox(std::mt19937_64& rng) {
  const Eigen::Vector3d center = randomCenter(rng);
  return randomBoxAt(rng, center);
}

/// Half-width of `box` along unit direction n (double; the oracle decides the truth).
inline double supportRadius(const Obb3& box, const Eigen::Vector3d& n) {
  return (box.rotation().transpose() * n).cwiseAbs().dot(box.half);
}

/// Candidate axis k of the pair (0-2 A faces, 3-5 B faces, 6-14 a_i x b_j), unit; the zero
/// vector when it vanishes.
inline Eigen::Vector3d candidateAxis(const Obb3& a, const Obb3& b, int k) {
  Eigen::Vector3d n =
      k < 3   ? Eigen::Vector3d(a.rotation().col(k))
      : k < 6 ? Eigen::Vector3d(b.rotation().col(k - 3))
              : Eigen::Vector3d(a.rotation().col((k - 6) / 3).cross(b.rotation().col((k - 6) % 3)));
  const double len = n.norm();
  return len > 0.0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
}

/// Moves b so that, along unit axis n, its projection sits `gap` metres beyond A's (gap < 0:
/// overlapping by -gap along n). Other axes may separate more; the oracle decides.
inline void placeAtGap(const Obb3& a, Obb3& b, const Eigen::Vector3d& n, double gap) {
  b.center = a.center + n * (supportRadius(a, n) + supportRadius(b, n) + gap);
}

/// Gap magnitude log-uniform in 1e-9..1 m on either side of touching.
inline double randomGap(std::mt19937_64& rng) {
  const double sign = randomSign(rng);
  return sign * logUniform(rng, 1e-9, 1.0);
}

/// Places b at randomGap() along n or -n (placeAtGap); the sign is drawn first, then the gap.
inline void placeAtRandomGap(std::mt19937_64& rng, const Obb3& a, Obb3& b,
                             const Eigen::Vector3d& n) {
  const double sign = randomSign(rng);
  placeAtGap(a, b, n * sign, randomGap(rng));
}

/// Random pair placed at a small gap along one of its 15 candidate axes or a random direction.
inline Pair3 gapPair(std::mt19937_64& rng) {
  Pair3 p{randomBox(rng), randomBoxAt(rng, {0, 0, 0})};
  const int k = static_cast<int>(rng() % 16);
  Eigen::Vector3d n = k < 15 ? candidateAxis(p.a, p.b, k) : randomUnit(rng);
  if (n.isZero()) n = randomUnit(rng);
  placeAtRandomGap(rng, p.a, p.b, n);
  return p;
}

/// Both boxes far out (1e6..1e7 m per coordinate), at a gap log-uniform 1e-9..10 m either side.
inline Pair3 farPair(std::mt19937_64& rng) {
  const Eigen::Vector3d c{farCoordinate(rng), farCoordinate(rng), farCoordinate(rng)};
  Pair3 p{randomBoxAt(rng, c), randomBoxAt(rng, {0, 0, 0})};
  const Eigen::Vector3d n = candidateAxis(p.a, p.b, static_cast<int>(rng() % 6));
  const double sign = randomSign(rng);
  const double gap_sign = randomSign(rng);
  placeAtGap(p.a, p.b, n * sign, gap_sign * logUniform(rng, 1e-9, 10.0));
  return p;
}

/// Extreme sizes: each dimension 1 cm, 100 m or log-uniform between; B anywhere near A or at a gap.
inline Pair3 sizePair(std::mt19937_64& rng) {
  const auto extreme = [&rng] {
    Eigen::Vector3d s;
    for (int k = 0; k < 3; ++k) {
      const auto pick = rng() % 3;
      s[k] = pick == 0 ? 0.01 : pick == 1 ? 100.0 : logUniform(rng, 0.01, 100.0);
    }
    return s;
  };
  const Eigen::Vector3d ca = randomCenter(rng);
  const Eigen::Quaterniond qa = randomRotation(rng);
  const Eigen::Vector3d sa = extreme();
  const Eigen::Quaterniond qb = randomRotation(rng);
  const Eigen::Vector3d sb = extreme();
  Pair3 p{Obb3::fromQuaternion(ca, qa, sa), Obb3::fromQuaternion({0, 0, 0}, qb, sb)};
  if (rng() % 2 == 0) {
    const Eigen::Vector3d n = candidateAxis(p.a, p.b, static_cast<int>(rng() % 6));
    placeAtRandomGap(rng, p.a, p.b, n);
  } else {
    p.b.center = p.a.center + randomOffset(rng, 0.0, 150.0);
  }
  return p;
}

/// Near-parallel edges: B = A turned by an angle log-uniform in [lo, hi] rad about a random axis,
/// optionally after an exact quarter-turn permutation of the axes (edges crossed, then nudged).
/// B is placed at a small gap along a near-parallel edge-edge axis (so that axis is the true
/// separating axis), a face axis, or at random.
inline Pair3 nearParallelPair(std::mt19937_64& rng, double lo = 1e-15, double hi = 1e-3) {
  const Eigen::Quaterniond qa = randomRotation(rng).normalized();
  // Quarter turns with exactly representable components up to the common sqrt(1/2) factor.
  static const Eigen::Quaterniond kTurns[4] = {
      {1, 0, 0, 0}, {std::sqrt(0.5), 0, 0, std::sqrt(0.5)}, {0.5, 0.5, 0.5, 0.5}, {0, 1, 0, 0}};
  const Eigen::Quaterniond turn = kTurns[rng() % 4];
  const double angle = logUniform(rng, lo, hi);
  const Eigen::Quaterniond qb = qa * turn * axisAngle(randomUnit(rng), angle);
  // Long thin boxes make edge-edge contacts likely.
  const auto longBox = [&rng] {
    Eigen::Vector3d s = randomSize(rng);
    s[static_cast<int>(rng() % 3)] = logUniform(rng, 10.0, 100.0);
    return s;
  };
  const Eigen::Vector3d ca = randomCenter(rng);
  const Eigen::Vector3d sa = longBox();
  const Eigen::Vector3d sb = longBox();
  Pair3 p{Obb3::fromQuaternion(ca, qa, sa), Obb3::fromQuaternion({0, 0, 0}, qb, sb)};
  const auto pick = rng() % 8;
  if (pick < 6) {
    // The edge pairs that are near parallel have the shortest cross products.
    int best = 6;
    double bestLen = 2.0;
    const int first = static_cast<int>(rng() % 9);
    for (int m = 0; m < 9; ++m) {
      const int k = 6 + (first + m) % 9;
      const double len =
          p.a.rotation().col((k - 6) / 3).cross(p.b.rotation().col((k - 6) % 3)).norm();
      if (len > 0.0 && len < bestLen && (pick < 3 || rng() % 3 == 0)) {
        best = k;
        bestLen = len;
      }
    }
    // Normalise an accurately formed cross product: the naive one is noise at 1e-15 rad.
    const Eigen::Vector3d u = p.a.rotation().col((best - 6) / 3);
    const Eigen::Vector3d v = p.b.rotation().col((best - 6) % 3);
    Eigen::Vector3d n;
    for (int c = 0; c < 3; ++c) {
      const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      const double w = u[c2] * v[c1];
      n[c] = std::fma(u[c1], v[c2], -w) + std::fma(-u[c2], v[c1], w);
    }
    if (n.norm() > 0.0) {
      n = n / n.cwiseAbs().maxCoeff();
      n.normalize();
    } else {
      n = randomUnit(rng);
    }
    placeAtRandomGap(rng, p.a, p.b, n);
  } else if (pick == 6) {
    const Eigen::Vector3d n = candidateAxis(p.a, p.b, static_cast<int>(rng() % 6));
    placeAtRandomGap(rng, p.a, p.b, n);
  } else {
    p.b.center = p.a.center + randomOffset(rng, 0.0, 100.0);
  }
  return p;
}

/// Exactly coincident boxes (same centre, rotation and size).
inline Pair3 coincidentPair(std::mt19937_64& rng) {
  const Obb3 a = randomBox(rng);
  return {a, a};
}

/// Exactly parallel boxes: the same quaternion (or 2q, or -q), any sizes, placed at a gap or near.
inline Pair3 parallelPair(std::mt19937_64& rng) {
  const Eigen::Quaterniond q = randomRotation(rng);
  const double factor = rng() % 3 == 0 ? 2.0 : rng() % 2 == 0 ? -1.0 : 1.0;
  const Eigen::Quaterniond qb(q.coeffs() * factor);
  const Eigen::Vector3d ca = randomCenter(rng);
  const Eigen::Vector3d sa = randomSize(rng);
  const Eigen::Vector3d sb = randomSize(rng);
  Pair3 p{Obb3::fromQuaternion(ca, q, sa), Obb3::fromQuaternion({0, 0, 0}, qb, sb)};
  if (rng() % 2 == 0) {
    const Eigen::Vector3d n = candidateAxis(p.a, p.b, static_cast<int>(rng() % 3));
    placeAtRandomGap(rng, p.a, p.b, n);
  } else {
    p.b.center = p.a.center + randomOffset(rng, 0.0, 150.0);
  }
  return p;
}

/// B strictly inside A (by the double construction; the oracle decides), either order.
inline Pair3 containmentPair(std::mt19937_64& rng) {
  const Eigen::Vector3d sa{logUniform(rng, 1.0, 100.0), logUniform(rng, 1.0, 100.0),
                           logUniform(rng, 1.0, 100.0)};
  const Eigen::Vector3d ca = randomCenter(rng);
  const Obb3 a = Obb3::fromQuaternion(ca, randomRotation(rng), sa);
  // B's bounding sphere fits inside A's inscribed sphere, somewhere in the remaining room.
  const double room = 0.5 * sa.minCoeff();
  const double rb = room * uniform(rng, 0.02, 0.9);
  const Eigen::Vector3d sb = randomUnit(rng).cwiseAbs().cwiseMax(0.01) * (2.0 * rb);
  Obb3 b = Obb3::fromQuaternion({0, 0, 0}, randomRotation(rng), sb);
  b.center = a.center + randomOffset(rng, 0.0, room - b.half.norm());
  return rng() % 2 == 0 ? Pair3{a, b} : Pair3{b, a};
}

/// Axis-aligned boxes touching exactly (all coordinates dyadic so every sum is exact): face to
/// face with a random lateral offset inside the contact, or edge or corner contact.
inline Pair3 touchingPair(std::mt19937_64& rng) {
  const auto dyadic = [&rng](double lo, double hi) {
    return std::ldexp(std::round(std::ldexp(uniform(rng, lo, hi), 10)), -10);
  };
  const auto dyadicSize = [&] {
    return Eigen::Vector3d{dyadic(0.25, 100.0), dyadic(0.25, 100.0), dyadic(0.25, 100.0)};
  };
  const double far = (rng() % 2 == 0) ? 0.0 : 4194304.0;  // 2^22: exact sums with 2^-10 steps
  const Eigen::Vector3d c{far + dyadic(-8.0, 8.0), far + dyadic(-8.0, 8.0), dyadic(-8.0, 8.0)};
  Pair3 p{Obb3::fromQuaternion(c, Eigen::Quaterniond::Identity(), dyadicSize()),
          Obb3::fromQuaternion({0, 0, 0}, Eigen::Quaterniond::Identity(), dyadicSize())};
  const int touching = 1 + static_cast<int>(rng() % 3);  // how many axes are exactly touching
  const int first = static_cast<int>(rng() % 3);
  Eigen::Vector3d d;
  for (int m = 0; m < 3; ++m) {
    const int k = (first + m) % 3;
    const double reach = p.a.half[k] + p.b.half[k];
    d[k] = m < touching ? randomSign(rng) * reach
                        : std::ldexp(std::round(std::ldexp(uniform(rng, -reach, reach), 10)), -10);
  }
  p.b.center = p.a.center + d;
  return p;
}

// Both boxes, every digit, for a failure message.
inline std::string describe(const Obb3& a, const Obb3& b) {
  std::ostringstream s;
  s.precision(17);
  s << "A c=" << a.center.transpose() << " h=" << a.half.transpose() << " R=["
    << a.rotation().row(0) << "; " << a.rotation().row(1) << "; " << a.rotation().row(2) << "]\n"
    << "B c=" << b.center.transpose() << " h=" << b.half.transpose() << " R=["
    << b.rotation().row(0) << "; " << b.rotation().row(1) << "; " << b.rotation().row(2) << "]";
  return s.str();
}

}  // namespace cardemo::test3
