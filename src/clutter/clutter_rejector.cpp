// Paper 000 §3.1 (measurement preprocessing of LBP-PHD group tracking):
//   step 1, clutter rejection: Gaussian kernel density at each plot (eq. 6-7) and the
//           threshold tau = f_min + (beta / N_f)(f_max - f_min) (eq. 8);
//   step 2, mean-shift partitioning of the kept plots: mean-shift vector (eq. 9) and
//           iteration z <- sum_i z_i G(z, z_i) / sum_i G(z, z_i) (eq. 10), close converged
//           points merged into one cell;
//   step 3, the interval hull of each cell is its measurement box (eq. 11).
// Eq. 7 is printed with |z - z_i| in the exponent; the normalisation (2 pi h^2)^(d/2) is that
// of a Gaussian, so the squared distance is meant and used here. The kernel is truncated at
// c h (c = truncation_sigmas), which lets a k-d tree radius search (nanoflann) replace the
// O(N^2) double sum; docs/clutter_rejection.md bounds the error.
#include "skytrack/clutter/clutter_rejector.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <nanoflann.hpp>

namespace skytrack::clutter {
namespace {

// Densities whose spread (f_max - f_min) is below this fraction of f_max are all equal:
// summation order alone must not split a regular pattern into kept and rejected plots.
constexpr double kEqualDensityTolerance = 1e-9;

// nanoflann dataset adaptor over contiguous points; unused coordinates are 0.
struct PointCloud {
  std::vector<Eigen::Vector3d> points;

  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::uint32_t index, std::size_t dim) const {
    return points[index][static_cast<Eigen::Index>(dim)];
  }
  template <class BoundingBox>
  bool kdtree_get_bbox(BoundingBox& /*box*/) const {
    return false;  // let nanoflann compute it
  }
};

template <int D>
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>,
                                                   PointCloud, D, std::uint32_t>;

// A nanoflann result set that hands every point with |x - p|^2 < radius_sq to `visit`,
// storing nothing: the kernel sums are accumulated during the tree walk, without allocation.
template <class Visit>
struct RadiusVisitor {
  double radius_sq;
  Visit visit;
  std::size_t count = 0;

  void init() { count = 0; }
  std::size_t size() const { return count; }
  bool full() const { return true; }
  double worstDist() const { return radius_sq; }
  bool addPoint(double squared_distance, std::uint32_t index) {
    visit(squared_distance, index);
    ++count;
    return true;
  }
};

template <int D, class Visit>
void visit_radius(const KdTree<D>& tree, const Eigen::Vector3d& centre, double radius_sq,
                  Visit&& visit) {
  RadiusVisitor<Visit&> result_set{radius_sq, visit};
  tree.findNeighbors(result_set, centre.data(), nanoflann::SearchParams());
}

const nanoflann::KDTreeSingleIndexAdaptorParams kDeferredBuild{
    10, nanoflann::KDTreeSingleIndexAdaptorFlags::SkipInitialBuildIndex};

// One k-d tree per point set, for a fixed dimension; rebuilt each scan over reused clouds.
template <int D>
struct Trees {
  Trees(const PointCloud& plot_cloud, const PointCloud& kept_cloud, const PointCloud& mode_cloud)
      : plots(D, plot_cloud, kDeferredBuild),
        kept(D, kept_cloud, kDeferredBuild),
        modes(D, mode_cloud, kDeferredBuild) {}
  KdTree<D> plots;  // all valid plots: density (eq. 6-7)
  KdTree<D> kept;   // kept plots: mean-shift (eq. 10)
  KdTree<D> modes;  // converged points: merging
};

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

// The smaller index becomes the root, so a component's root is its first kept plot whatever
// the order of the unions: the partition and its labels are order-independent.
void unite(std::vector<int>& parent, int a, int b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a < b) {
    parent[b] = a;
  } else if (b < a) {
    parent[a] = b;
  }
}

}  // namespace

