#include "skytrack/asterix/feed.hpp"

namespace skytrack::asterix {

struct Feed::Impl final : RecordSink {
  Impl(const FeedOptions& o, Batcher::ScanSink on_scan, ErrorSink e)
      : decoder(o.decoder), batcher(o.batch, std::move(on_scan)), error_sink(std::move(e)) {}
  void on_report(const TargetReport& report) override { batcher.add(report); }
  void on_service(const ServiceMessage& message) override { batcher.add(message); }
  void on_error(const DecodeError& error) override {
    if (error_sink) error_sink(error);
  }
  Decoder decoder;
  Batcher batcher;
  ErrorSink error_sink;
};

Feed::Feed(const FeedOptions& options, Batcher::ScanSink on_scan, ErrorSink on_error)
    : impl_(std::make_unique<Impl>(options, std::move(on_scan), std::move(on_error))) {}
Feed::~Feed() = default;
Feed::Feed(Feed&&) noexcept = default;
Feed& Feed::operator=(Feed&&) noexcept = default;

void Feed::feed(const Datagram& datagram) noexcept {
  impl_->decoder.decode(datagram.payload, datagram.where, datagram.reception_time, *impl_);
}
void Feed::finish() {
  impl_->batcher.finish();
}
const Decoder& Feed::decoder() const {
  return impl_->decoder;
}
const Batcher& Feed::batcher() const {
  return impl_->batcher;
}

void run_capture(CaptureReader& reader, Feed& feed,
                 const std::function<void(std::size_t, std::size_t)>& progress) {
  while (auto datagram = reader.next()) {
    feed.feed(*datagram);
    if (progress) progress(reader.bytes_read(), reader.file_size());
  }
  feed.finish();
}

}  // namespace skytrack::asterix
