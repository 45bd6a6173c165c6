#pragma once
// An ASTERIX feed: datagrams (from a capture or a UDP socket) through the decoder into the
// batcher, with plot batches and decoding errors handed to callbacks. What the import tool,
// `skytrack replay --asterix` and the daemon's UDP input share.
#include <functional>
#include <memory>

#include "skytrack/asterix/batcher.hpp"
#include "skytrack/asterix/capture.hpp"
#include "skytrack/asterix/decoder.hpp"

namespace skytrack::asterix {

struct FeedOptions {
  DecoderOptions decoder;
  BatchOptions batch;
};

class Feed {
 public:
  using ErrorSink = std::function<void(const DecodeError& error)>;
  Feed(const FeedOptions& options, Batcher::ScanSink on_scan, ErrorSink on_error = {});
  ~Feed();
  Feed(Feed&&) noexcept;
  Feed& operator=(Feed&&) noexcept;

  void feed(const Datagram& datagram) noexcept;
  /// Closes the open batches (end of input).
  void finish();

  const Decoder& decoder() const;
  const Batcher& batcher() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A whole file through a feed: every datagram the reader gives, then finish(). `progress`
/// (bytes read, file size) is called after each datagram.
void run_capture(CaptureReader& reader, Feed& feed,
                 const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace skytrack::asterix
