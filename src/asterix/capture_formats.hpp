#pragma once
// Frame by frame through the two capture file formats: classic pcap (either byte order,
// micro- or nanosecond time stamps) and pcapng (sections of either byte order; interfaces
// with their link types and if_tsresol; enhanced, simple and obsolete packet blocks).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace skytrack::asterix::detail {

struct Frame {
  std::span<const std::uint8_t> data;
  std::size_t offset = 0;  // file offset of data[0]
  std::uint32_t link_type = 0;
  std::optional<double> time;  // [s] since the epoch
};

enum class FrameStatus : std::uint8_t { kFrame, kEnd, kDamaged };

/// Classic pcap. A damaged record header ends the file (nothing after it can be found).
class PcapCursor {
 public:
  /// False when `file` does not start with a pcap header.
  bool start(std::span<const std::uint8_t> file);
  FrameStatus next(Frame& frame, std::string& problem);
  std::size_t position() const { return pos_; }

 private:
  std::uint32_t u32(std::size_t at) const;
  std::span<const std::uint8_t> file_;
  std::size_t pos_ = 0;
  bool swapped_ = false;
  double tick_ = 1e-6;  // [s] of the fractional time stamp
  std::uint32_t link_type_ = 0;
};

/// pcapng. A block with a bad length ends the file; unknown blocks are skipped.
class PcapNgCursor {
 public:
  bool start(std::span<const std::uint8_t> file);
  FrameStatus next(Frame& frame, std::string& problem);
  std::size_t position() const { return pos_; }

 private:
  struct Interface {
    std::uint32_t link_type = 0;
    double tick = 1e-6;
  };
  std::uint32_t u32(std::size_t at) const;
  std::uint16_t u16(std::size_t at) const;
  void read_interface(std::size_t body, std::size_t body_end);
  std::span<const std::uint8_t> file_;
  std::size_t pos_ = 0;
  bool swapped_ = false;
  std::vector<Interface> interfaces_;
};

}  // namespace skytrack::asterix::detail
