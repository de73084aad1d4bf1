// CrashLedger: crash windows, charges, counts, scrape damage and the hashed state, one collider
// or two at a time, against hand-worked frames.

#include "sim/crash_ledger.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace cardemo {
namespace {

TEST(CrashLedger, FirstHitStartsACrashAndChargesItsWorth) {
  CrashLedger ledger(3, 180);
  EXPECT_FALSE(ledger.touching(1));
  const CrashCharge c = ledger.hit(1, 10, 15);
  EXPECT_EQ(c.damage, 15);
  EXPECT_EQ(c.crash, 1);
  EXPECT_EQ(ledger.crashes(), 1);
  EXPECT_EQ(ledger.damagingCrashes(), 1);
}

TEST(CrashLedger, ReTouchWithinTheWindowChargesOnlyTheExcess) {
  CrashLedger ledger(2, 180);
  ASSERT_EQ(ledger.hit(0, 10, 15).damage, 15);
  ledger.touch(0, 12);  // last contact at frame 12: the window runs to frame 192
  const CrashCharge softer = ledger.hit(0, 192, 9);
  EXPECT_EQ(softer.damage, 0);
  EXPECT_EQ(softer.crash, 1);
  const CrashCharge harder = ledger.hit(0, 100, 24);
  EXPECT_EQ(harder.damage, 9);  // 24 worth, 15 already charged
  EXPECT_EQ(harder.crash, 1);
  EXPECT_EQ(ledger.crashes(), 1);
  EXPECT_EQ(ledger.damagingCrashes(), 1);
}

TEST(CrashLedger, ReTouchAfterTheWindowIsANewCrash) {
  CrashLedger ledger(2, 180);
  ledger.hit(0, 10, 15);
  ledger.touch(0, 10);
  const CrashCharge again = ledger.hit(0, 191, 6);
  EXPECT_EQ(again.damage, 6);
  EXPECT_EQ(again.crash, 2);
  EXPECT_EQ(ledger.crashes(), 2);
  EXPECT_EQ(ledger.damagingCrashes(), 2);
}

TEST(CrashLedger, ACrashCountsAsDamagingFromItsFirstChargedHit) {
  CrashLedger ledger(1, 180);
  EXPECT_EQ(ledger.hit(0, 5, 0).damage, 0);  // a touch below the damage threshold
  EXPECT_EQ(ledger.damagingCrashes(), 0);
  ledger.touch(0, 5);
  EXPECT_EQ(ledger.hit(0, 50, 12).damage, 12);
  EXPECT_EQ(ledger.damagingCrashes(), 1);
  EXPECT_EQ(ledger.hit(0, 60, 20).damage, 8);
  EXPECT_EQ(ledger.damagingCrashes(), 1);  // the same crash, already charged
  EXPECT_EQ(ledger.crashes(), 1);
}

TEST(CrashLedger, CollidersKeepTheirOwnWindowsAndFlags) {
  CrashLedger ledger(2, 180);
  ledger.hit(0, 10, 15);
  ledger.touch(0, 10);
  ledger.setTouching(0, true);
  EXPECT_TRUE(ledger.touching(0));
  EXPECT_FALSE(ledger.touching(1));
  const CrashCharge other = ledger.hit(1, 20, 15);
  EXPECT_EQ(other.damage, 15);
  EXPECT_EQ(other.crash, 2);
  ledger.setTouching(0, false);
  EXPECT_FALSE(ledger.touching(0));
}

TEST(CrashLedger, ScrapeDamageIsExactInWholeFrames) {
  // 4 points a second at 120 Hz: one point every 30 frames, whatever the rounding of 4/120.
  CrashLedger ledger(1, 180);
  int total = 0;
  for (int frame = 1; frame <= 3000; ++frame) {
    total += ledger.scrapeFrame(4.0, 120.0);
    ASSERT_EQ(total, static_cast<int>(std::floor(frame * 4.0 / 120.0))) << "frame " << frame;
  }
  EXPECT_EQ(ledger.scrapeDamage(), 100);
}

TEST(CrashLedger, HashSeesOpenWindowsOnly) {
  CrashLedger a(3, 10), b(3, 10);
  a.hit(2, 5, 15);
  a.touch(2, 5);
  Fnv1a64 open_a, open_b;
  a.hashInto(open_a, 15);
  b.hashInto(open_b, 15);
  EXPECT_NE(open_a.value(), open_b.value());  // window open to frame 15: and the crash count
  // Once the window has closed, only the crash count differs from a ledger that never crashed.
  CrashLedger c(3, 10);
  c.hit(1, 5, 15);
  c.touch(1, 5);
  Fnv1a64 closed_a, closed_c;
  a.hashInto(closed_a, 16);
  c.hashInto(closed_c, 16);
  EXPECT_EQ(closed_a.value(), closed_c.value());
}

}  // namespace
}  // namespace cardemo
