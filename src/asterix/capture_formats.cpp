// pcap: tcpdump.org pcap-savefile(5); pcapng: IETF draft-ietf-opsawg-pcapng (SHB 0x0A0D0D0A,
// IDB 1, obsolete PB 2, SPB 3, EPB 6; if_tsresol option 9).
#include "capture_formats.hpp"

#include <cmath>

namespace skytrack::asterix::detail {
namespace {

std::uint32_t load32(const std::uint8_t* p, bool big) {
  return big ? (std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 |
                p[3])
             : (std::uint32_t{p[3]} << 24 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[1]} << 8 |
                p[0]);
}

constexpr std::uint32_t kPcapMicro = 0xA1B2C3D4, kPcapNano = 0xA1B23C4D;
constexpr std::uint32_t kSectionHeader = 0x0A0D0D0A, kByteOrderMagic = 0x1A2B3C4D;
constexpr std::uint32_t kInterfaceBlock = 1, kObsoletePacket = 2, kSimplePacket = 3,
                        kEnhancedPacket = 6;

}  // namespace

std::uint32_t PcapCursor::u32(std::size_t at) const {
  return load32(&file_[at], swapped_);
}

bool PcapCursor::start(std::span<const std::uint8_t> file) {
  file_ = file;
  if (file.size() < 24) return false;
  const std::uint32_t little = load32(file.data(), false);
  const std::uint32_t big = load32(file.data(), true);
  if (little == kPcapMicro || little == kPcapNano) {
    swapped_ = false;
  } else if (big == kPcapMicro || big == kPcapNano) {
    swapped_ = true;
  } else {
    return false;
  }
  tick_ = u32(0) == kPcapNano ? 1e-9 : 1e-6;
  link_type_ = u32(20) & 0x0FFFFFFFu;  // the upper bits may carry FCS information
  pos_ = 24;
  return true;
}

FrameStatus PcapCursor::next(Frame& frame, std::string& problem) {
  if (pos_ >= file_.size()) return FrameStatus::kEnd;
  if (file_.size() - pos_ < 16) {
    problem = "pcap record header cut short at the end of the file";
    pos_ = file_.size();
    return FrameStatus::kDamaged;
  }
  const std::size_t captured = u32(pos_ + 8);
  if (captured > file_.size() - pos_ - 16) {
    problem = "pcap record of " + std::to_string(captured) + " bytes runs past the end of the file";
    pos_ = file_.size();
    return FrameStatus::kDamaged;
  }
  frame.time = static_cast<double>(u32(pos_)) + static_cast<double>(u32(pos_ + 4)) * tick_;
  frame.link_type = link_type_;
  frame.offset = pos_ + 16;
  frame.data = file_.subspan(pos_ + 16, captured);
  pos_ += 16 + captured;
  return FrameStatus::kFrame;
}

std::uint32_t PcapNgCursor::u32(std::size_t at) const {
  return load32(&file_[at], swapped_);
}
std::uint16_t PcapNgCursor::u16(std::size_t at) const {
  return static_cast<std::uint16_t>(swapped_ ? (file_[at] << 8 | file_[at + 1])
                                             : (file_[at + 1] << 8 | file_[at]));
}

bool PcapNgCursor::start(std::span<const std::uint8_t> file) {
  file_ = file;
  pos_ = 0;
  return file.size() >= 12 && load32(file.data(), false) == kSectionHeader;
}

void PcapNgCursor::read_interface(std::size_t body, std::size_t body_end) {
  Interface interface;
  if (body + 8 > body_end) return interfaces_.push_back(interface);
  interface.link_type = u16(body);
  for (std::size_t at = body + 8; at + 4 <= body_end;) {  // options: code, length, value
    const std::uint16_t code = u16(at), length = u16(at + 2);
    if (code == 0 || at + 4 + length > body_end) break;
    if (code == 9 && length >= 1) {  // if_tsresol: 10^-n, or 2^-n with the top bit
      const std::uint8_t r = file_[at + 4];
      const double n = r & 0x7Fu;
      interface.tick = (r & 0x80u) ? std::pow(2.0, -n) : std::pow(10.0, -n);
    }
    at += 4 + ((length + 3u) & ~3u);
  }
  interfaces_.push_back(interface);
}

FrameStatus PcapNgCursor::next(Frame& frame, std::string& problem) {
  while (pos_ < file_.size()) {
    if (file_.size() - pos_ < 12) {
      problem = "pcapng block cut short at the end of the file";
      pos_ = file_.size();
      return FrameStatus::kDamaged;
    }
    const std::size_t at = pos_;
    if (load32(&file_[at], false) == kSectionHeader) {  // a new section: byte order, interfaces
      const std::uint32_t magic = load32(&file_[at + 8], false);
      if (magic != kByteOrderMagic && load32(&file_[at + 8], true) != kByteOrderMagic) {
        problem = "pcapng section header with a bad byte-order magic";
        pos_ = file_.size();
        return FrameStatus::kDamaged;
      }
      swapped_ = magic != kByteOrderMagic;
      interfaces_.clear();
    }
    const std::uint32_t type = u32(at);
    const std::size_t length = u32(at + 4);
    if (length < 12 || length % 4 != 0 || length > file_.size() - at) {
      problem = "pcapng block of length " + std::to_string(length) + " (type " +
                std::to_string(type) + ") does not fit the file";
      pos_ = file_.size();
      return FrameStatus::kDamaged;
    }
    pos_ = at + length;
    const std::size_t body = at + 8, body_end = at + length - 4;
    if (type == kInterfaceBlock) {
      read_interface(body, body_end);
      continue;
    }
    std::size_t header = 0, captured = 0, interface = 0;
    std::optional<std::uint64_t> stamp;
    if (type == kEnhancedPacket && body + 20 <= body_end) {
      interface = u32(body);
      stamp = std::uint64_t{u32(body + 4)} << 32 | u32(body + 8);
      captured = u32(body + 12);
      header = 20;
    } else if (type == kObsoletePacket && body + 20 <= body_end) {
      interface = u16(body);
      stamp = std::uint64_t{u32(body + 4)} << 32 | u32(body + 8);
      captured = u32(body + 12);
      header = 20;
    } else if (type == kSimplePacket && body + 4 <= body_end) {
      captured = std::min<std::size_t>(u32(body), body_end - body - 4);
      header = 4;
    } else {
      continue;  // other blocks (statistics, name resolution, custom...)
    }
    if (captured > body_end - body - header || interface >= interfaces_.size()) {
      problem = "pcapng packet block with a bad length or interface";
      return FrameStatus::kDamaged;  // the next block is still found by this one's length
    }
    const Interface& i = interfaces_[interface];
    frame.link_type = i.link_type;
    frame.time.reset();
    if (stamp) frame.time = static_cast<double>(*stamp) * i.tick;
    frame.offset = body + header;
    frame.data = file_.subspan(body + header, captured);
    return FrameStatus::kFrame;
  }
  return FrameStatus::kEnd;
}

}  // namespace skytrack::asterix::detail
