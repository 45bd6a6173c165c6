// Cost of taking PlotBatch samples the checked way (dds_takecdr, check_serialized, Cyclone's
// read into our sample) against the plain loaned dds_take it replaced, both followed by
// from_dds, in one process on a loopback domain; and the check alone over the bytes.
// Usage: CYCLONEDDS_URI=file://$PWD/config/dds/loopback.xml build/bench/dds_take_bench
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <string>
#include <vector>

#include <dds/dds.h>
#include <dds/ddsi/ddsi_serdata.h>

#include "skytrack/dds/checked_take.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/dds/sample_check.hpp"

namespace {

using namespace skytrack;

PlotScan scan_of(int plots) {
  PlotScan scan;
  scan.sensor = 1;
  scan.scan = 1;
  scan.time = 1.0;
  for (int i = 0; i < plots; ++i) {
    Plot p;
    p.id = i;
    p.form = PlotForm::kCartesian;
    p.x = 100.0 * i;
    p.y = 50.0 * i;
    scan.plots.push_back(p);
  }
  return scan;
}

/// A participant on its own domain with a keep-all writer and reader of PlotBatch.
struct Endpoints {
  Endpoints() {
    const auto domain = static_cast<dds_domainid_t>(200 + getpid() % 20);
    participant = dds_create_participant(domain, nullptr, nullptr);
    const std::string name = "skytrack_take_bench_" + std::to_string(getpid());
    const dds_entity_t topic =
        dds_create_topic(participant, &skytrack_dds_PlotBatch_desc, name.c_str(), nullptr, nullptr);
    dds_qos_t* qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
    reader = dds_create_reader(participant, topic, qos, nullptr);
    writer = dds_create_writer(participant, topic, qos, nullptr);
    dds_delete_qos(qos);
  }
  ~Endpoints() { dds_delete(participant); }
  dds_entity_t participant = 0, reader = 0, writer = 0;
};

void BM_TakeLoaned(benchmark::State& state) {
  Endpoints e;
  const auto sample = dds::to_dds(scan_of(static_cast<int>(state.range(0))));
  PlotScan out;
  for (auto _ : state) {
    state.PauseTiming();
    dds_write(e.writer, sample->data());
    state.ResumeTiming();
    void* loaned[1] = {nullptr};
    dds_sample_info_t info{};
    if (dds_take(e.reader, loaned, &info, 1, 1) == 1) {
      benchmark::DoNotOptimize(
          dds::from_dds(*static_cast<const skytrack_dds_PlotBatch*>(loaned[0]), out));
      dds_return_loan(e.reader, loaned, 1);
    }
  }
}

void BM_TakeChecked(benchmark::State& state) {
  Endpoints e;
  const auto sample = dds::to_dds(scan_of(static_cast<int>(state.range(0))));
  dds::PlotBatchSample scratch;
  PlotScan out;
  for (auto _ : state) {
    state.PauseTiming();
    dds_write(e.writer, sample->data());
    state.ResumeTiming();
    dds::take_checked(
        e.reader, scratch,
        [&](const skytrack_dds_PlotBatch& b, const dds_sample_info_t&) {
          benchmark::DoNotOptimize(dds::from_dds(b, out));
        },
        [](const dds_sample_info_t&, const Error&) {});
  }
}

void BM_CheckOnly(benchmark::State& state) {
  Endpoints e;
  const auto sample = dds::to_dds(scan_of(static_cast<int>(state.range(0))));
  dds_write(e.writer, sample->data());
  ddsi_serdata* data = nullptr;
  dds_sample_info_t info{};
  if (dds_takecdr(e.reader, &data, 1, &info, DDS_ANY_STATE) != 1) {
    state.SkipWithError("no sample");
    return;
  }
  std::vector<std::byte> bytes(ddsi_serdata_size(data));
  ddsi_serdata_to_ser(data, 0, bytes.size(), bytes.data());
  ddsi_serdata_unref(data);
  for (auto _ : state) {
    benchmark::DoNotOptimize(dds::check_serialized(skytrack_dds_PlotBatch_desc, bytes));
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}

BENCHMARK(BM_TakeLoaned)->Arg(10)->Arg(100)->Arg(1000);
BENCHMARK(BM_TakeChecked)->Arg(10)->Arg(100)->Arg(1000);
BENCHMARK(BM_CheckOnly)->Arg(10)->Arg(100)->Arg(1000);

}  // namespace
