#pragma once
/// Decodes fuzz bytes into 3D box pairs: any rotation, exactly or nearly parallel edges, exactly
/// touching dyadic boxes, gaps along any of the 15 candidate axes. In-domain pairs are what the
/// accuracy contract covers (sizes 1 cm to 100 m, coordinates up to 1e7 m); "wild" pairs are
/// anything the pair parser accepts (up to 1e9, any positive size), where only finiteness is
/// promised.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "byte_reader.hpp"
#include "geometry/obb3.hpp"

namespace cardemo::fuzz {

/// Half-width of `box` along unit direction n.
inline double supportRadius(const Obb3& box, const Eigen::Vector3d& n) {
  return (box.rotation().transpose() * n).cwiseAbs().dot(box.half);
}

/// u x v with every component accurate even for nearly parallel u, v (fma, Kahan's algorithm),
/// so that a gap placed along a near-parallel edge pair's axis is placed where intended.
inline Eigen::Vector3d accurateCross(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  Eigen::Vector3d n;
  for (int c = 0; c < 3; ++c) {
    const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
    const double w = u[c2] * v[c1];
    n[c] = std::fma(u[c1], v[c2], -w) + std::fma(-u[c2], v[c1], w);
  }
  return n;
}

/// Full precision description of a box for failure messages.
inline std::string describe(const Obb3& b) {
  std::ostringstream out;
  out.precision(17);
  out << "center (" << b.center.transpose() << ") half (" << b.half.transpose() << ") rotation ["
      << b.rotation().row(0) << "; " << b.rotation().row(1) << "; " << b.rotation().row(2) << "]";
  return out.str();
}

/// Decodes boxes and pairs from fuzz bytes.
class BoxDecoder3 {
 public:
  /// Decodes from `in`; `wild` selects the parser-accepted domain instead of the contract's.
  BoxDecoder3(ByteReader& in, bool wild) : in_(in), wild_(wild) {}

  /// A centre near the origin, up to 1e7 m out, or on a dyadic grid far out.
  Eigen::Vector3d center() {
    Eigen::Vector3d c;
    const int mode = in_.pick(3);
    for (int k = 0; k < 3; ++k) {
      if (wild_) {
        c[k] = in_.pick(8) == 0 ? 0.0 : in_.signedLog(1e-300, 1e9);
      } else if (mode == 0) {
        c[k] = in_.range(-100.0, 100.0);
      } else if (mode == 1) {
        c[k] = in_.signedLog(1.0, 5.7e6);  // |c| <= 1e7
      } else {
        c[k] = in_.dyadic(2e6, 4e6);
      }
    }
    return c;
  }

  /// A rotation: exact quarter turns, any, a quarter turn nudged by 1e-15..1e-3 rad, or any
  /// axis-angle. Wild: raw components of any magnitude the parser accepts.
  Eigen::Quaterniond rotation() {
    if (wild_) {
      Eigen::Quaterniond q;
      for (int k = 0; k < 4; ++k) {
        q.coeffs()[k] = in_.pick(4) == 0 ? 0.0 : in_.signedLog(1e-90, 1e9);
      }
      // The parser refuses squared norms at or below 1e-200.
      if (!(q.coeffs().squaredNorm() > 1e-200)) q = Eigen::Quaterniond::Identity();
      return q;
    }
    switch (in_.pick(4)) {
      case 0:
        return quarterTurns();
      case 1: {
        Eigen::Quaterniond q;
        for (int k = 0; k < 4; ++k) q.coeffs()[k] = in_.range(-1.0, 1.0);
        return q.coeffs().norm() > 1e-3 ? q : Eigen::Quaterniond::Identity();
      }
      case 2: {
        const Eigen::Quaterniond turn = quarterTurns();
        return turn * nudge();
      }
      default: {
        const double angle = in_.range(-std::numbers::pi, std::numbers::pi);
        return Eigen::Quaterniond(Eigen::AngleAxisd(angle, direction()));
      }
    }
  }

