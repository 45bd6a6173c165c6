#include "record_walker.hpp"

namespace skytrack::asterix::detail {
namespace {

WalkResult fail(ErrorReason reason, int frn, std::size_t at) {
  return {false, reason, frn, at};
}

/// Length of an FX-extended field of `part`-byte parts starting at `pos`, or 0 when it runs
/// past `end`.
std::size_t extended_length(const std::uint8_t* b, std::size_t pos, std::size_t end,
                            std::size_t part) {
  std::size_t n = 0;
  for (;;) {
    if (pos + n + part > end) return 0;
    n += part;
    if ((b[pos + n - 1] & 1u) == 0) return n;
  }
}

/// Size of one item of format `spec` at `pos`; ok false when it runs past `end`.
WalkResult item_size(const ItemSpec& spec, const std::uint8_t* b, std::size_t pos, std::size_t end,
                     int frn, const Uap& uap, std::size_t& size);

WalkResult compound_size(const ItemSpec& spec, const std::uint8_t* b, std::size_t pos,
                         std::size_t end, int frn, const Uap& uap, std::size_t& size) {
  const std::size_t primary = extended_length(b, pos, end, 1);
  if (primary == 0) return fail(ErrorReason::kItemPastEnd, frn, pos);
  std::size_t n = primary;
  for (std::size_t octet = 0; octet < primary; ++octet) {
    for (int bit = 0; bit < 7; ++bit) {
      if (((b[pos + octet] >> (7 - bit)) & 1u) == 0) continue;
      const std::size_t index = octet * 7 + static_cast<std::size_t>(bit);
      if (index >= spec.subfield_count || spec.subfields[index].format == ItemFormat::kUndefined) {
        return fail(ErrorReason::kUndefinedItem, frn, pos);
      }
      std::size_t sub = 0;
      if (auto r = item_size(spec.subfields[index], b, pos + n, end, frn, uap, sub); !r.ok) {
        return r;
      }
      n += sub;
    }
  }
  size = n;
  return {};
}

WalkResult item_size(const ItemSpec& spec, const std::uint8_t* b, std::size_t pos, std::size_t end,
                     int frn, const Uap& uap, std::size_t& size) {
  switch (spec.format) {
    case ItemFormat::kUndefined:
      return fail(ErrorReason::kUndefinedItem, frn, pos);
    case ItemFormat::kFixed:
      if (pos + spec.size > end) return fail(ErrorReason::kItemPastEnd, frn, pos);
      size = spec.size;
      return {};
    case ItemFormat::kExtended:
      size = extended_length(b, pos, end, spec.size);
      if (size == 0) return fail(ErrorReason::kItemPastEnd, frn, pos);
      return {};
    case ItemFormat::kRepetitive: {
      if (pos + 1 > end) return fail(ErrorReason::kItemPastEnd, frn, pos);
      size = 1 + static_cast<std::size_t>(b[pos]) * spec.size;
      if (pos + size > end) return fail(ErrorReason::kRepetitionPastEnd, frn, pos);
      return {};
    }
    case ItemFormat::kCompound:
      return compound_size(spec, b, pos, end, frn, uap, size);
    case ItemFormat::kExplicit:
      if (pos + 1 > end) return fail(ErrorReason::kItemPastEnd, frn, pos);
      size = b[pos];
      if (size == 0 || pos + size > end) return fail(ErrorReason::kRepetitionPastEnd, frn, pos);
      return {};
    case ItemFormat::kRandom: {
      // N, then N (FRN, item) pairs; a nested RFS is not allowed.
      if (pos + 1 > end) return fail(ErrorReason::kItemPastEnd, frn, pos);
      std::size_t n = 1;
      for (unsigned i = 0; i < b[pos]; ++i) {
        if (pos + n + 1 > end) return fail(ErrorReason::kRepetitionPastEnd, frn, pos);
        const int inner = b[pos + n];
        if (inner < 1 || inner > uap.count || uap.items[inner - 1].format == ItemFormat::kRandom) {
          return fail(ErrorReason::kUndefinedItem, frn, pos + n);
        }
        std::size_t sub = 0;
        if (auto r = item_size(uap.items[inner - 1], b, pos + n + 1, end, inner, uap, sub); !r.ok) {
          return r;
        }
        n += 1 + sub;
      }
      size = n;
      return {};
    }
  }
  return fail(ErrorReason::kUndefinedItem, frn, pos);
}

}  // namespace

WalkResult read_fspec(std::span<const std::uint8_t> block, std::size_t pos, const Uap& uap,
                      Fspec& out) noexcept {
  const std::uint8_t* b = block.data();
  const std::size_t end = block.size();
  const std::size_t max_octets = static_cast<std::size_t>((uap.count + 6) / 7);
  out = {};
  for (std::size_t octet = 0;; ++octet) {
    if (pos + octet >= end) return fail(ErrorReason::kFspecPastEnd, 0, pos);
    if (octet >= max_octets) return fail(ErrorReason::kFspecTooLong, 0, pos);
    const std::uint8_t v = b[pos + octet];
    for (int bit = 0; bit < 7; ++bit) {
      if ((v >> (7 - bit)) & 1u)
        out.bits |= 1ull << (octet * 7 + static_cast<std::size_t>(bit) + 1);
    }
    if ((v & 1u) == 0) {
      out.length = octet + 1;
      return {};
    }
  }
}

WalkResult walk_record(std::span<const std::uint8_t> block, std::size_t pos, const Uap& uap,
                       RecordItems& out) noexcept {
  Fspec fspec;
  if (auto r = read_fspec(block, pos, uap, fspec); !r.ok) return r;
  const std::uint8_t* b = block.data();
  const std::size_t end = block.size();
  out.present = 0;
  out.block = b;
  std::size_t at = pos + fspec.length;
  std::uint64_t bits = fspec.bits;
  while (bits != 0) {
    const int frn = __builtin_ctzll(bits);
    bits &= bits - 1;
    if (frn > uap.count) return fail(ErrorReason::kUndefinedItem, frn, at);
    std::size_t size = 0;
    if (auto r = item_size(uap.items[frn - 1], b, at, end, frn, uap, size); !r.ok) return r;
    out.present |= 1ull << frn;
    out.offset[static_cast<std::size_t>(frn)] = static_cast<std::uint16_t>(at);
    out.length[static_cast<std::size_t>(frn)] = static_cast<std::uint16_t>(size);
    at += size;
  }
  return {true, ErrorReason::kCount, 0, at};
}

}  // namespace skytrack::asterix::detail
