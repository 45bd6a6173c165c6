#include "skytrack/tracking/branch_tree.hpp"

#include <algorithm>
#include <iterator>
#include <utility>

namespace skytrack {

std::string_view to_string(BranchType type) {
  switch (type) {
    case BranchType::kFather:
      return "father";
    case BranchType::kSon:
      return "son";
    case BranchType::kGrandson:
      return "grandson";
  }
  return "?";
}

void BranchTree::add_father(std::int64_t id) {
  nodes_[id] = BranchNode{};
}

void BranchTree::add_branch(std::int64_t id, std::int64_t parent, bool coast) {
  BranchNode& up = nodes_.at(parent);
  BranchNode node;
  node.type = up.type == BranchType::kFather ? BranchType::kSon : BranchType::kGrandson;
  node.parent = parent;
  node.coast = coast;
  up.children.push_back(id);
  nodes_[id] = std::move(node);
  ++branches_;
}

bool BranchTree::can_branch(std::int64_t id, int max_children) const {
  const BranchNode* node = find(id);
  if (node == nullptr || node->type == BranchType::kGrandson) return false;
  const auto branches = std::count_if(node->children.begin(), node->children.end(),
                                      [&](std::int64_t c) { return !nodes_.at(c).coast; });
  return branches < max_children;
}

std::vector<std::int64_t> BranchTree::coast_sons(std::int64_t father) const {
  std::vector<std::int64_t> out;
  if (const BranchNode* node = find(father)) {
    std::copy_if(node->children.begin(), node->children.end(), std::back_inserter(out),
                 [&](std::int64_t c) { return nodes_.at(c).coast; });
  }
  std::sort(out.begin(), out.end());  // numbers grow with time: oldest first
  return out;
}

const BranchNode* BranchTree::find(std::int64_t id) const {
  const auto it = nodes_.find(id);
  return it == nodes_.end() ? nullptr : &it->second;
}

std::int64_t BranchTree::father_of(std::int64_t id) const {
  const BranchNode* node = find(id);
  while (node != nullptr && node->type != BranchType::kFather) {
    id = node->parent;
    node = find(id);
  }
  return node == nullptr ? 0 : id;
}

int BranchTree::branch_count(std::int64_t father) const {
  const BranchNode* node = find(father);
  if (node == nullptr) return 0;
  int count = 0;
  for (const std::int64_t son : node->children) {
    count += 1 + static_cast<int>(nodes_.at(son).children.size());
  }
  return count;
}

void BranchTree::mark_non_manoeuvre_update(std::int64_t id) {
  if (const auto it = nodes_.find(id); it != nodes_.end()) it->second.non_manoeuvre_updated = true;
}

void BranchTree::release_branches(std::int64_t father, std::vector<BranchChange>& out) {
  const auto it = nodes_.find(father);
  if (it == nodes_.end()) return;
  const std::vector<std::int64_t> sons = std::exchange(it->second.children, {});
  for (const std::int64_t son : sons) {
    BranchNode& node = nodes_.at(son);
    if (node.coast) {  // the alternative to this very update
      it->second.children.push_back(son);
      continue;
    }
    // Every grandson goes; a son with a non-manoeuvre update of its own lives on as a father.
    const std::vector<std::int64_t> grandsons = std::exchange(node.children, {});
    for (const std::int64_t grandson : grandsons) erase_subtree(grandson, father, out);
    if (node.non_manoeuvre_updated) {
      out.push_back({BranchChange::Kind::kIndependent, son, BranchType::kSon, father, father});
      node.type = BranchType::kFather;
      node.parent = 0;
      --branches_;
    } else {
      erase_subtree(son, father, out);
    }
  }
}

void BranchTree::prune_children(std::int64_t son, std::vector<BranchChange>& out) {
  const auto it = nodes_.find(son);
  if (it == nodes_.end()) return;
  const std::int64_t father = father_of(son);
  const std::vector<std::int64_t> grandsons = std::exchange(it->second.children, {});
  for (const std::int64_t grandson : grandsons) erase_subtree(grandson, father, out);
}

void BranchTree::promote(std::int64_t branch, std::vector<BranchChange>& out, bool split) {
  const BranchNode* node = find(branch);
  if (node == nullptr || node->type == BranchType::kFather) return;
  const std::int64_t father = father_of(branch);
  out.push_back({BranchChange::Kind::kPromoted, branch, node->type, node->parent, father});
  detach(branch);
  // A promoted son has no grandsons after its non-manoeuvre update (rule 8); a grandson has
  // none at all. Whatever is left goes with the father's other branches.
  std::vector<std::int64_t> own = std::exchange(nodes_.at(branch).children, {});
  for (const std::int64_t child : own) erase_subtree(child, father, out);
  release_branches(father, out);
  BranchNode promoted = std::move(nodes_.at(branch));
  nodes_.erase(branch);
  promoted.type = BranchType::kFather;
  promoted.parent = 0;
  promoted.coast = false;
  // The father's coast sons (their parent is the number, which the promoted branch keeps);
  // of a branch split from the father, only those that split before it: the later ones
  // split from the father's updates that the promotion rejects.
  const std::vector<std::int64_t> coast = std::exchange(nodes_.at(father).children, {});
  for (const std::int64_t son : coast) {
    if (!split || son < branch) {
      promoted.children.push_back(son);
    } else {
      erase_subtree(son, father, out);
    }
  }
  nodes_[father] = std::move(promoted);
  --branches_;
}

void BranchTree::rename(std::int64_t id, std::int64_t number) {
  auto node = nodes_.extract(id);
  if (node.empty()) return;
  for (const std::int64_t child : node.mapped().children) nodes_.at(child).parent = number;
  node.key() = number;
  nodes_.insert(std::move(node));
}

void BranchTree::remove(std::int64_t id, std::vector<BranchChange>& out) {
  const BranchNode* node = find(id);
  if (node == nullptr) return;
  const std::int64_t father = father_of(id);
  if (node->type == BranchType::kFather) {
    const std::vector<std::int64_t> sons = node->children;
    for (const std::int64_t son : sons) erase_subtree(son, father, out);
    nodes_.erase(id);
    return;
  }
  detach(id);
  erase_subtree(id, father, out);
}

void BranchTree::erase_subtree(std::int64_t id, std::int64_t father,
                               std::vector<BranchChange>& out) {
  const auto it = nodes_.find(id);
  if (it == nodes_.end()) return;
  const std::vector<std::int64_t> children = std::exchange(it->second.children, {});
  for (const std::int64_t child : children) erase_subtree(child, father, out);
  const BranchNode& node = nodes_.at(id);
  out.push_back({BranchChange::Kind::kPruned, id, node.type, node.parent, father});
  nodes_.erase(id);
  --branches_;
}

void BranchTree::detach(std::int64_t id) {
  const BranchNode* node = find(id);
  if (node == nullptr || node->parent == 0) return;
  const auto up = nodes_.find(node->parent);
  if (up == nodes_.end()) return;
  std::erase(up->second.children, id);
}

}  // namespace skytrack
