#pragma once
// Plot-track pair confirmation of branch tracking, paper 003 §2.1-2.2. Every plot-track pair
// of one kind (branch type x association type) carries the joint conditional probability
// (JPDA beta) computed over the pairs of that kind (§2.1 (3)). Pairs are confirmed kind by
// kind in the order
//   father non-manoeuvre > son non-manoeuvre > grandson manoeuvre > son manoeuvre >
//   father manoeuvre
// and inside a kind by descending probability; a pair whose plot or track an earlier
// confirmed pair has taken is dropped (§2.2).
//
// The tracks of the two creating kinds (son and father manoeuvre pairs, §2.3 (4)-(5)) are
// not updated by their pair but get a new branch from its plot. A track may therefore create
// several branches in one scan, one per plot (paper 003 §4.3 starts two branches of one
// track from two plots in its manoeuvre gate), while its plots are still used once each;
// such a track cannot also be confirmed in an updating kind.
#include <cstdint>
#include <span>
#include <vector>

namespace skytrack {

/// The five pair kinds, in the order of confirmation.
enum class PairKind : std::uint8_t {
  kFatherNonManoeuvre,
  kSonNonManoeuvre,
  kGrandsonManoeuvre,
  kSonManoeuvre,
  kFatherManoeuvre,
};
inline constexpr int kPairKinds = 5;

/// True for the kinds that update their track (the others create a branch from the plot).
constexpr bool updates_track(PairKind kind) {
  return kind == PairKind::kFatherNonManoeuvre || kind == PairKind::kSonNonManoeuvre ||
         kind == PairKind::kGrandsonManoeuvre;
}

struct BranchPair {
  PairKind kind = PairKind::kFatherNonManoeuvre;
  int track = 0;  // index of the track in this scan
  int plot = 0;   // index of the plot in this scan
  double probability = 0.0;
  int candidate = -1;  // the caller's handle on the pair (not used here)
};

/// Confirms pairs as in §2.2. Returns the confirmed pairs in processing order (kind, then
/// descending probability; ties by track, then plot, so the result is deterministic).
/// `num_tracks` and `num_plots` bound the indices.
std::vector<BranchPair> confirm_pairs(std::span<const BranchPair> pairs, int num_tracks,
                                      int num_plots);

}  // namespace skytrack
