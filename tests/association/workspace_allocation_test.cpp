// The per-scan association components reuse their buffers: after warm-up on a scan, running
// the same work again makes no heap allocation through operator new (std containers).
// Eigen's own mallocs are not seen here. JpdaResult::beta is the one exception by design: it
// is resized (freed and re-malloced by Eigen) when the cluster shape changes, and keeps its
// storage while the shape is unchanged, which the data() check below covers.
#include <atomic>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "jpda_test_support.hpp"
#include "skytrack/association/cluster_builder.hpp"
#include "skytrack/association/gnn_associator.hpp"
#include "skytrack/association/jpda_solver.hpp"
#include "skytrack/association/plot_index.hpp"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace

// Replaceable global allocation functions: count while armed, otherwise plain malloc.
// noinline keeps GCC from pairing an inlined free() with a std::allocator's operator new
// (a false -Wmismatched-new-delete).
[[gnu::noinline]] void* operator new(std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void* operator new[](std::size_t size) {
  return operator new(size);
}
[[gnu::noinline]] void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
  return std::malloc(size == 0 ? 1 : size);
}
[[gnu::noinline]] void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
[[gnu::noinline]] void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

namespace skytrack {
namespace {

class CountAllocations {
 public:
  CountAllocations() {
    g_allocations = 0;
    g_counting = true;
  }
  ~CountAllocations() { g_counting = false; }
  long count() const { return g_allocations.load(); }
};

TEST(AssociationWorkspaces, NoAllocationAfterWarmUp) {
  // GIVEN one scan's worth of work done once (warm-up)
  std::mt19937_64 rng(8);
  const JpdaProblem exact_cluster = test::chain_cluster(8, 2.5, 0.02, rng);
  const JpdaProblem big_cluster = test::chain_cluster(16, 2.5, 0.02, rng);
  std::vector<Eigen::Vector3d> positions;
  std::uniform_real_distribution<double> xy(-1e4, 1e4);
  for (int i = 0; i < 2000; ++i) {
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const double y = xy(rng), x = xy(rng);
    positions.emplace_back(x, y, 0.0);
  }
  std::vector<GatedPair> pairs;
  for (int i = 0; i < 300; ++i) pairs.push_back({i % 50, (7 * i) % 200});

  JpdaSolver solver;
  GnnAssociator gnn;
  ClusterBuilder clusters;
  PlotIndex index;
  std::vector<int> found;
  found.reserve(positions.size());
  auto scan = [&] {
    index.build(positions, 2);
    for (int q = 0; q < 50; ++q) index.within(positions[static_cast<std::size_t>(q)], 800.0, found);
    clusters.build(50, 200, pairs);
    solver.solve(exact_cluster);
    solver.solve(big_cluster);  // 16 tracks > 8: Murty k = 100
    gnn.associate(big_cluster);
  };
  scan();
  long allocations = 0;
  {
    CountAllocations counter;  // WHEN the same scan runs again
    scan();
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0);  // THEN nothing was allocated
  const double* beta_storage = solver.solve(big_cluster).beta.data();
  EXPECT_TRUE(solver.solve(big_cluster).approximated);  // same shape again: same storage
  EXPECT_EQ(solver.solve(big_cluster).beta.data(), beta_storage);
}

}  // namespace
}  // namespace skytrack
