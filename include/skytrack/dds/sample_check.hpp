#pragma once
// Checks a serialized DDS sample against its type before Cyclone deserialises it.
//
// Debian 12's Cyclone DDS 0.10.2 validates a received sample (dds_stream_normalize) and then
// reads it (dds_stream_read) without bounds checks. Its validation lets an 8-byte sequence
// claim N elements with only 4N bytes present: the read then copies 8N bytes (a heap
// over-read) and, inside a nested appendable struct, continues 4N bytes further on than the
// validation did, so later counts come from bytes the validation saw as something else (a
// 1.5 kB TrackBatch can ask for gigabytes). docs/dds-trust.md has the details.
//
// check_serialized walks the type's idlc op program (the program Cyclone's read follows) over
// the bytes and requires every member, array, sequence and string to lie inside them, every
// delimited region (DHEADER) to fit its parent, and booleans and enums to hold legal values.
// It reads the bytes only: no allocation unless it fails, no Cyclone call.
#include <cstddef>
#include <span>

#include <dds/dds.h>

#include "skytrack/core/expected.hpp"

namespace skytrack::dds {

/// `sample` is what ddsi_serdata_to_ser gives: the 4-byte encapsulation header and the body.
/// Accepted encapsulation: D_CDR2 (XCDR2 delimited) in either byte order, the only one
/// Cyclone 0.10.2 writes and reads for skytrack's appendable types; the header's options give
/// the padding at the end. Types may use primitives, booleans, enums, strings, arrays of
/// primitives and sequences of primitives, strings and structs (final or appendable); any
/// other construct is refused, so an IDL change cannot slip past unchecked. On failure the
/// error names the member by its 1-based position in the IDL ("#9" is PlotBatch.plot_ids,
/// "#5[3].#14" the mode_probabilities of the fourth of TrackBatch.tracks) and its byte offset
/// in the body (after the 4-byte header).
Expected<void> check_serialized(const dds_topic_descriptor_t& type,
                                std::span<const std::byte> sample);

}  // namespace skytrack::dds
