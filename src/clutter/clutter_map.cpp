#include "skytrack/clutter/clutter_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace skytrack::clutter {
namespace {

constexpr int kExtra = kMaxMeasurementDim - 2;  // components after the mapped two
constexpr int kMinForSpread = 5;                // plots needed to trust a block's spread
constexpr double kMaxCells = 1 << 26;           // per axis, within the key's 28 bits

struct Cell {
  std::int64_t a = 0, b = 0;
};

struct Sums {  // of the counted plots in one cell
  int count = 0;
  std::array<double, kExtra> sum{}, square{};

  void add(const PlotMeasurement& p, int sign) {
    count += sign;
    for (int i = 2; i < p.z.size(); ++i) {
      sum[i - 2] += sign * p.z[i];
      square[i - 2] += sign * p.z[i] * p.z[i];
    }
  }
  void add(const Sums& o) {
    count += o.count;
    for (int i = 0; i < kExtra; ++i) {
      sum[i] += o.sum[i];
      square[i] += o.square[i];
    }
  }
};

// Cells of one measurement form; the azimuth axis wraps round.
struct Grid {
  double size_a = 1.0, size_b = 1.0;
  std::int64_t wrap_b = 0;  // number of azimuth cells, 0 for Cartesian

  Grid(const PlotMeasurement& p, const ClutterMapCells& cells) {
    if (is_polar(p.model.kind)) {
      size_a = cells.range;
      // Clamped before the cast: a cell far finer than any radar's (the loader refuses it)
      // must not overflow.
      wrap_b = static_cast<std::int64_t>(
          std::clamp(std::ceil(2.0 * std::numbers::pi / cells.azimuth), 3.0, kMaxCells));
      size_b = 2.0 * std::numbers::pi / static_cast<double>(wrap_b);
    } else {
      size_a = size_b = cells.cartesian;
    }
  }
  Cell cell_of(const PlotMeasurement& p) const {
    const double b = wrap_b > 0 ? p.z[1] + std::numbers::pi : p.z[1];
    return {index(p.z[0] / size_a), wrapped(index(b / size_b))};
  }
  // A cell index, clamped before the cast: a position far beyond any radar's reach (the
  // edges reject such plots; the map must not overflow on one that slips through).
  static std::int64_t index(double cells) {
    return static_cast<std::int64_t>(std::clamp(std::floor(cells), -kMaxCells, kMaxCells));
  }
  std::int64_t wrapped(std::int64_t b) const {
    return wrap_b > 0 ? ((b % wrap_b) + wrap_b) % wrap_b : b;
  }
  // Area of the 3 x 3 block round cell c; a polar block is clipped at zero range.
  double block_area(Cell c, bool polar) const {
    const double low = polar ? std::max(0.0, (c.a - 1) * size_a) : (c.a - 1) * size_a;
    return ((c.a + 2) * size_a - low) * 3.0 * size_b;
  }
};

int form_of(const PlotMeasurement& p) {
  return static_cast<int>(p.model.kind) * 8 + static_cast<int>(p.z.size());
}

std::uint64_t key(int form, Cell c) {
  // Form in the top byte; 28 bits per cell index (range cells of a few km: ample).
  const auto a = static_cast<std::uint64_t>(c.a + (1 << 27)) & 0xFFFFFFF;
  const auto b = static_cast<std::uint64_t>(c.b + (1 << 27)) & 0xFFFFFFF;
  return (static_cast<std::uint64_t>(form) << 56) | (a << 28) | b;
}

}  // namespace

