// The father / son / grandson rules of paper 003 §1 (5), (8), (10) on the bare tree.
#include "skytrack/tracking/branch_tree.hpp"

#include <gtest/gtest.h>

namespace skytrack {
namespace {

using Kind = BranchChange::Kind;

/// Father 1 with sons 2 and 3, grandson 4 under son 2 and grandson 5 under son 3.
BranchTree family() {
  BranchTree tree;
  tree.add_father(1);
  tree.add_branch(2, 1);
  tree.add_branch(3, 1);
  tree.add_branch(4, 2);
  tree.add_branch(5, 3);
  return tree;
}

bool has(const std::vector<BranchChange>& changes, Kind kind, std::int64_t track) {
  for (const BranchChange& c : changes) {
    if (c.kind == kind && c.track == track) return true;
  }
  return false;
}

TEST(BranchTree, LevelsParentsAndChildrenFollowTheRulesOfSection1) {
  // GIVEN the family above
  const BranchTree tree = family();
  // THEN types, parent and child indices are as in §1 (1)-(3)
  EXPECT_EQ(tree.find(1)->type, BranchType::kFather);
  EXPECT_EQ(tree.find(1)->parent, 0);
  EXPECT_EQ(tree.find(1)->children, (std::vector<std::int64_t>{2, 3}));
  EXPECT_EQ(tree.find(2)->type, BranchType::kSon);
  EXPECT_EQ(tree.find(2)->parent, 1);
  EXPECT_EQ(tree.find(4)->type, BranchType::kGrandson);
  EXPECT_EQ(tree.find(4)->parent, 2);
  EXPECT_TRUE(tree.find(4)->children.empty());
  EXPECT_EQ(tree.father_of(4), 1);
  EXPECT_EQ(tree.branch_count(1), 4);
  EXPECT_EQ(tree.total_branches(), 4);
}

TEST(BranchTree, ChildrenAreCappedAndGrandsonsNeverBranch) {
  BranchTree tree;
  tree.add_father(1);
  EXPECT_TRUE(tree.can_branch(1, 2));
  tree.add_branch(2, 1);
  tree.add_branch(3, 1);
  EXPECT_FALSE(tree.can_branch(1, 2));  // two sons: full at max_children 2
  EXPECT_TRUE(tree.can_branch(2, 2));
  tree.add_branch(4, 2);
  EXPECT_FALSE(tree.can_branch(4, 3));  // a grandson has no branches (§1 (1))
}

TEST(BranchTree, FatherNonManoeuvreUpdateReleasesItsBranches) {
  // GIVEN son 2 has had a non-manoeuvre update since its birth, son 3 has not
  BranchTree tree = family();
  tree.mark_non_manoeuvre_update(2);
  // WHEN the father takes a non-manoeuvre association (§1 (5), §2.3 (1))
  std::vector<BranchChange> changes;
  tree.release_branches(1, changes);
  // THEN every grandson is deleted, son 2 becomes an independent father, son 3 is deleted
  EXPECT_TRUE(has(changes, Kind::kPruned, 4));
  EXPECT_TRUE(has(changes, Kind::kPruned, 5));
  EXPECT_TRUE(has(changes, Kind::kIndependent, 2));
  EXPECT_TRUE(has(changes, Kind::kPruned, 3));
  EXPECT_EQ(changes.size(), 4u);
  EXPECT_TRUE(tree.find(1)->children.empty());
  EXPECT_EQ(tree.find(2)->type, BranchType::kFather);
  EXPECT_EQ(tree.find(2)->parent, 0);
  EXPECT_TRUE(tree.find(2)->children.empty());
  EXPECT_FALSE(tree.contains(3));
  EXPECT_FALSE(tree.contains(4));
  EXPECT_EQ(tree.total_branches(), 0);
}

TEST(BranchTree, SonNonManoeuvreUpdateDeletesItsGrandsons) {
  BranchTree tree = family();
  std::vector<BranchChange> changes;
  tree.prune_children(2, changes);  // §1 (8)
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].kind, Kind::kPruned);
  EXPECT_EQ(changes[0].track, 4);
  EXPECT_EQ(changes[0].parent, 2);
  EXPECT_EQ(changes[0].father, 1);
  EXPECT_TRUE(tree.contains(5));  // the other son's grandson stays
  EXPECT_EQ(tree.branch_count(1), 3);
}

