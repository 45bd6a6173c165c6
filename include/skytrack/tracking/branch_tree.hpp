#pragma once
// Father / son / grandson bookkeeping of branch ("filiation") tracking, paper 003 §1 and §2.3
// (Ma, Xu, Zhang 2020). Tracks are named by their numbers; a father's number is the one
// reported, a branch's number is internal until the branch replaces its father.
//   §1 (1)-(3)  three levels; a father has sons, a son has grandsons, a grandson has none;
//               each node has one parent and at most max_children children.
//   §1 (5)      father updated by a non-manoeuvre association: every grandson is deleted, a
//               son with a non-manoeuvre update since its birth becomes an independent
//               father, the other sons are deleted                  -> release_branches
//   §1 (8)      son updated by a non-manoeuvre association: its grandsons are deleted
//                                                                   -> prune_children
//   §1 (10)     a confirmed son or grandson replaces its father, takes its number and
//               attributes; the father is deleted and its other branches are handled as
//               in (5)                                              -> promote
// The tree only decides; the tracker applies the returned changes to its tracks.
#include <cstdint>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace skytrack {

enum class BranchType : std::uint8_t { kFather, kSon, kGrandson };

std::string_view to_string(BranchType type);

struct BranchNode {
  BranchType type = BranchType::kFather;
  std::int64_t parent = 0;             // number of the parent; 0 for a father
  std::vector<std::int64_t> children;  // sons of a father, grandsons of a son
  bool non_manoeuvre_updated = false;  // a non-manoeuvre update since its birth
  // A coast son (branching.coast_sons): its father's motion before a doubtful plot. Not a
  // paper 003 branch: it is the alternative to the father's own updates, so rule 5 keeps
  // it, a promoted sibling inherits it, and it does not take one of max_children.
  bool coast = false;
};

/// One decision about one branch.
struct BranchChange {
  enum class Kind : std::uint8_t {
    kPruned,       // the branch is deleted
    kIndependent,  // the son leaves the tree as a father of its own (keeps its number)
    kPromoted,     // the branch replaced its father and now carries the father's number
  };
  Kind kind = Kind::kPruned;
  std::int64_t track = 0;  // the branch's own number (before a promotion)
  BranchType type = BranchType::kSon;
  std::int64_t parent = 0;  // its parent's number
  std::int64_t father = 0;  // the reported number of the tree it belonged to
};

class BranchTree {
 public:
  void add_father(std::int64_t id);
  /// Adds a son under a father or a grandson under a son. Requires can_branch(parent), or
  /// a father for a coast son.
  void add_branch(std::int64_t id, std::int64_t parent, bool coast = false);
  /// A father or a son below max_children children besides coast sons (grandsons never
  /// branch, §1 (1)).
  bool can_branch(std::int64_t id, int max_children) const;
  /// The coast sons of a father, oldest first.
  std::vector<std::int64_t> coast_sons(std::int64_t father) const;

  const BranchNode* find(std::int64_t id) const;
  bool contains(std::int64_t id) const { return find(id) != nullptr; }
  /// The father at the root of the tree holding `id` (id itself for a father; 0 if absent).
  std::int64_t father_of(std::int64_t id) const;
  /// Sons plus grandsons of a father.
  int branch_count(std::int64_t father) const;
  /// Sons and grandsons of all fathers.
  int total_branches() const { return branches_; }

  void mark_non_manoeuvre_update(std::int64_t id);

  /// §1 (5), §2.3 (1): the father took a non-manoeuvre association. Coast sons stay.
  void release_branches(std::int64_t father, std::vector<BranchChange>& out);
  /// §1 (8): the son took a non-manoeuvre association; its grandsons go.
  void prune_children(std::int64_t son, std::vector<BranchChange>& out);
  /// §1 (10), §2.3 (2)-(3): the confirmed branch replaces its father. Emits kPromoted for
  /// the branch first, then the clean-up of the father's other branches as in (5). Afterwards
  /// the branch is a father under the father's number, with the father's coast sons; when
  /// the branch split from the father (`split`: not a new track adopted as its son), only
  /// those older than the branch (the newer ones split from updates the promotion rejects).
  void promote(std::int64_t branch, std::vector<BranchChange>& out, bool split = true);
  /// Deletes a node and everything below it (a branch that died, a father deleted, a cap).
  /// Emits kPruned for every branch removed (not for a father).
  void remove(std::int64_t id, std::vector<BranchChange>& out);
  /// Gives a father another number (its sons follow).
  void rename(std::int64_t id, std::int64_t number);

 private:
  void erase_subtree(std::int64_t id, std::int64_t father, std::vector<BranchChange>& out);
  void detach(std::int64_t id);

  std::unordered_map<std::int64_t, BranchNode> nodes_;
  int branches_ = 0;
};

}  // namespace skytrack
