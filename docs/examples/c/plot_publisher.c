/* A minimal PlotBatch publisher for skytrackd, in C against Debian's Cyclone DDS (cyclonedds-dev)
 * and the C types idlc generates from share/skytrack/idl/skytrack.idl. It publishes one batch
 * per second of simulated time with one polar plot of an aircraft flying east at 200 m/s,
 * 20 km north of the radar, as skytrackd's default configuration expects them (topic
 * skytrack_plots, reliable, keep-all). Usage: plot_publisher [domain] [batches]
 * Run it with CYCLONEDDS_URI pointing at a loopback configuration (share/skytrack/dds). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dds/dds.h"
#include "skytrack.h"

int main(int argc, char** argv) {
  const dds_domainid_t domain = argc > 1 ? (dds_domainid_t)atoi(argv[1]) : 0;
  const int batches = argc > 2 ? atoi(argv[2]) : 20;
  const dds_entity_t participant = dds_create_participant(domain, NULL, NULL);
  if (participant < 0) {
    fprintf(stderr, "plot_publisher: participant: %s\n", dds_strretcode(-participant));
    return 1;
  }
  const dds_entity_t topic =
      dds_create_topic(participant, &skytrack_dds_PlotBatch_desc, "skytrack_plots", NULL, NULL);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(10));
  dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  const dds_entity_t writer = dds_create_writer(participant, topic, qos, NULL);
  dds_delete_qos(qos);
  if (writer < 0) {
    fprintf(stderr, "plot_publisher: writer: %s\n", dds_strretcode(-writer));
    return 1;
  }
  /* Wait (up to 10 s) for skytrackd's reader. */
  dds_publication_matched_status_t matched = {0};
  for (int i = 0; i < 1000 && matched.current_count == 0; ++i) {
    dds_get_publication_matched_status(writer, &matched);
    if (matched.current_count == 0) dds_sleepfor(DDS_MSECS(10));
  }
  if (matched.current_count == 0) {
    fprintf(stderr, "plot_publisher: no reader of skytrack_plots on domain %d\n", (int)domain);
    return 2;
  }
  int64_t id = 0;
  uint32_t flags = (1u << 0) | (1u << 1) | (1u << 2); /* time, range, azimuth: polar plot */
  double values[skytrack_dds_PLOT_STRIDE];
  skytrack_dds_PlotBatch batch;
  memset(&batch, 0, sizeof batch);
  batch.sensor = 1;
  batch.plot_ids._buffer = &id;
  batch.plot_ids._length = batch.plot_ids._maximum = 1;
  batch.plot_flags._buffer = &flags;
  batch.plot_flags._length = batch.plot_flags._maximum = 1;
  batch.plot_values._buffer = values;
  batch.plot_values._length = batch.plot_values._maximum = skytrack_dds_PLOT_STRIDE;
  for (int k = 0; k < batches; ++k) {
    const double t = (double)k, x = -2000.0 + 200.0 * t, y = 20000.0;
    memset(values, 0, sizeof values);
    values[0] = t;                   /* plot time [s] */
    values[1] = sqrt(x * x + y * y); /* range [m] */
    values[2] = atan2(x, y);         /* azimuth [rad], clockwise from north */
    if (values[2] < 0) values[2] += 2.0 * M_PI;
    batch.scan = (unsigned long long)k;
    batch.time = t;
    const dds_return_t rc = dds_write(writer, &batch);
    if (rc != DDS_RETCODE_OK) {
      fprintf(stderr, "plot_publisher: write: %s\n", dds_strretcode(-rc));
      return 1;
    }
    dds_sleepfor(DDS_MSECS(20));
  }
  printf("plot_publisher: %d batches published\n", batches);
  dds_sleepfor(DDS_MSECS(200)); /* let reliable delivery finish before leaving */
  dds_delete(participant);
  return 0;
}