TEST(BranchTree, ConfirmedSonReplacesItsFatherUnderTheFathersNumber) {
  // GIVEN son 3 had a non-manoeuvre update, son 2 (with grandson 4) did not; son 6 is new
  BranchTree tree = family();
  tree.add_branch(6, 1);
  tree.mark_non_manoeuvre_update(3);
  tree.mark_non_manoeuvre_update(6);
  // WHEN son 6 is confirmed (§1 (10), §2.3 (2))
  std::vector<BranchChange> changes;
  tree.promote(6, changes);
  // THEN it is promoted first, then the father's other branches are handled as in (5)
  ASSERT_FALSE(changes.empty());
  EXPECT_EQ(changes[0].kind, Kind::kPromoted);
  EXPECT_EQ(changes[0].track, 6);
  EXPECT_EQ(changes[0].father, 1);
  EXPECT_TRUE(has(changes, Kind::kPruned, 2));
  EXPECT_TRUE(has(changes, Kind::kPruned, 4));
  EXPECT_TRUE(has(changes, Kind::kPruned, 5));
  EXPECT_TRUE(has(changes, Kind::kIndependent, 3));
  // The father's number now names the promoted track, a father without branches.
  EXPECT_FALSE(tree.contains(6));
  ASSERT_TRUE(tree.contains(1));
  EXPECT_EQ(tree.find(1)->type, BranchType::kFather);
  EXPECT_TRUE(tree.find(1)->children.empty());
  EXPECT_EQ(tree.find(3)->type, BranchType::kFather);
  EXPECT_EQ(tree.total_branches(), 0);
}

TEST(BranchTree, ConfirmedGrandsonReplacesTheFatherAndItsOwnSonIsCleanedUp) {
  // GIVEN grandson 4 under son 2 (no non-manoeuvre update) and son 3 with one
  BranchTree tree = family();
  tree.add_branch(7, 2);  // a sibling grandson
  tree.mark_non_manoeuvre_update(3);
  // WHEN grandson 4 is confirmed (§1 (10), §2.3 (3))
  std::vector<BranchChange> changes;
  tree.promote(4, changes);
  // THEN it replaces father 1; son 2 and every other grandson go; son 3 becomes a father
  EXPECT_EQ(changes[0].kind, Kind::kPromoted);
  EXPECT_EQ(changes[0].type, BranchType::kGrandson);
  EXPECT_EQ(changes[0].parent, 2);
  EXPECT_TRUE(has(changes, Kind::kPruned, 2));
  EXPECT_TRUE(has(changes, Kind::kPruned, 7));
  EXPECT_TRUE(has(changes, Kind::kPruned, 5));
  EXPECT_TRUE(has(changes, Kind::kIndependent, 3));
  EXPECT_EQ(tree.find(1)->type, BranchType::kFather);
  EXPECT_FALSE(tree.contains(4));
  EXPECT_EQ(tree.total_branches(), 0);
}

