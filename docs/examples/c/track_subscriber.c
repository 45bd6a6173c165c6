/* A minimal TrackBatch subscriber of skytrackd, in C against Debian's Cyclone DDS: prints one
 * line per batch (scan, time, tracks by status, the first confirmed track's position) until
 * `count` batches arrived or `timeout` seconds passed without one.
 * Usage: track_subscriber [domain] [count] [timeout]. Loopback CYCLONEDDS_URI, as above. */
#include <stdio.h>
#include <stdlib.h>

#include "dds/dds.h"
#include "skytrack.h"

int main(int argc, char** argv) {
  const dds_domainid_t domain = argc > 1 ? (dds_domainid_t)atoi(argv[1]) : 0;
  const int count = argc > 2 ? atoi(argv[2]) : 20;
  const double timeout = argc > 3 ? atof(argv[3]) : 10.0;
  const dds_entity_t participant = dds_create_participant(domain, NULL, NULL);
  if (participant < 0) {
    fprintf(stderr, "track_subscriber: participant: %s\n", dds_strretcode(-participant));
    return 1;
  }
  const dds_entity_t topic =
      dds_create_topic(participant, &skytrack_dds_TrackBatch_desc, "skytrack_tracks", NULL, NULL);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(10));
  dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  const dds_entity_t reader = dds_create_reader(participant, topic, qos, NULL);
  dds_delete_qos(qos);
  const dds_entity_t waitset = dds_create_waitset(participant);
  const dds_entity_t readable = dds_create_readcondition(reader, DDS_ANY_STATE);
  dds_waitset_attach(waitset, readable, reader);
  printf("track_subscriber: waiting on domain %d\n", (int)domain);
  fflush(stdout);
  int received = 0;
  while (received < count) {
    if (dds_waitset_wait(waitset, NULL, 0, (dds_duration_t)(timeout * 1e9)) <= 0) break;
    void* samples[16] = {NULL};
    dds_sample_info_t infos[16];
    const dds_return_t n = dds_take(reader, samples, infos, 16, 16); /* loaned */
    for (dds_return_t i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const skytrack_dds_TrackBatch* b = samples[i];
      unsigned by_status[4] = {0, 0, 0, 0};
      const skytrack_dds_Track* first = NULL;
      for (uint32_t t = 0; t < b->tracks._length; ++t) {
        const skytrack_dds_Track* track = &b->tracks._buffer[t];
        ++by_status[track->status];
        if (track->status == skytrack_dds_TRACK_CONFIRMED && first == NULL) first = track;
      }
      printf("scan %llu t=%.1f: %u tentative, %u confirmed, %u coasting",
             (unsigned long long)b->scan, b->time, by_status[0], by_status[1], by_status[2]);
      if (first != NULL) {
        printf("; track %lld at (%.0f, %.0f) m", (long long)first->id, first->position[0],
               first->position[1]);
      }
      printf("\n");
      ++received;
    }
    dds_return_loan(reader, samples, n);
    fflush(stdout);
  }
  printf("track_subscriber: %d batches received\n", received);
  dds_delete(participant);
  return received > 0 ? 0 : 2;
}