void raise_to_local_density(std::span<const PlotMeasurement> plots,
                            std::span<const std::uint8_t> counted, const ClutterMapCells& cells,
                            std::vector<double>& density) {
  // Per form (a batch holds one or two): its grid and the extent of the counted plots in the
  // components after the mapped two. A short list, searched from the plot's form.
  struct Form {
    int id = 0;
    Grid grid;
    std::array<std::pair<double, double>, kExtra> extent{};
  };
  std::vector<Form> forms;
  const auto find_form = [&](int id) {
    for (std::size_t f = 0; f < forms.size(); ++f) {
      if (forms[f].id == id) return static_cast<int>(f);
    }
    return -1;
  };
  for (std::size_t j = 0; j < plots.size(); ++j) {
    if (counted[j] == 0) continue;
    const PlotMeasurement& p = plots[j];
    const int id = form_of(p);
    int f = find_form(id);
    const bool fresh = f < 0;
    if (fresh) {
      forms.push_back({id, Grid(p, cells), {}});
      f = static_cast<int>(forms.size()) - 1;
    }
    for (int i = 2; i < p.z.size(); ++i) {
      auto& [low, high] = forms[static_cast<std::size_t>(f)].extent[i - 2];
      low = fresh ? p.z[i] : std::min(low, p.z[i]);
      high = fresh ? p.z[i] : std::max(high, p.z[i]);
    }
  }
  std::vector<int> form_at(plots.size(), -1);
  for (std::size_t j = 0; j < plots.size(); ++j) form_at[j] = find_form(form_of(plots[j]));
  // Each cell's sums of counted plots (in plot order), in an open-addressing table keyed by
  // cell, and the 3 x 3 block round it, summed once for all the plots in the cell.
  std::vector<std::uint64_t> keys(plots.size(), 0);
  std::size_t slots = 16;
  while (slots < 2 * plots.size()) slots *= 2;
  std::vector<std::pair<std::uint64_t, std::int32_t>> table(slots, {0, -1});
  const auto slot_of = [&](std::uint64_t k) {
    std::size_t i = static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ULL) >> 20) & (slots - 1);
    while (table[i].second >= 0 && table[i].first != k) i = (i + 1) & (slots - 1);
    return i;
  };
  std::vector<Sums> sums;
  for (std::size_t j = 0; j < plots.size(); ++j) {
    const PlotMeasurement& p = plots[j];
    if (form_at[j] < 0) continue;
    const Form& form = forms[static_cast<std::size_t>(form_at[j])];
    keys[j] = key(form.id, form.grid.cell_of(p));
    auto& [k, at] = table[slot_of(keys[j])];
    if (at < 0) {
      k = keys[j];
      at = static_cast<std::int32_t>(sums.size());
      sums.emplace_back();
    }
    if (counted[j] != 0) sums[static_cast<std::size_t>(at)].add(p, +1);
  }
  std::vector<Sums> blocks(sums.size());
  std::vector<std::uint8_t> summed(sums.size(), 0);
  for (std::size_t j = 0; j < plots.size(); ++j) {
    const PlotMeasurement& p = plots[j];
    if (form_at[j] < 0) continue;
    const Form& form = forms[static_cast<std::size_t>(form_at[j])];
    const auto& extent = form.extent;
    const Grid& grid = form.grid;
    const Cell c = grid.cell_of(p);
    const auto at = static_cast<std::size_t>(table[slot_of(keys[j])].second);
    if (!summed[at]) {
      summed[at] = 1;
      for (std::int64_t da = -1; da <= 1; ++da) {
        for (std::int64_t db = -1; db <= 1; ++db) {
          const std::int32_t n =
              table[slot_of(key(form.id, {c.a + da, grid.wrapped(c.b + db)}))].second;
          if (n >= 0) blocks[at].add(sums[static_cast<std::size_t>(n)]);
        }
      }
    }
    Sums block = blocks[at];
    if (counted[j] != 0) block.add(p, -1);  // not itself
    if (block.count <= 0) continue;
    // The other components (elevation, range-rate, height) span what the block's plots span:
    // the width of a uniform spread with their variance, at most the form's extent (the
    // form's extent when the block holds too few plots), and at least the plot's own noise's:
    // no narrower spread can be told apart. Flight levels are whole steps, so plots on the
    // ground share one value and their extent is nil: without the floor an airport's few
    // uncounted plots made a density that called every plot round them clutter.
    double volume = grid.block_area(c, is_polar(p.model.kind));
    for (int i = 2; i < p.z.size(); ++i) {
      const auto [low, high] = extent[i - 2];
      double width = high - low;
      if (block.count >= kMinForSpread) {
        const double n = block.count;
        const double mean = block.sum[i - 2] / n;
        const double variance = std::max(0.0, block.square[i - 2] / n - mean * mean);
        width = std::min(std::sqrt(12.0 * variance), width);
      }
      volume *= std::max({width, std::sqrt(12.0) * p.model.sigma[i], 1e-6});
    }
    density[j] = std::max(density[j], block.count / volume);
  }
}

}  // namespace skytrack::clutter
