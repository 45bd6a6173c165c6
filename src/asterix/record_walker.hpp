#pragma once
// The structure of an ASTERIX record, independent of what the items mean: the FSPEC, then
// each present item in User Application Profile order, sized by its format (fixed, extended
// with FX bits, repetitive, compound, explicit, random field sequencing). The walk records
// where each item lies, so a category decoder reads only the items it interprets and every
// other item is skipped by its length. Formats: EUROCONTROL ASTERIX Part 1, section 4.3.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "skytrack/asterix/records.hpp"

namespace skytrack::asterix::detail {

enum class ItemFormat : std::uint8_t {
  kUndefined,   // spare FRN: its length is unknown, the record cannot be walked past it
  kFixed,       // `size` bytes
  kExtended,    // `size`-byte parts, FX = bit 1 of each part's last byte
  kRepetitive,  // REP byte, then REP * `size` bytes
  kCompound,    // FX-extended primary subfield, then the subfields its bits announce
  kExplicit,    // LEN byte (counting itself), then LEN - 1 bytes (SP and RE fields)
  kRandom,      // RFS: N, then N times (FRN byte, that item)
};

struct ItemSpec {
  ItemFormat format = ItemFormat::kUndefined;
  std::uint8_t size = 0;
  const ItemSpec* subfields = nullptr;  // compound: one spec per primary-subfield bit
  std::uint8_t subfield_count = 0;
};

constexpr ItemSpec fixed(std::uint8_t n) {
  return {ItemFormat::kFixed, n, nullptr, 0};
}
constexpr ItemSpec extended(std::uint8_t n = 1) {
  return {ItemFormat::kExtended, n, nullptr, 0};
}
constexpr ItemSpec repetitive(std::uint8_t n) {
  return {ItemFormat::kRepetitive, n, nullptr, 0};
}
constexpr ItemSpec explicit_length() {
  return {ItemFormat::kExplicit, 0, nullptr, 0};
}
constexpr ItemSpec random_fields() {
  return {ItemFormat::kRandom, 0, nullptr, 0};
}
constexpr ItemSpec undefined() {
  return {};
}
template <std::size_t N>
constexpr ItemSpec compound(const std::array<ItemSpec, N>& subfields) {
  return {ItemFormat::kCompound, 0, subfields.data(), static_cast<std::uint8_t>(N)};
}

/// A category's UAP: items[frn - 1] for FRN 1..count.
struct Uap {
  const ItemSpec* items = nullptr;
  int count = 0;
  const char* const* names = nullptr;  // "I048/010", ... for messages
};

inline constexpr int kMaxFrn = 42;  // six FSPEC octets

/// Where the present items of one record lie within its block.
struct RecordItems {
  std::uint64_t present = 0;  // bit frn
  std::array<std::uint16_t, kMaxFrn + 1> offset{};
  std::array<std::uint16_t, kMaxFrn + 1> length{};
  const std::uint8_t* block = nullptr;

  bool has(int frn) const { return (present >> frn) & 1u; }
  const std::uint8_t* data(int frn) const { return block + offset[static_cast<std::size_t>(frn)]; }
  std::size_t size(int frn) const { return length[static_cast<std::size_t>(frn)]; }
  int count() const { return __builtin_popcountll(present); }
};

/// The result of walking one record: where it ends, or why it could not be walked (then the
/// rest of the block cannot be found either).
struct WalkResult {
  bool ok = true;
  ErrorReason error = ErrorReason::kCount;
  int frn = 0;          // the item at fault, when there is one
  std::size_t end = 0;  // offset after the record (ok) or of the fault
};

/// The FSPEC at `pos`: the present FRNs as bits, and its length. ok false on an FSPEC that runs
/// past `end` or has FX set beyond the UAP's last item.
struct Fspec {
  std::uint64_t bits = 0;
  std::size_t length = 0;
};
WalkResult read_fspec(std::span<const std::uint8_t> block, std::size_t pos, const Uap& uap,
                      Fspec& out) noexcept;

/// Walks the record starting at `pos` (its FSPEC) of `block`.
WalkResult walk_record(std::span<const std::uint8_t> block, std::size_t pos, const Uap& uap,
                       RecordItems& out) noexcept;

// Big-endian readers; callers check lengths through RecordItems.
inline std::uint32_t be16(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) << 8 | p[1];
}
inline std::uint32_t be24(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) << 16 | static_cast<std::uint32_t>(p[1]) << 8 | p[2];
}
/// Two's complement value of the low `bits` bits of `raw`.
inline std::int32_t signed_bits(std::uint32_t raw, int bits) {
  const std::uint32_t sign = 1u << (bits - 1);
  raw &= (sign << 1) - 1u;
  return static_cast<std::int32_t>(raw ^ sign) - static_cast<std::int32_t>(sign);
}

}  // namespace skytrack::asterix::detail
