#include "sim/state_hash.hpp"

#include <string>

#include "sim/world.hpp"

namespace cardemo {

std::uint64_t World::stateHash() const {
  Fnv1a64 h;
  h.addInt(frame_);
  h.addDouble(car_.position.x());
  h.addDouble(car_.position.y());
  h.addDouble(car_.heading);
  h.addDouble(car_.direction.x());
  h.addDouble(car_.direction.y());
  h.addDouble(car_.speed);
  h.addDouble(car_.steer);
  h.addDouble(car_.slip);
  h.addDouble(car_.surface_normal.x());
  h.addDouble(car_.surface_normal.y());
  h.addInt(health_);
  h.addInt(static_cast<std::int64_t>(hits_.size()));
  // contacts_ is kept sorted by collider index, so this is the touching set in increasing order.
  for (const ActiveContact& c : contacts_) h.add(c.collider);
  ledger_.hashInto(h, frame_);
  // The driver's state: what each held pedal does and how long the steering key has been held.
  h.add(static_cast<std::uint64_t>(controls_.up));
  h.add(static_cast<std::uint64_t>(controls_.down));
  h.addInt(controls_.steer_steps);
  return h.value();
}

std::string hashHex(std::uint64_t hash) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i) {
    s[static_cast<std::size_t>(i)] = kDigits[hash & 0xfu];
    hash >>= 4;
  }
  return s;
}

}  // namespace cardemo
