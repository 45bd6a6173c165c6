#include "skytrack/dds/sample_check.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include <dds/ddsc/dds_opcodes.h>

namespace skytrack::dds {
namespace {

// Encapsulation identifiers, big-endian in header bytes 0..1 (XTypes 1.3, 7.6.3.1.2).
constexpr std::uint16_t kDelimitedCdr2Be = 0x0008;
constexpr std::uint16_t kDelimitedCdr2Le = 0x0009;
// The ops of a type are static, so nesting is bounded by the IDL; this only sizes the path.
constexpr std::size_t kMaxDepth = 8;
// Smallest wire size of one string: its length and the terminating NUL.
constexpr std::uint64_t kMinString = 5;

std::string hex(std::uint32_t value) {
  std::array<char, 12> text{};
  std::snprintf(text.data(), text.size(), "0x%x", value);
  return text.data();
}

std::uint32_t primitive_size(std::uint32_t code) {
  switch (code) {
    case DDS_OP_VAL_1BY:
      return 1;
    case DDS_OP_VAL_2BY:
      return 2;
    case DDS_OP_VAL_4BY:
      return 4;
    case DDS_OP_VAL_8BY:
      return 8;
    default:
      return 0;
  }
}

/// Words taken by the ADR instruction at `ops`, or 0 for a construct the checker does not
/// know (optional and external members change the layout, so they count as unknown too).
std::uint32_t adr_words(const std::uint32_t* ops) {
  const std::uint32_t insn = ops[0];
  if (DDS_OP(insn) != DDS_OP_ADR || (insn & DDS_OP_FLAG_EXT) != 0 ||
      (DDS_OP_FLAGS(insn) & DDS_OP_FLAG_OPT) != 0) {
    return 0;
  }
  const std::uint32_t sub = DDS_OP_SUBTYPE(insn);
  switch (DDS_OP_TYPE(insn)) {
    case DDS_OP_VAL_1BY:
    case DDS_OP_VAL_2BY:
    case DDS_OP_VAL_4BY:
    case DDS_OP_VAL_8BY:
    case DDS_OP_VAL_BLN:
    case DDS_OP_VAL_STR:
      return 2;
    case DDS_OP_VAL_ENU:
      return DDS_OP_TYPE_SZ(insn) == 4 ? 3 : 0;
    case DDS_OP_VAL_ARR:
      if (primitive_size(sub) != 0 || sub == DDS_OP_VAL_BLN) return 3;
      return sub == DDS_OP_VAL_ENU && DDS_OP_TYPE_SZ(insn) == 4 ? 4 : 0;
    case DDS_OP_VAL_SEQ:
      if (primitive_size(sub) != 0 || sub == DDS_OP_VAL_STR) return 2;
      if (sub == DDS_OP_VAL_STU) return DDS_OP_ADR_JMP(ops[3]) != 0 ? DDS_OP_ADR_JMP(ops[3]) : 4;
      return 0;
    default:
      return 0;
  }
}

class Walker {
 public:
  Walker(const std::byte* body, std::size_t size, bool swap)
      : body_(body), size_(size), swap_(swap) {}

  /// A struct at the current offset, ending at or before `end`: delimited (DLC, appendable)
  /// or plain (final).
  bool type(const std::uint32_t* ops, std::size_t end);
  std::string error(const char* type_name) const;

 private:
  struct Step {
    std::uint32_t member = 0;
    std::int64_t element = -1;  // index inside a sequence member, -1 when none
  };

  bool member(const std::uint32_t* ops, std::size_t end);
  bool sequence(const std::uint32_t* ops, std::size_t end);
  bool align(std::size_t a, std::size_t end);
  bool u32(std::size_t end, std::uint32_t& value);
  /// `count` primitives of `size` bytes.
  bool primitives(std::uint32_t size, std::uint64_t count, std::size_t end);
  bool booleans(std::uint64_t count, std::size_t end);
  bool enums(std::uint64_t count, std::uint32_t max, std::size_t end);
  bool string(std::size_t end);
  /// Reads a DHEADER and returns the end of the region it delimits, or 0 on failure (a
  /// region ends after its own header, never at 0).
  std::size_t region(std::size_t end);
  bool fail(std::string what);
  static std::string bytes_left(std::uint64_t need, std::size_t left);