TEST(BranchTree, CoastSonOutlivesTheFathersUpdatesAndFollowsAPromotedSibling) {
  // GIVEN the family above with coast son 6 of father 1 (branching.coast_sons)
  BranchTree tree = family();
  tree.add_branch(6, 1, /*coast=*/true);
  // THEN it does not take one of max_children (two sons: full at 2, not at 3)
  EXPECT_FALSE(tree.can_branch(1, 2));
  EXPECT_TRUE(tree.can_branch(1, 3));
  EXPECT_EQ(tree.coast_sons(1), (std::vector<std::int64_t>{6}));
  // WHEN the father takes a non-manoeuvre association (rule 5)
  std::vector<BranchChange> changes;
  tree.release_branches(1, changes);
  // THEN sons 2, 3 and their grandsons go, the coast son (the alternative to that very
  // update) stays
  EXPECT_FALSE(has(changes, Kind::kPruned, 6));
  EXPECT_TRUE(has(changes, Kind::kPruned, 2));
  EXPECT_EQ(tree.find(1)->children, (std::vector<std::int64_t>{6}));
  // WHEN a new son 7 is confirmed and replaces the father
  tree.add_branch(7, 1);
  changes.clear();
  tree.promote(7, changes);
  // THEN the coast son is the promoted branch's, under the father's number
  EXPECT_TRUE(has(changes, Kind::kPromoted, 7));
  EXPECT_FALSE(has(changes, Kind::kPruned, 6));
  EXPECT_EQ(tree.find(1)->children, (std::vector<std::int64_t>{6}));
  EXPECT_EQ(tree.father_of(6), 1);
  EXPECT_EQ(tree.total_branches(), 1);
  // WHEN the coast son itself is confirmed: it replaces the father and is a father
  changes.clear();
  tree.promote(6, changes);
  EXPECT_TRUE(has(changes, Kind::kPromoted, 6));
  EXPECT_EQ(tree.find(1)->type, BranchType::kFather);
  EXPECT_FALSE(tree.find(1)->coast);
  EXPECT_TRUE(tree.find(1)->children.empty());
  EXPECT_EQ(tree.total_branches(), 0);
}

TEST(BranchTree, PromotedSonKeepsOnlyTheCoastSonsThatSplitBeforeIt) {
  // GIVEN father 1 with coast son 6, then son 7 (from a manoeuvre pair), then coast son 8
  // (split from an update of the father after son 7 started)
  BranchTree tree;
  tree.add_father(1);
  tree.add_branch(6, 1, /*coast=*/true);
  tree.add_branch(7, 1);
  tree.add_branch(8, 1, /*coast=*/true);
  // WHEN son 7 is confirmed and replaces the father
  std::vector<BranchChange> changes;
  tree.promote(7, changes);
  // THEN coast son 8, which kept the father's motion from after son 7's start, goes with
  // the father's track that son 7 replaced; coast son 6 (an earlier alternative) stays
  EXPECT_TRUE(has(changes, Kind::kPromoted, 7));
  EXPECT_TRUE(has(changes, Kind::kPruned, 8));
  EXPECT_FALSE(has(changes, Kind::kPruned, 6));
  EXPECT_EQ(tree.find(1)->children, (std::vector<std::int64_t>{6}));
  EXPECT_EQ(tree.total_branches(), 1);
  // WHEN a new track 9 is adopted as the father's son and promoted (not split from it)
  tree.add_branch(10, 1, /*coast=*/true);
  tree.add_branch(9, 1);
  changes.clear();
  tree.promote(9, changes, /*split=*/false);
  // THEN every coast son stays, the one newer than the track's number too
  EXPECT_FALSE(has(changes, Kind::kPruned, 6));
  EXPECT_FALSE(has(changes, Kind::kPruned, 10));
  EXPECT_EQ(tree.find(1)->children, (std::vector<std::int64_t>{6, 10}));
}

TEST(BranchTree, RemovingANodeTakesItsSubtree) {
  BranchTree tree = family();
  std::vector<BranchChange> changes;
  tree.remove(2, changes);
  EXPECT_TRUE(has(changes, Kind::kPruned, 2));
  EXPECT_TRUE(has(changes, Kind::kPruned, 4));
  EXPECT_EQ(tree.find(1)->children, (std::vector<std::int64_t>{3}));
  changes.clear();
  tree.remove(1, changes);  // a father: its branches are pruned, no change for itself
  EXPECT_EQ(changes.size(), 2u);
  EXPECT_FALSE(tree.contains(1));
  EXPECT_EQ(tree.total_branches(), 0);
}

}  // namespace
}  // namespace skytrack
