#include "skytrack/clutter/clutter_density.hpp"

#include <algorithm>
#include <numbers>

namespace skytrack::clutter {
namespace {

// Below this many plots of one form a look says nothing of its clutter density.
constexpr int kMinPlotsForDensity = 10;
constexpr double kRevolution = 2.0 * std::numbers::pi;

/// The box estimate of every used plot's form, written to `density` (0 for too few).
void box_density(std::span<const PlotMeasurement> plots, std::span<const std::uint8_t> used,
                 std::vector<double>& density) {
  struct Form {
    int kind, size, count = 0;
    MeasVec low, high;
  };
  std::vector<Form> forms;
  std::vector<int> form_of(plots.size(), -1);
  for (std::size_t j = 0; j < plots.size(); ++j) {
    if (!used[j]) continue;
    const PlotMeasurement& p = plots[j];
    const int kind = static_cast<int>(p.model.kind), size = static_cast<int>(p.z.size());
    auto it = std::find_if(forms.begin(), forms.end(),
                           [&](const Form& f) { return f.kind == kind && f.size == size; });
    if (it == forms.end()) {
      forms.push_back({kind, size, 0, p.z, p.z});
      it = std::prev(forms.end());
    }
    it->low = it->low.cwiseMin(p.z);
    it->high = it->high.cwiseMax(p.z);
    ++it->count;
    form_of[j] = static_cast<int>(it - forms.begin());
  }
  density.assign(plots.size(), 0.0);
  for (std::size_t j = 0; j < plots.size(); ++j) {
    if (form_of[j] < 0) continue;
    const Form& f = forms[static_cast<std::size_t>(form_of[j])];
    if (f.count < kMinPlotsForDensity) continue;
    double volume = 1.0;
    for (int i = 0; i < f.size; ++i) volume *= std::max(f.high[i] - f.low[i], 1e-6);
    density[j] = f.count / volume;
  }
}

}  // namespace

ClutterDensity::ClutterDensity(std::optional<ClutterMapCells> map)
    : map_enabled_(map.has_value()), cells_(map.value_or(ClutterMapCells{})) {}

void ClutterDensity::forget(std::vector<Seen>& window, double latest) const {
  std::erase_if(window, [&](const Seen& s) { return s.plot.sweep <= latest - kRevolution; });
}

void ClutterDensity::estimate(std::uint32_t sensor, bool windowed,
                              std::span<const PlotMeasurement> plots,
                              std::span<const std::uint8_t> boxed,
                              std::span<const std::uint8_t> counted, std::vector<double>& density) {
  const std::size_t n = plots.size();
  std::vector<Seen>* window = nullptr;
  if (windowed && n > 0) {
    window = &windows_[sensor];
    double latest = plots.front().sweep;
    for (const PlotMeasurement& p : plots) latest = std::max(latest, p.sweep);
    forget(*window, latest);
    if (window->empty()) window = nullptr;
  }
  if (window == nullptr) {  // the look's own plots
    box_density(plots, boxed, density);
    if (map_enabled_) raise_to_local_density(plots, counted, cells_, density);
    return;
  }
  // The last revolution's plots, then the look's.
  all_.clear();
  all_counted_.clear();
  all_used_.clear();
  for (const Seen& s : *window) {
    all_.push_back(s.plot);
    all_counted_.push_back(s.counted);
    all_used_.push_back(s.boxed);
  }
  const std::size_t first = all_.size();
  for (std::size_t j = 0; j < n; ++j) {
    all_.push_back(plots[j]);
    all_counted_.push_back(map_enabled_ ? counted[j] : 0);
    all_used_.push_back(boxed[j]);
  }
  box_density(all_, all_used_, all_density_);
  if (map_enabled_) raise_to_local_density(all_, all_counted_, cells_, all_density_);
  density.assign(all_density_.begin() + static_cast<std::ptrdiff_t>(first), all_density_.end());
}

void ClutterDensity::remember(std::uint32_t sensor, std::span<const PlotMeasurement> plots,
                              std::span<const std::uint8_t> rejected,
                              std::span<const std::uint8_t> boxed,
                              std::span<const std::uint8_t> counted) {
  std::vector<Seen>& window = windows_[sensor];
  for (std::size_t j = 0; j < plots.size(); ++j) {
    if (rejected[j]) continue;
    window.push_back(
        {plots[j], map_enabled_ && !counted.empty() ? counted[j] : std::uint8_t{0}, boxed[j]});
  }
}

}  // namespace skytrack::clutter
