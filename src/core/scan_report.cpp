#include "skytrack/core/scan_report.hpp"

#include <algorithm>

namespace skytrack {

void ScanReport::add_later_look(const ScanReport& look) {
  plots += look.plots;
  plots_invalid += look.plots_invalid;
  plots_rejected_clutter += look.plots_rejected_clutter;
  plots_in_clouds += look.plots_in_clouds;
  tentative = look.tentative;
  confirmed = look.confirmed;
  coasting = look.coasting;
  initiated += look.initiated;
  initiations_refused += look.initiations_refused;
  chains_held += look.chains_held;
  deleted += look.deleted;
  numeric_failures += look.numeric_failures;
  predict += look.predict;
  associate += look.associate;
  manage += look.manage;
  point.clusters += look.point.clusters;
  point.largest_cluster = std::max(point.largest_cluster, look.point.largest_cluster);
  point.approximated_clusters += look.point.approximated_clusters;
  point.branches = look.point.branches;
  point.branches_created += look.point.branches_created;
  point.branches_promoted += look.point.branches_promoted;
  point.branches_pruned += look.point.branches_pruned;
}

}  // namespace skytrack