  /// B's rotation from A's: independent, nearly parallel (A's times a quarter turn times a
  /// 1e-15..1e-3 rad nudge), exactly parallel (the same quaternion scaled by 1, -1 or 2), or A's
  /// times a quarter turn.
  Eigen::Quaterniond rotationFrom(const Eigen::Quaterniond& qa) {
    if (wild_) return rotation();
    switch (in_.pick(4)) {
      case 0:
        return rotation();
      case 1: {
        const Eigen::Quaterniond turn = quarterTurns();
        return qa * turn * nudge();
      }
      case 2: {
        const double factor =
            std::array<double, 3>{1.0, -1.0, 2.0}[static_cast<std::size_t>(in_.pick(3))];
        return Eigen::Quaterniond(qa.coeffs() * factor);
      }
      default:
        return qa * quarterTurns();
    }
  }

  /// Full sizes: 1 cm to 100 m each, often exactly at an end; wild: any positive size to 1e9.
  Eigen::Vector3d size() {
    Eigen::Vector3d s;
    for (int k = 0; k < 3; ++k) {
      if (wild_) {
        s[k] = in_.logRange(4.9406564584124654e-324, 1e9);
        continue;
      }
      const int mode = in_.pick(4);
      s[k] = mode == 0 ? 0.01 : mode == 1 ? 100.0 : in_.logRange(0.01, 100.0);
    }
    return s;
  }

  /// Moves B next to A: at random nearby, at a chosen signed gap (0 or 1e-12..10 m either way)
  /// along one of the 15 candidate axes or any direction (with a lateral offset), or inside A.
  void place(const Obb3& a, Obb3& b) {
    const int mode = in_.pick(4);
    if (mode == 0) {
      b.center = a.center + (wild_ ? center()
                                   : Eigen::Vector3d{in_.range(-150, 150), in_.range(-150, 150),
                                                     in_.range(-150, 150)});
      return;
    }
    if (mode == 3) {
      b.center = a.center +
                 Eigen::Vector3d{in_.range(-1, 1), in_.range(-1, 1), in_.range(-1, 1)}.cwiseProduct(
                     a.half);
      return;
    }
    Eigen::Vector3d n = direction();
    if (mode == 1) {
      const int k = in_.pick(15);
      const Eigen::Vector3d axis =
          k < 3   ? Eigen::Vector3d(a.rotation().col(k))
          : k < 6 ? Eigen::Vector3d(b.rotation().col(k - 3))
                  : accurateCross(a.rotation().col((k - 6) / 3), b.rotation().col((k - 6) % 3));
      const double scale = axis.cwiseAbs().maxCoeff();
      if (scale > 0.0) n = (axis / scale).normalized() * in_.sign();
    }
    const double gap = in_.pick(4) == 0 ? 0.0 : in_.signedLog(1e-12, 10.0);
    Eigen::Vector3d lateral = n.cross(direction());
    lateral =
        lateral.norm() > 1e-3 ? Eigen::Vector3d(lateral.normalized()) : Eigen::Vector3d::Zero();
    b.center = a.center + n * (supportRadius(a, n) + supportRadius(b, n) + gap) +
               lateral * in_.range(0.0, a.half.minCoeff());
  }

 private:
  // One of 16 quarter-turn products with exactly representable components (up to sqrt(1/2)).
  Eigen::Quaterniond quarterTurns() {
    static const std::array<Eigen::Quaterniond, 4> kTurns = {
        Eigen::Quaterniond{1, 0, 0, 0}, Eigen::Quaterniond{std::sqrt(0.5), 0, 0, std::sqrt(0.5)},
        Eigen::Quaterniond{0.5, 0.5, 0.5, 0.5}, Eigen::Quaterniond{0, 1, 0, 0}};
    const auto first = static_cast<std::size_t>(in_.pick(4));
    const auto second = static_cast<std::size_t>(in_.pick(4));
    return kTurns[first] * kTurns[second];
  }

  // A rotation by 1e-15..1e-3 rad about a random axis.
  Eigen::Quaterniond nudge() {
    const double angle = in_.signedLog(1e-15, 1e-3);
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, direction()));
  }

  // A unit direction (spherical angles).
  Eigen::Vector3d direction() {
    const double z = in_.range(-1.0, 1.0);
    const double t = in_.range(-std::numbers::pi, std::numbers::pi);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(t), r * std::sin(t), z};
  }

  ByteReader& in_;
  bool wild_;
};

}  // namespace cardemo::fuzz
