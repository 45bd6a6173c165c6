#pragma once
// Helpers of the point tracker's branch layer (paper 003), shared by its translation units
// (not installed).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "skytrack/tracking/branch_association.hpp"
#include "skytrack/tracking/branch_tree.hpp"

namespace skytrack::tracking_detail {

inline constexpr PairKind kConfirmationOrder[kPairKinds] = {
    PairKind::kFatherNonManoeuvre, PairKind::kSonNonManoeuvre, PairKind::kGrandsonManoeuvre,
    PairKind::kSonManoeuvre, PairKind::kFatherManoeuvre};

inline bool is_manoeuvre(PairKind kind) {
  return kind == PairKind::kGrandsonManoeuvre || kind == PairKind::kSonManoeuvre ||
         kind == PairKind::kFatherManoeuvre;
}

inline BranchType type_of(PairKind kind) {
  switch (kind) {
    case PairKind::kFatherNonManoeuvre:
    case PairKind::kFatherManoeuvre:
      return BranchType::kFather;
    case PairKind::kSonNonManoeuvre:
    case PairKind::kSonManoeuvre:
      return BranchType::kSon;
    case PairKind::kGrandsonManoeuvre:
      return BranchType::kGrandson;
  }
  return BranchType::kFather;
}

inline std::string name(BranchType type, std::int64_t number) {
  std::string out(type == BranchType::kFather ? std::string_view("track") : to_string(type));
  out.append(" ").append(std::to_string(number));
  return out;
}

// A father with branches is suspended before gating once its prediction is this many times
// wider than delete_position_sigma. At 1.0 (the limit its own life applies to the posterior)
// it also suspended fathers whose update would suspend them anyway, and those now start
// their sons from the plots their update weighed (solve_kind); exp. 1, seeds 1-100: 0.6: 14
// number changes, 1.0: 12, 1.2 to 2.5: 10, never: 10 but exp. 2 and 3 worse.
inline constexpr double kSuspendBeforeGating = 1.2;

// The prior of a manoeuvre begun between two looks, in a branch's support: one look in ten
// (exp. 2 measured the same with 0.01, 51 %, and a little worse with 0.23, 50 %).
inline constexpr double kManoeuvreOnset = 0.1;

// A probability's log, floored so that a zero weight still orders branches.
inline double log_of(double p) {
  return std::log(std::max(p, 1e-300));
}

// True when the second likeliest plot above the miss weight has at least `tau`.
inline bool ambiguous(std::span<const double> beta, double miss, double tau) {
  double first = 0.0, second = 0.0;
  for (const double b : beta) {
    if (b <= miss) continue;
    if (b > first) {
      second = first;
      first = b;
    } else if (b > second) {
      second = b;
    }
  }
  return second >= tau;
}

}  // namespace skytrack::tracking_detail
