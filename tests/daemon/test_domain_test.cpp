// The DDS domain lease the end-to-end tests run on: two tests running at once never share a
// domain, and a domain is free again once its test has ended.
#include "support/test_domain.hpp"

#include <memory>
#include <set>
#include <vector>

#include <gtest/gtest.h>

namespace skytrack::test {
namespace {

TEST(TestDomain, LeasesHeldAtOnceAreAllDifferentAndInRange) {
  // GIVEN 40 leases held at once (flock conflicts between open files, in one process too)
  std::vector<std::unique_ptr<TestDomain>> leases;
  std::set<int> ids;
  for (int i = 0; i < 40; ++i) {
    leases.push_back(std::make_unique<TestDomain>());
    ids.insert(leases.back()->id());
  }
  // THEN no two share an id, and none reaches the fixed domains from 220 on
  EXPECT_EQ(ids.size(), leases.size());
  EXPECT_GE(*ids.begin(), TestDomain::kFirst);
  EXPECT_LT(*ids.rbegin(), TestDomain::kFirst + TestDomain::kCount);
}

TEST(TestDomain, AnIdIsFreeAgainWhenItsLeaseEnds) {
  // GIVEN a lease, and the id a second lease takes meanwhile
  auto first = std::make_unique<TestDomain>();
  const int id = first->id();
  {
    const TestDomain second;
    EXPECT_NE(second.id(), id);
  }
  // WHEN the first ends, THEN the next lease starts from the same id again and gets it
  first.reset();
  const TestDomain again;
  EXPECT_EQ(again.id(), id);
}

}  // namespace
}  // namespace skytrack::test
