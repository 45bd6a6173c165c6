#pragma once
// The web side of `skytrack display`: serves the page's files, the picture as JSON (one GET or
// a server-sent event stream) and a track's details, and takes the replay controls. Each
// event-stream client gets the newest picture whenever it is ready for one: a slow browser
// skips frames instead of queueing them.
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "skytrack/core/expected.hpp"
#include "skytrack/display/picture.hpp"

namespace httplib {
class Server;
}

namespace skytrack::tool {

/// "host:port" -> host and port; port 0 picks a free one.
struct ListenAddress {
  std::string host = "127.0.0.1";
  int port = 8080;
};
Expected<ListenAddress> parse_listen_address(const std::string& text);
/// True for 127.0.0.0/8, ::1 and "localhost".
bool is_loopback_host(const std::string& host);

/// The page's folder: `explicit_root` when given, else share/skytrack/display under the
/// install prefix next to the executable, else the source tree's tools/skytrack/display.
Expected<std::string> find_web_root(const std::string& explicit_root);

/// Replay controls (POST /api/control?cmd=play|pause|step|restart[&rate=N]); returns the
/// replay's state as JSON or an error for the client. Empty in live mode.
using ControlHandler = std::function<Expected<std::string>(const std::string& cmd, double rate)>;

class DisplayServer {
 public:
  DisplayServer(display::Picture& picture, std::string web_root, ControlHandler control);
  ~DisplayServer();
  DisplayServer(const DisplayServer&) = delete;
  DisplayServer& operator=(const DisplayServer&) = delete;

  /// Binds and starts serving in a thread of its own; returns the bound port.
  Expected<int> start(const ListenAddress& address);
  void stop();

 private:
  void add_routes();

  display::Picture& picture_;
  std::string web_root_;
  ControlHandler control_;
  std::unique_ptr<httplib::Server> server_;
  std::thread thread_;
  std::mutex page_state_mutex_;
  std::string page_state_ = "{}";
};

}  // namespace skytrack::tool