namespace detail {

struct ClutterWorkspace {
  PointCloud plots;                // valid plots, dims coordinates
  std::vector<int> plot_of_valid;  // input index of each valid plot
  PointCloud kept;                 // kept plots
  std::vector<int> plot_of_kept;   // input index of each kept plot
  PointCloud modes;                // converged mean-shift point of each kept plot
  std::vector<int> parent;         // union-find over kept plots
  std::vector<int> label_of_root;  // cell label of each union-find root
  Trees<2> trees2{plots, kept, modes};
  Trees<3> trees3{plots, kept, modes};
};

}  // namespace detail

namespace {

using detail::ClutterWorkspace;

void reset_result(ClutterRejectionResult& r, std::size_t n) {
  r.keep.assign(n, 0);
  r.cell.assign(n, -1);
  r.density.assign(n, 0.0);
  r.cells = 0;
  r.rejected = 0;
  r.protected_kept = 0;
  r.invalid = 0;
  r.mean_shift_steps = 0;
  r.threshold = 0.0;
  r.boxes.clear();
}

// Copies the finite plots, zeroing the coordinates beyond dims.
void load_valid_plots(std::span<const Eigen::Vector3d> positions, int dims, ClutterWorkspace& ws,
                      ClutterRejectionResult& r) {
  ws.plots.points.clear();
  ws.plot_of_valid.clear();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    Eigen::Vector3d p = positions[i];
    if (dims == 2) {
      p.z() = 0.0;
    }
    if (!p.allFinite()) {
      ++r.invalid;
      continue;
    }
    ws.plots.points.push_back(p);
    ws.plot_of_valid.push_back(static_cast<int>(i));
  }
}

// Eq. 6-7 with the kernel truncated at c h; the radius search finds the plot itself (d = 0),
// as the paper's sum over i = 1..N includes it.
template <int D>
void compute_density(const KdTree<D>& tree, const ClutterWorkspace& ws, double h, double c,
                     ClutterRejectionResult& r) {
  const double inv_two_h2 = 1.0 / (2.0 * h * h);
  const double radius_sq = (c * h) * (c * h);
  const double norm =
      gaussian_kernel(0.0, h, D) / static_cast<double>(ws.plots.points.size());  // G(0) / N
  for (std::size_t v = 0; v < ws.plots.points.size(); ++v) {
    double sum = 0.0;
    visit_radius<D>(tree, ws.plots.points[v], radius_sq,
                    [&sum, inv_two_h2](double d2, auto) { sum += std::exp(-d2 * inv_two_h2); });
    r.density[static_cast<std::size_t>(ws.plot_of_valid[v])] = norm * sum;
  }
}

// Eq. 8 and the protection rule.
void apply_threshold(const config::ClutterRejectionSpec& spec,
                     std::span<const std::uint8_t> protected_plots, const ClutterWorkspace& ws,
                     ClutterRejectionResult& r) {
  if (ws.plot_of_valid.empty()) {
    return;
  }
  double f_min = std::numeric_limits<double>::infinity();
  double f_max = -f_min;
  for (const int i : ws.plot_of_valid) {
    f_min = std::min(f_min, r.density[static_cast<std::size_t>(i)]);
    f_max = std::max(f_max, r.density[static_cast<std::size_t>(i)]);
  }
  const bool all_equal = f_max - f_min <= kEqualDensityTolerance * f_max;
  const double tau = all_equal ? f_min : clutter_threshold(f_min, f_max, spec.beta, spec.n_f);
  r.threshold = tau;
  for (const int i : ws.plot_of_valid) {
    const auto u = static_cast<std::size_t>(i);
    const bool below = r.density[u] < tau;
    const bool is_protected = u < protected_plots.size() && protected_plots[u] != 0;
    r.keep[u] = (!below || is_protected) ? 1 : 0;
    if (below && is_protected) {
      ++r.protected_kept;
    }
  }
}

void collect_kept(ClutterWorkspace& ws, ClutterRejectionResult& r) {
  ws.kept.points.clear();
  ws.plot_of_kept.clear();
  for (std::size_t v = 0; v < ws.plot_of_valid.size(); ++v) {
    if (r.keep[static_cast<std::size_t>(ws.plot_of_valid[v])] != 0) {
      ws.kept.points.push_back(ws.plots.points[v]);
      ws.plot_of_kept.push_back(ws.plot_of_valid[v]);
    }
  }
  r.rejected = static_cast<int>(r.keep.size() - ws.kept.points.size());
}