  const std::byte* body_;
  std::size_t size_;
  bool swap_;
  std::size_t off_ = 0;
  std::array<Step, kMaxDepth> path_{};
  std::size_t depth_ = 0;
  std::size_t item_ = 0;  // where the member or element being checked starts
  std::size_t error_offset_ = 0;
  std::string error_;
};

bool Walker::type(const std::uint32_t* ops, std::size_t end) {
  if (depth_ == kMaxDepth) return fail("nested deeper than the checker's path");
  const bool delimited = DDS_OP(ops[0]) == DDS_OP_DLC;
  if (delimited) {
    end = region(end);
    if (end == 0) return false;
    ++ops;
  }
  ++depth_;
  for (std::uint32_t index = 1; *ops != DDS_OP_RTS; ++index) {
    path_[depth_ - 1] = Step{index, -1};
    const std::uint32_t words = adr_words(ops);
    if (words == 0) return fail("op " + hex(ops[0]) + " not supported by the checker");
    // An appendable struct may end before its last members (a writer built from an older
    // IDL): Cyclone then reads them as absent, exactly when they would start at the end.
    // Keys and must-understand members may not be absent.
    item_ = off_;
    if (delimited && off_ >= end) {
      if ((DDS_OP_FLAGS(ops[0]) & (DDS_OP_FLAG_KEY | DDS_OP_FLAG_MU)) != 0) {
        return fail("key member absent");
      }
    } else if (!member(ops, end)) {
      return false;
    }
    ops += words;
  }
  --depth_;
  // Members a newer IDL appended are skipped, as Cyclone skips them.
  if (delimited) off_ = end;
  return true;
}

bool Walker::member(const std::uint32_t* ops, std::size_t end) {
  const std::uint32_t insn = ops[0];
  const std::uint32_t sub = DDS_OP_SUBTYPE(insn);
  switch (DDS_OP_TYPE(insn)) {
    case DDS_OP_VAL_BLN:
      return booleans(1, end);
    case DDS_OP_VAL_ENU:
      return enums(1, ops[2], end);
    case DDS_OP_VAL_STR:
      return string(end);
    case DDS_OP_VAL_ARR:
      if (sub == DDS_OP_VAL_BLN) return booleans(ops[2], end);
      if (sub == DDS_OP_VAL_ENU) return enums(ops[2], ops[3], end);
      return primitives(primitive_size(sub), ops[2], end);
    case DDS_OP_VAL_SEQ:
      return sequence(ops, end);
    default:
      return primitives(primitive_size(DDS_OP_TYPE(insn)), 1, end);
  }
}

bool Walker::sequence(const std::uint32_t* ops, std::size_t end) {
  const std::uint32_t sub = DDS_OP_SUBTYPE(ops[0]);
  std::uint32_t count = 0;
  if (const std::uint32_t size = primitive_size(sub); size != 0) {
    // No DHEADER before a sequence of primitives; Cyclone reads nothing more when it is empty.
    return u32(end, count) && (count == 0 || primitives(size, count, end));
  }
  // Sequences of strings and structs: DHEADER, count, elements filling the region exactly.
  // Cyclone's read ignores the DHEADER, so any slack would shift everything after it.
  end = region(end);
  if (end == 0 || !u32(end, count)) return false;
  const std::uint64_t min_each = sub == DDS_OP_VAL_STR ? kMinString : 1;
  if (count > (end - off_) / min_each) {
    return fail(std::to_string(count) + " elements cannot fit in " + std::to_string(end - off_) +
                " bytes");
  }
  // Struct elements: the op after offset and element size holds the elements' ops offset.
  const std::uint32_t* element = sub == DDS_OP_VAL_STU ? ops + DDS_OP_ADR_JSR(ops[3]) : nullptr;
  for (std::uint32_t i = 0; i < count; ++i) {
    path_[depth_ - 1].element = i;
    const std::size_t before = item_ = off_;
    if (element == nullptr ? !string(end) : !type(element, end)) return false;
    if (off_ == before) return fail("an element takes no bytes");
  }
  path_[depth_ - 1].element = -1;
  if (off_ != end) {
    return fail("the elements end " + std::to_string(end - off_) +
                " bytes before the sequence's DHEADER says");
  }
  return true;
}

std::size_t Walker::region(std::size_t end) {
  std::uint32_t size = 0;
  if (!u32(end, size)) return 0;
  if (size > end - off_) {
    fail("DHEADER of " + std::to_string(size) + " bytes, " + std::to_string(end - off_) + " left");
    return 0;
  }
  return off_ + size;
}

bool Walker::align(std::size_t a, std::size_t end) {
  // XCDR2 aligns to the element size, at most 4 (8-byte values too), from the body's start.
  a = a < 4 ? a : 4;
  const std::size_t aligned = (off_ + a - 1) & ~(a - 1);
  if (aligned > end) return fail("padding runs past the end");
  off_ = aligned;
  return true;
}

bool Walker::u32(std::size_t end, std::uint32_t& value) {
  if (!align(4, end)) return false;
  if (end - off_ < 4) return fail("a 4-byte length or header, " + bytes_left(4, end - off_));
  std::memcpy(&value, body_ + off_, 4);
  if (swap_) value = __builtin_bswap32(value);
  off_ += 4;
  return true;
}

bool Walker::primitives(std::uint32_t size, std::uint64_t count, std::size_t end) {
  if (!align(size, end)) return false;
  const std::uint64_t need = count * size;  // count < 2^32, size <= 8: no overflow
  if (need > end - off_) {
    return fail(std::to_string(count) + " elements of " + std::to_string(size) + " bytes, " +
                bytes_left(need, end - off_));
  }
  off_ += static_cast<std::size_t>(need);
  return true;
}

bool Walker::booleans(std::uint64_t count, std::size_t end) {
  if (!primitives(1, count, end)) return false;
  const std::size_t start = off_ - static_cast<std::size_t>(count);
  for (std::size_t i = start; i < off_; ++i) {
    // Any other byte would be an invalid bool once in the C struct.
    if (std::to_integer<unsigned>(body_[i]) > 1) {
      item_ = i;
      return fail("boolean " + std::to_string(std::to_integer<unsigned>(body_[i])));
    }
  }
  return true;
}

bool Walker::enums(std::uint64_t count, std::uint32_t max, std::size_t end) {
  if (!primitives(4, count, end)) return false;
  const std::size_t start = off_ - static_cast<std::size_t>(4 * count);
  for (std::size_t i = start; i < off_; i += 4) {
    std::uint32_t v = 0;
    std::memcpy(&v, body_ + i, 4);
    if (swap_) v = __builtin_bswap32(v);
    if (v > max) {
      item_ = i;
      return fail("enumerator " + std::to_string(v) + ", at most " + std::to_string(max));
    }
  }
  return true;
}

bool Walker::string(std::size_t end) {
  std::uint32_t length = 0;
  if (!u32(end, length)) return false;
  if (length == 0) return fail("string of length 0 (a CDR string holds at least its NUL)");
  if (length > end - off_) return fail("string " + bytes_left(length, end - off_));
  if (body_[off_ + length - 1] != std::byte{0}) return fail("string not NUL-terminated");
  off_ += length;
  return true;
}

std::string Walker::bytes_left(std::uint64_t need, std::size_t left) {
  return "needs " + std::to_string(need) + " bytes, " + std::to_string(left) + " left";
}

bool Walker::fail(std::string what) {
  error_ = std::move(what);
  error_offset_ = item_;
  return false;
}

std::string Walker::error(const char* type_name) const {
  std::string out = type_name != nullptr ? type_name : "sample";
  for (std::size_t d = 0; d < depth_; ++d) {
    out += (d == 0 ? " #" : ".#") + std::to_string(path_[d].member);
    if (path_[d].element >= 0) out += "[" + std::to_string(path_[d].element) + "]";
  }
  out += " at byte " + std::to_string(error_offset_) + " of " + std::to_string(size_) + ": ";
  return out + error_;
}

}  // namespace

Expected<void> check_serialized(const dds_topic_descriptor_t& type,
                                std::span<const std::byte> sample) {
  const auto byte = [&](std::size_t i) { return std::to_integer<unsigned>(sample[i]); };
  if (sample.size() < 4) {
    return make_error(std::to_string(sample.size()) +
                      " bytes, shorter than the 4-byte encapsulation header");
  }
  const auto id = static_cast<std::uint16_t>(byte(0) << 8 | byte(1));
  if (id != kDelimitedCdr2Be && id != kDelimitedCdr2Le) {
    return make_error("encapsulation " + hex(id) +
                      " is not D_CDR2 (0x8 or 0x9), the only one read for this type");
  }
  // Options are big-endian; their low two bits count the padding after the body.
  const std::size_t padding = byte(3) & 3u;
  if (padding > sample.size() - 4) return make_error("padding longer than the body");
  const bool big_endian = id == kDelimitedCdr2Be;
  Walker walker(sample.data() + 4, sample.size() - 4 - padding,
                big_endian != (std::endian::native == std::endian::big));
  if (!walker.type(type.m_ops, sample.size() - 4 - padding)) {
    return make_error(walker.error(type.m_typename));
  }
  return {};
}

}  // namespace skytrack::dds
