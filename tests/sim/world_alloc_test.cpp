// Counts global allocations to check that World::step does not allocate once warm.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "scene_builders.hpp"
#include "sim/world.hpp"

// The replacement pair below is malloc/free on purpose; GCC flags free() on operator-new memory.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
// std::stable_sort's buffer comes from the nothrow form; left to the sanitizer's own allocator it
// would come back through the free() above, which AddressSanitizer reports as a mismatch.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size == 0 ? 1 : size);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}

namespace cardemo {
namespace {

TEST(WorldAllocation, StepDoesNotAllocateOnceWarm) {
  World world(test::parkingLot(5));
  const std::vector<InputFrame> drive = test::scriptedDrive(5, 3000);
  for (int i = 0; i < 1500; ++i) world.step(drive[static_cast<std::size_t>(i)]);
  const std::size_t hits = world.hits().size();
  const long before = g_allocations.load();
  for (int i = 1500; i < 3000; ++i) world.step(drive[static_cast<std::size_t>(i)]);
  const long allocated = g_allocations.load() - before;
  // Each new hit copies its id into the event list; everything else runs in reserved buffers.
  EXPECT_LE(allocated, static_cast<long>(world.hits().size() - hits));
}

}  // namespace
}  // namespace cardemo