// Eq. 10 from each kept plot until a step is shorter than the tolerance.
template <int D>
int climb_modes(const KdTree<D>& tree, ClutterWorkspace& ws, const config::MeanShiftSpec& ms,
                double c) {
  int steps = 0;
  const double inv_two_h2 = 1.0 / (2.0 * ms.bandwidth * ms.bandwidth);
  const double radius_sq = (c * ms.bandwidth) * (c * ms.bandwidth);
  const double tolerance_sq = ms.tolerance * ms.tolerance;
  const std::vector<Eigen::Vector3d>& kept = ws.kept.points;
  ws.modes.points.resize(kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k) {
    Eigen::Vector3d x = kept[k];
    for (int iteration = 0; iteration < ms.max_iterations; ++iteration) {
      Eigen::Vector3d weighted_sum = Eigen::Vector3d::Zero();  // sum_i z_i G(x, z_i)
      double weight_sum = 0.0;                                 // sum_i G(x, z_i)
      visit_radius<D>(tree, x, radius_sq, [&](double d2, std::uint32_t j) {
        const double w = std::exp(-d2 * inv_two_h2);
        weighted_sum += w * kept[j];
        weight_sum += w;
      });
      if (!(weight_sum > 0.0)) {
        break;  // no kept plot within the truncation radius: x is as far as it gets
      }
      ++steps;
      const Eigen::Vector3d next = weighted_sum / weight_sum;
      const double step_sq = (next - x).squaredNorm();  // |a(x)|^2, eq. 9
      x = next;
      if (step_sq < tolerance_sq) {
        break;
      }
    }
    ws.modes.points[k] = x;
  }
  return steps;
}

// Converged points within merge_distance (inclusive) of each other join one cell.
template <int D>
void merge_modes(const KdTree<D>& tree, ClutterWorkspace& ws, double merge_distance) {
  const int count = static_cast<int>(ws.modes.points.size());
  ws.parent.resize(ws.modes.points.size());
  for (int k = 0; k < count; ++k) {
    ws.parent[static_cast<std::size_t>(k)] = k;
  }
  // nanoflann keeps d^2 < radius_sq; the next double up makes the test d <= merge_distance.
  const double radius_sq =
      std::nextafter(merge_distance * merge_distance, std::numeric_limits<double>::infinity());
  for (int k = 0; k < count; ++k) {
    visit_radius<D>(
        tree, ws.modes.points[static_cast<std::size_t>(k)], radius_sq,
        [&ws, k](double, std::uint32_t j) { unite(ws.parent, k, static_cast<int>(j)); });
  }
}

// Labels 0..cells-1 in order of first plot index; boxes as interval hulls (eq. 11).
void label_cells(ClutterWorkspace& ws, ClutterRejectionResult& r) {
  const std::size_t count = ws.plot_of_kept.size();
  ws.label_of_root.assign(count, -1);
  for (std::size_t k = 0; k < count; ++k) {
    const auto root = static_cast<std::size_t>(find_root(ws.parent, static_cast<int>(k)));
    if (ws.label_of_root[root] < 0) {
      ws.label_of_root[root] = r.cells++;
    }
    r.cell[static_cast<std::size_t>(ws.plot_of_kept[k])] = ws.label_of_root[root];
  }
  const double inf = std::numeric_limits<double>::infinity();
  r.boxes.assign(static_cast<std::size_t>(r.cells),
                 MeasurementBox{Eigen::Vector3d::Constant(inf), Eigen::Vector3d::Constant(-inf)});
  for (std::size_t k = 0; k < count; ++k) {
    MeasurementBox& box = r.boxes[static_cast<std::size_t>(r.cell[ws.plot_of_kept[k]])];
    box.lower = box.lower.cwiseMin(ws.kept.points[k]);
    box.upper = box.upper.cwiseMax(ws.kept.points[k]);
  }
}

