// Memory stays bounded: after the first scans no per-scan step allocates. Counts calls of
// the global operator new, replaced for this test program only.
#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/bernoulli/imm_bernoulli_filter.hpp"
#include "skytrack/bernoulli/mm_bernoulli_filter.hpp"
#include "skytrack/bernoulli/paper001_scenario.hpp"

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

namespace skytrack::bernoulli {
namespace {

template <class Filter>
long allocations_after_warm_up(Filter& filter, const std::vector<Paper001Scan>& scans) {
  for (int k = 0; k < 5; ++k)
    filter.step(scans[k].time, Eigen::Vector2d::Zero(), std::span(scans[k].plots));
  const long before = g_allocations.load();
  for (std::size_t k = 5; k < scans.size(); ++k) {
    filter.step(scans[k].time, Eigen::Vector2d::Zero(), std::span(scans[k].plots));
  }
  return g_allocations.load() - before;
}

TEST(BernoulliMemory, StepsAllocateNothingAfterWarmUp) {
  // GIVEN the paper's scenario, whose scans hold at most a few dozen plots
  const std::vector<Paper001Scan> scans = simulate_paper001(Paper001Options{.seed = 6});
  BernoulliSpec spec;
  const long at_start = g_allocations.load();
  MmBernoulliFilter mm(spec);
  EXPECT_GT(g_allocations.load(), at_start);  // the counter sees the buffers allocated here
  EXPECT_EQ(allocations_after_warm_up(mm, scans), 0);
  ImmBernoulliFilter imm(spec, 1000);
  EXPECT_EQ(allocations_after_warm_up(imm, scans), 0);
  spec.birth_proposal = BirthProposal::kPlotPairs;
  MmBernoulliFilter pairs(spec);
  EXPECT_EQ(allocations_after_warm_up(pairs, scans), 0);
}

}  // namespace
}  // namespace skytrack::bernoulli
