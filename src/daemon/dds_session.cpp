#include "skytrack/daemon/dds_session.hpp"

#include <thread>
#include <utility>
#include <vector>

#include "skytrack/daemon/dds_environment.hpp"

namespace skytrack::daemon {
namespace {

QosPtr make_qos() {
  return QosPtr(dds_create_qos());
}

Error dds_error(const std::string& what, dds_return_t code) {
  return Error{what + ": " + dds_strretcode(code)};
}

QosPtr partition_qos(const DdsSettings& dds) {
  QosPtr qos = make_qos();
  if (!dds.partitions.empty()) {
    std::vector<const char*> names;
    for (const auto& p : dds.partitions) names.push_back(p.c_str());
    dds_qset_partition(qos.get(), static_cast<std::uint32_t>(names.size()), names.data());
  }
  return qos;
}

template <class Status, class Get>
bool wait_matched(dds_entity_t entity, std::uint32_t count, std::chrono::milliseconds timeout,
                  const std::function<bool()>& keep_waiting, Get get) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    Status status{};
    if (get(entity, &status) != DDS_RETCODE_OK) return false;
    if (status.current_count >= count) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    if (keep_waiting && !keep_waiting()) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace

QosPtr plots_reader_qos(const DdsSettings& dds) {
  QosPtr qos = make_qos();
  if (dds.plots.reliability == Reliability::kReliable) {
    dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  } else {
    dds_qset_reliability(qos.get(), DDS_RELIABILITY_BEST_EFFORT, 0);
  }
  if (dds.plots.history_depth == 0) {
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_ALL, 0);
  } else {
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, dds.plots.history_depth);
  }
  dds_qset_durability(qos.get(), DDS_DURABILITY_VOLATILE);
  return qos;
}

QosPtr plots_writer_qos(const DdsSettings& dds) {
  QosPtr qos = make_qos();
  if (dds.plots.reliability == Reliability::kReliable) {
    // Keep all and block (up to 10 s) while the reader's acknowledgements lag: flow control.
    dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, DDS_SECS(10));
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_ALL, 0);
  } else {
    dds_qset_reliability(qos.get(), DDS_RELIABILITY_BEST_EFFORT, 0);
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, 1);
  }
  dds_qset_durability(qos.get(), DDS_DURABILITY_VOLATILE);
  return qos;
}

QosPtr tracks_writer_qos(const DdsSettings& dds) {
  QosPtr qos = make_qos();
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, dds.tracks.history_depth);
  dds_qset_durability(qos.get(), dds.tracks.durability == Durability::kTransientLocal
                                     ? DDS_DURABILITY_TRANSIENT_LOCAL
                                     : DDS_DURABILITY_VOLATILE);
  return qos;
}

QosPtr tracks_reader_qos(const DdsSettings& dds, bool keep_all) {
  QosPtr qos = make_qos();
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  if (keep_all) {
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_ALL, 0);
  } else {
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, dds.tracks.history_depth);
  }
  dds_qset_durability(qos.get(), dds.tracks.durability == Durability::kTransientLocal
                                     ? DDS_DURABILITY_TRANSIENT_LOCAL
                                     : DDS_DURABILITY_VOLATILE);
  return qos;
}

QosPtr status_writer_qos(const DdsSettings& dds) {
  QosPtr qos = make_qos();
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, 1);
  dds_qset_durability(qos.get(), DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_deadline(qos.get(), static_cast<dds_duration_t>(dds.status.deadline * 1e9));
  return qos;
}

QosPtr status_reader_qos(const DdsSettings& dds) {
  return status_writer_qos(dds);
}

Expected<DdsSession> DdsSession::open(const DdsSettings& dds) {
  auto configuration = ensure_dds_configuration();
  if (!configuration) return unexpected(configuration.error());
  DdsSession s;
  s.configuration_ = *configuration;
  s.participant_ =
      dds_create_participant(static_cast<dds_domainid_t>(dds.domain), nullptr, nullptr);
  if (s.participant_ < 0) {
    const dds_return_t code = s.participant_;
    s.participant_ = 0;
    return unexpected(dds_error("creating the DDS participant on domain " +
                                    std::to_string(dds.domain) + " (" + s.configuration_ + ")",
                                code));
  }
  const QosPtr partitions = partition_qos(dds);
  s.publisher_ = dds_create_publisher(s.participant_, partitions.get(), nullptr);
  if (s.publisher_ < 0) return unexpected(dds_error("creating the publisher", s.publisher_));
  s.subscriber_ = dds_create_subscriber(s.participant_, partitions.get(), nullptr);
  if (s.subscriber_ < 0) return unexpected(dds_error("creating the subscriber", s.subscriber_));
  return s;
}

DdsSession::DdsSession(DdsSession&& other) noexcept
    : participant_(std::exchange(other.participant_, 0)),
      publisher_(other.publisher_),
      subscriber_(other.subscriber_),
      configuration_(std::move(other.configuration_)) {}

DdsSession& DdsSession::operator=(DdsSession&& other) noexcept {
  if (this != &other) {
    if (participant_ > 0) dds_delete(participant_);
    participant_ = std::exchange(other.participant_, 0);
    publisher_ = other.publisher_;
    subscriber_ = other.subscriber_;
    configuration_ = std::move(other.configuration_);
  }
  return *this;
}

DdsSession::~DdsSession() {
  if (participant_ > 0) dds_delete(participant_);
}

Expected<dds_entity_t> DdsSession::topic(const dds_topic_descriptor_t* descriptor,
                                         const std::string& name) {
  const dds_entity_t t = dds_create_topic(participant_, descriptor, name.c_str(), nullptr, nullptr);
  if (t < 0) return unexpected(dds_error("creating topic '" + name + "'", t));
  return t;
}

Expected<dds_entity_t> DdsSession::reader(dds_entity_t topic, const dds_qos_t* qos) {
  const dds_entity_t r = dds_create_reader(subscriber_, topic, qos, nullptr);
  if (r < 0) return unexpected(dds_error("creating a reader", r));
  return r;
}

Expected<dds_entity_t> DdsSession::writer(dds_entity_t topic, const dds_qos_t* qos) {
  const dds_entity_t w = dds_create_writer(publisher_, topic, qos, nullptr);
  if (w < 0) return unexpected(dds_error("creating a writer", w));
  return w;
}

bool wait_for_readers(dds_entity_t writer, std::uint32_t count, std::chrono::milliseconds timeout,
                      const std::function<bool()>& keep_waiting) {
  return wait_matched<dds_publication_matched_status_t>(writer, count, timeout, keep_waiting,
                                                        dds_get_publication_matched_status);
}

bool wait_for_writers(dds_entity_t reader, std::uint32_t count, std::chrono::milliseconds timeout,
                      const std::function<bool()>& keep_waiting) {
  return wait_matched<dds_subscription_matched_status_t>(reader, count, timeout, keep_waiting,
                                                         dds_get_subscription_matched_status);
}

}  // namespace skytrack::daemon