template <int D>
void run(const config::ClutterRejectionSpec& spec, double c,
         std::span<const std::uint8_t> protected_plots, ClutterWorkspace& ws, Trees<D>& trees,
         ClutterRejectionResult& r) {
  if (spec.enabled) {
    trees.plots.buildIndex();
    compute_density<D>(trees.plots, ws, spec.kernel_bandwidth, c, r);
    apply_threshold(spec, protected_plots, ws, r);
  } else {
    for (const int i : ws.plot_of_valid) {
      r.keep[static_cast<std::size_t>(i)] = 1;
    }
  }
  collect_kept(ws, r);
  trees.kept.buildIndex();
  r.mean_shift_steps = climb_modes<D>(trees.kept, ws, spec.mean_shift, c);
  trees.modes.buildIndex();
  merge_modes<D>(trees.modes, ws, spec.mean_shift.merge_distance);
  label_cells(ws, r);
}

void require(bool ok, const char* what) {
  if (!ok) {
    throw std::invalid_argument(std::string("ClutterRejector: ") + what);
  }
}

// Startup check; the profile loader enforces the same ranges on YAML input.
void check_spec(const config::ClutterRejectionSpec& spec, double truncation_sigmas) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  const config::MeanShiftSpec& ms = spec.mean_shift;
  require(positive(spec.kernel_bandwidth), "kernel_bandwidth must be > 0");
  require(spec.n_f >= 1 && spec.beta >= 0, "need n_f >= 1 and beta >= 0");
  require(positive(ms.bandwidth), "mean_shift.bandwidth must be > 0");
  require(std::isfinite(ms.merge_distance) && ms.merge_distance >= 0.0,
          "mean_shift.merge_distance must be >= 0");
  require(ms.max_iterations >= 0, "mean_shift.max_iterations must be >= 0");
  require(std::isfinite(ms.tolerance) && ms.tolerance >= 0.0, "mean_shift.tolerance must be >= 0");
  require(positive(truncation_sigmas), "truncation_sigmas must be > 0");
}

}  // namespace

double gaussian_kernel(double squared_distance, double bandwidth, int dims) noexcept {
  const double two_h2 = 2.0 * bandwidth * bandwidth;
  return std::pow(std::numbers::pi * two_h2, -0.5 * dims) * std::exp(-squared_distance / two_h2);
}

double clutter_threshold(double f_min, double f_max, int beta, int n_f) noexcept {
  const int bins = std::max(n_f, 1);
  return f_min + (static_cast<double>(beta) / bins) * (f_max - f_min);
}

double truncation_error_bound(double bandwidth, int dims, double truncation_sigmas) noexcept {
  return gaussian_kernel(0.0, bandwidth, dims) *
         std::exp(-0.5 * truncation_sigmas * truncation_sigmas);
}

ClutterRejector::ClutterRejector(const config::ClutterRejectionSpec& spec, double truncation_sigmas)
    : spec_(spec),
      truncation_sigmas_(truncation_sigmas),
      workspace_(std::make_unique<detail::ClutterWorkspace>()) {
  check_spec(spec_, truncation_sigmas_);  // startup code: may throw
}

ClutterRejector::~ClutterRejector() = default;
ClutterRejector::ClutterRejector(ClutterRejector&&) noexcept = default;
ClutterRejector& ClutterRejector::operator=(ClutterRejector&&) noexcept = default;

const ClutterRejectionResult& ClutterRejector::apply(
    std::span<const Eigen::Vector3d> positions, int dims,
    std::span<const std::uint8_t> protected_plots) noexcept {
  assert(workspace_ && "apply() on a moved-from ClutterRejector");
  assert((dims == 2 || dims == 3) && "ClutterRejector works in 2 or 3 dimensions");
  const int d = dims >= 3 ? 3 : 2;
  detail::ClutterWorkspace& ws = *workspace_;
  reset_result(result_, positions.size());
  load_valid_plots(positions, d, ws, result_);
  if (d == 2) {
    run<2>(spec_, truncation_sigmas_, protected_plots, ws, ws.trees2, result_);
  } else {
    run<3>(spec_, truncation_sigmas_, protected_plots, ws, ws.trees3, result_);
  }
  return result_;
}

}  // namespace skytrack::clutter
