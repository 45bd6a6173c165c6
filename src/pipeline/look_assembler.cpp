#include "skytrack/pipeline/look_assembler.hpp"

#include <algorithm>
#include <numbers>

namespace skytrack {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// [rad] the narrowest look: sweeps closer than this are one azimuth (plots of one dwell).
constexpr double kEdge = 1e-6;

}  // namespace

void LookAssembler::add(const PlotScan& batch, std::span<const double> sweeps, double reached) {
  if (!started_) {
    // The first look starts just before the first plot: no track is older.
    from_ = reached;
    for (const double s : sweeps) from_ = std::min(from_, s);
    from_ -= 1e-9;
    reached_ = from_;
    started_ = true;
  }
  reached_ = std::max(reached_, reached);
  PlotScan header = batch;
  header.plots.clear();
  headers_.push_back(std::move(header));
  for (std::size_t i = 0; i < batch.plots.size(); ++i) {
    held_.push_back({batch.plots[i], sweeps[i], headers_.size() - 1});
  }
}

double LookAssembler::cut(std::span<const AzimuthSpan> spans, const AntennaSweep& antenna) {
  // After a gap of three revolutions or more, one look takes all: the gap's misses count once.
  if (reached_ - from_ >= 3.0 * kTwoPi) return reached_;
  // A look sweeps at most one revolution, so it never holds two plots of one target.
  const double last = std::min(reached_, from_ + kTwoPi);
  // Every revolution's instance of each span that reaches into (from, last]. A span of half
  // a revolution or more (a region round the radar) cannot be kept whole by any cut.
  merged_.clear();
  for (const AzimuthSpan& span : spans) {
    if (span.half >= 0.5 * std::numbers::pi) continue;
    for (double c = antenna.sweep_of(span.centre, from_ - span.half); c - span.half < last;
         c += kTwoPi) {
      merged_.push_back({c - span.half, c + span.half});
    }
  }
  std::sort(merged_.begin(), merged_.end(),
            [](const Interval& a, const Interval& b) { return a.low < b.low; });
  // The union of the spans, as disjoint intervals: the latest point at or before `last`
  // strictly inside none, which would split a search region between two looks.
  double c = last;
  double low = 0.0, high = -1.0;
  for (const Interval& s : merged_) {
    if (s.low > high) {
      if (low < c && c < high) break;
      low = s.low;
      high = s.high;
    } else {
      high = std::max(high, s.high);
    }
  }
  if (low < c && c < high) c = low;
  if (c > from_ + kEdge) return c;
  // None, and a revolution swept since the previous cut: the look is due anyway.
  return reached_ - from_ >= kTwoPi ? from_ + kTwoPi : from_;
}

bool LookAssembler::take(std::span<const AzimuthSpan> spans, const AntennaSweep& antenna,
                         Look& look) {
  if (headers_.empty()) return false;
  const double c = cut(spans, antenna);
  if (!(c > from_ + kEdge)) return false;
  release(c, look);
  // (from, c]: a sector's ends are both inside it, and the previous look took `from`.
  look.scan.coverage.reset();
  if (c - from_ < kTwoPi) look.scan.coverage = antenna.sector(from_ + kEdge, c);
  look.whole = false;
  from_ = c;
  return true;
}

void LookAssembler::take_all(Look& look) {
  if (headers_.empty()) return;
  double end = std::max(reached_, from_);
  for (const Held& h : held_) end = std::max(end, h.sweep);
  release(end, look);
  look.scan.coverage.reset();
  look.whole = true;
  from_ = end;
  reached_ = end;
}

void LookAssembler::release(double c, Look& look) {
  look.scan = headers_.back();
  look.scan.plots.clear();
  look.sweep_to = c;
  look.batches.clear();
  look.batch_of.clear();
  look.sweep.clear();
  kept_.clear();
  std::vector<int> index(headers_.size(), -2);  // header -> look.batches, -1 latest
  index.back() = -1;
  for (Held& h : held_) {
    if (h.sweep > c) {
      kept_.push_back(std::move(h));
      continue;
    }
    if (index[h.batch] == -2) {
      index[h.batch] = static_cast<int>(look.batches.size());
      look.batches.push_back(headers_[h.batch]);
    }
    look.scan.plots.push_back(std::move(h.plot));
    look.batch_of.push_back(index[h.batch]);
    look.sweep.push_back(h.sweep);
  }
  held_.swap(kept_);
  // Only the headers of plots still held (and the latest, for the next look) are kept.
  std::vector<std::size_t> renumber(headers_.size(), 0);
  std::vector<std::uint8_t> used(headers_.size(), 0);
  used.back() = 1;
  for (const Held& h : held_) used[h.batch] = 1;
  std::size_t next = 0;
  for (std::size_t b = 0; b < headers_.size(); ++b) {
    if (!used[b]) continue;
    renumber[b] = next;
    if (next != b) headers_[next] = std::move(headers_[b]);
    ++next;
  }
  headers_.resize(next);
  for (Held& h : held_) h.batch = renumber[h.batch];
}

}  // namespace skytrack
