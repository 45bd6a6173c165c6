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
  // GIVEN a lease: while it is held, no other lease gets its id
  auto first = std::make_unique<TestDomain>();
  const int id = first->id();
  {
    const TestDomain second;
    EXPECT_NE(second.id(), id);
  }
  // WHEN it ends, THEN leases taken one after another reach its id again (other test
  // processes may hold ids before it in the order they are tried)
  first.reset();
  std::vector<std::unique_ptr<TestDomain>> leases;
  bool again = false;
  for (int i = 0; i < TestDomain::kCount && !again; ++i) {
    leases.push_back(std::make_unique<TestDomain>());
    again = leases.back()->id() == id;
  }
  EXPECT_TRUE(again);
}

}  // namespace
}  // namespace skytrack::test
