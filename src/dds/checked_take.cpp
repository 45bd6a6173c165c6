#include "skytrack/dds/checked_take.hpp"

#include <span>

#include <dds/ddsi/ddsi_serdata.h>

#include "skytrack/dds/sample_check.hpp"

namespace skytrack::dds::detail {

SerializedBatch::SerializedBatch(dds_entity_t reader) {
  const dds_return_t n = dds_takecdr(reader, data_.data(), static_cast<std::uint32_t>(kCapacity),
                                     infos_.data(), DDS_ANY_STATE);
  size_ = n > 0 ? static_cast<std::size_t>(n) : 0;
}

SerializedBatch::~SerializedBatch() {
  for (std::size_t i = 0; i < size_; ++i) ddsi_serdata_unref(data_[i]);
}

Expected<void> SerializedBatch::read(std::size_t i, const dds_topic_descriptor_t& type,
                                     void* sample) const {
  ddsi_serdata* const data = data_[i];
  // A reference to the bytes Cyclone keeps (one contiguous block), not a copy.
  ddsrt_iovec_t bytes{};
  ddsi_serdata* const held = ddsi_serdata_to_ser_ref(data, 0, ddsi_serdata_size(data), &bytes);
  auto checked = check_serialized(
      type, std::span(static_cast<const std::byte*>(bytes.iov_base), bytes.iov_len));
  ddsi_serdata_to_ser_unref(held, &bytes);
  if (!checked) return checked;
  if (!ddsi_serdata_to_sample(data, sample, nullptr, nullptr)) {
    return make_error("Cyclone could not deserialise it");
  }
  return {};
}

}  // namespace skytrack::dds::detail
