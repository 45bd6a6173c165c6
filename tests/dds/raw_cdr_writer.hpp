#pragma once
// Puts serialized bytes on a DDS topic with dds_writecdr, as any peer on the domain can: the
// crafted samples of issue 30, finding 7, reach readers without going through a C struct.
// Cyclone builds the serdata with its own validation (the one the crafted samples pass).
#include <unistd.h>
#include <string>

#include <span>

#include <dds/dds.h>
#include <dds/ddsi/ddsi_serdata.h>
#include <dds/ddsi/ddsi_sertype.h>

namespace skytrack::test {

class RawCdrWriter {
 public:
  /// `writer` writes topics of `type`; `sample` is any valid sample of that type, written once
  /// on a private topic of `participant` to learn Cyclone's sertype (0.10.2 has no public
  /// getter for it).
  RawCdrWriter(dds_entity_t participant, dds_entity_t writer, const dds_topic_descriptor_t* type,
               const void* sample)
      : writer_(writer) {
    const std::string name = "skytrack_sertype_probe_" + std::to_string(getpid());
    const dds_entity_t topic = dds_create_topic(participant, type, name.c_str(), nullptr, nullptr);
    dds_qos_t* qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
    const dds_entity_t reader = dds_create_reader(participant, topic, qos, nullptr);
    const dds_entity_t probe = dds_create_writer(participant, topic, qos, nullptr);
    dds_delete_qos(qos);
    ddsi_serdata* data = nullptr;
    dds_sample_info_t info{};
    if (dds_write(probe, sample) == DDS_RETCODE_OK &&
        dds_takecdr(reader, &data, 1, &info, DDS_ANY_STATE) == 1) {
      type_ = ddsi_sertype_ref(data->type);
      ddsi_serdata_unref(data);
    }
    dds_delete(probe);
    dds_delete(reader);
    dds_delete(topic);
  }
  ~RawCdrWriter() {
    if (type_ != nullptr) ddsi_sertype_unref(type_);
  }
  RawCdrWriter(const RawCdrWriter&) = delete;
  RawCdrWriter& operator=(const RawCdrWriter&) = delete;

  bool ready() const { return type_ != nullptr; }

  /// The serdata Cyclone builds from `bytes`, or null when its validation refuses them.
  ddsi_serdata* serdata(std::span<const std::byte> bytes) const {
    ddsrt_iovec_t iov{const_cast<std::byte*>(bytes.data()),
                      static_cast<ddsrt_iov_len_t>(bytes.size())};
    return ddsi_serdata_from_ser_iov(type_, SDK_DATA, 1, &iov, bytes.size());
  }

  /// Writes `bytes` as one sample; false when Cyclone refuses to build it or to write it.
  bool write(std::span<const std::byte> bytes) const {
    ddsi_serdata* data = serdata(bytes);
    return data != nullptr && dds_writecdr(writer_, data) == DDS_RETCODE_OK;  // takes `data`
  }

 private:
  dds_entity_t writer_;
  ddsi_sertype* type_ = nullptr;
};

}  // namespace skytrack::test
