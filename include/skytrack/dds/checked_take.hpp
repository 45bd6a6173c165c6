#pragma once
// The one way skytrack takes samples from a DDS reader: serialized (dds_takecdr), checked
// against the type's layout (check_serialized) and only then deserialised by Cyclone, whose
// own validation in Debian's 0.10.2 lets malformed samples through to an unchecked read
// (sample_check.hpp, docs/dds-trust.md). A refused sample is reported, never deserialised.
#include <array>
#include <cstddef>

#include <dds/dds.h>

#include "skytrack/core/expected.hpp"
#include "skytrack/dds/conversion.hpp"

namespace skytrack::dds {

namespace detail {

/// Up to kCapacity serialized samples taken from a reader in one dds_takecdr call; releases
/// them on destruction.
class SerializedBatch {
 public:
  static constexpr std::size_t kCapacity = 32;

  explicit SerializedBatch(dds_entity_t reader);
  ~SerializedBatch();
  SerializedBatch(const SerializedBatch&) = delete;
  SerializedBatch& operator=(const SerializedBatch&) = delete;

  /// Samples taken (0 when none or on error).
  std::size_t size() const { return size_; }
  const dds_sample_info_t& info(std::size_t i) const { return infos_[i]; }
  /// Checks sample i against `type`, then has Cyclone deserialise it into `sample` (a zeroed
  /// sample of that type; Cyclone allocates its sequences and strings).
  Expected<void> read(std::size_t i, const dds_topic_descriptor_t& type, void* sample) const;

 private:
  std::array<ddsi_serdata*, kCapacity> data_{};
  std::array<dds_sample_info_t, kCapacity> infos_{};
  std::size_t size_ = 0;
};

}  // namespace detail

/// Takes every sample waiting in `reader` (or its read/query condition). Each data sample that
/// passes the check is deserialised into `scratch` and handed to
/// on_sample(const T&, const dds_sample_info_t&); each one refused goes to
/// on_malformed(const dds_sample_info_t&, const Error&). Disposals and unregistrations (no
/// data) go to neither. Samples come grouped by instance, as dds_take gives them. Returns the
/// number of samples taken.
template <class T, class OnSample, class OnMalformed>
std::size_t take_checked(dds_entity_t reader, OwnedSample<T>& scratch, OnSample&& on_sample,
                         OnMalformed&& on_malformed) {
  std::size_t taken = 0;
  for (;;) {
    const detail::SerializedBatch batch(reader);
    for (std::size_t i = 0; i < batch.size(); ++i) {
      if (!batch.info(i).valid_data) continue;
      scratch.reset();
      if (auto ok = batch.read(i, *topic_descriptor<T>(), scratch.data())) {
        on_sample(scratch.get(), batch.info(i));
      } else {
        on_malformed(batch.info(i), ok.error());
      }
    }
    taken += batch.size();
    if (batch.size() < detail::SerializedBatch::kCapacity) return taken;
  }
}

}  // namespace skytrack::dds
