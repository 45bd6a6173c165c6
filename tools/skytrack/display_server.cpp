#include "display_server.hpp"

#include <chrono>
#include <filesystem>
#include <string_view>
#include <thread>

#include <httplib.h>

namespace skytrack::tool {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// The page reports its own state (tracks shown, frame rate) for the browser test and the
// frame-rate measurement; anything bigger than this is not a page state.
constexpr std::size_t kMaxPageState = 1 << 20;

}  // namespace

Expected<ListenAddress> parse_listen_address(const std::string& text) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size()) {
    return make_error("--listen '" + text + "': expected HOST:PORT, e.g. 127.0.0.1:8080");
  }
  ListenAddress out;
  out.host = text.substr(0, colon);
  if (out.host.size() > 2 && out.host.front() == '[' && out.host.back() == ']') {
    out.host = out.host.substr(1, out.host.size() - 2);  // [::1]:8080
  }
  try {
    std::size_t used = 0;
    out.port = std::stoi(text.substr(colon + 1), &used);
    if (used != text.size() - colon - 1 || out.port < 0 || out.port > 65535) throw 0;
  } catch (...) {
    return make_error("--listen '" + text + "': the port must be 0 .. 65535");
  }
  return out;
}

bool is_loopback_host(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

Expected<std::string> find_web_root(const std::string& explicit_root) {
  std::vector<fs::path> candidates;
  if (!explicit_root.empty()) {
    candidates.emplace_back(explicit_root);
  } else {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) candidates.push_back(exe.parent_path() / "../share/skytrack/display");
#ifdef SKYTRACK_DISPLAY_SOURCE_DIR
    candidates.emplace_back(SKYTRACK_DISPLAY_SOURCE_DIR);
#endif
  }
  std::string searched;
  for (const fs::path& dir : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(dir / "index.html", ec)) return dir.lexically_normal().string();
    searched += (searched.empty() ? "" : ", ") + dir.lexically_normal().string();
  }
  return make_error("the display's page (index.html) is not in " + searched +
                    " (install it, or pass --web-root)");
}

DisplayServer::DisplayServer(display::Picture& picture, std::string web_root,
                             ControlHandler control)
    : picture_(picture),
      web_root_(std::move(web_root)),
      control_(std::move(control)),
      server_(std::make_unique<httplib::Server>()) {
  // Every event stream holds a worker for its life; leave room for the page's other requests.
  server_->new_task_queue = [] { return new httplib::ThreadPool(16); };
  add_routes();
}

DisplayServer::~DisplayServer() {
  stop();
}

void DisplayServer::add_routes() {
  server_->set_mount_point("/", web_root_);
  server_->Get("/api/frame", [this](const httplib::Request&, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    res.set_content(picture_.frame_json()->json, "application/json");
  });
  server_->Get("/api/events", [this](const httplib::Request&, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    auto seen = std::make_shared<std::uint64_t>(0);
    res.set_chunked_content_provider(
        "text/event-stream", [this, seen](std::size_t, httplib::DataSink& sink) {
          // Waits for a newer picture than the last one sent; sends only the newest, so a
          // browser that cannot keep up skips versions instead of queueing them.
          const std::uint64_t now = picture_.wait_for_change(*seen, 1s);
          if (picture_.stopped()) return false;
          if (now == *seen) {
            static constexpr std::string_view kKeepAlive = ": keep-alive\n\n";
            return sink.write(kKeepAlive.data(), kKeepAlive.size());
          }
          // A scan changes the picture a few times (plots, tracks, status) within
          // microseconds: let them land, then send one frame (at most 50 a second).
          std::this_thread::sleep_for(20ms);
          const auto frame = picture_.frame_json();
          std::string event = "data: ";
          event.reserve(frame->json.size() + 8);
          event += frame->json;
          event += "\n\n";
          *seen = frame->version;
          return sink.write(event.data(), event.size());
        });
  });
  server_->Get("/api/track", [this](const httplib::Request& req, httplib::Response& res) {
    try {
      const auto sensor = static_cast<std::uint32_t>(std::stoul(req.get_param_value("sensor")));
      const std::int64_t id = std::stoll(req.get_param_value("id"));
      if (auto json = picture_.track_json(sensor, id)) {
        return res.set_content(*json, "application/json");
      }
      res.status = 404;
    } catch (...) {
      res.status = 400;
    }
  });
  server_->Post("/api/control", [this](const httplib::Request& req, httplib::Response& res) {
    if (!control_) {
      res.status = 404;
      return res.set_content("live display: no replay to control", "text/plain");
    }
    double rate = 0.0;
    try {
      if (req.has_param("rate")) rate = std::stod(req.get_param_value("rate"));
    } catch (...) {
      res.status = 400;
      return;
    }
    auto state = control_(req.get_param_value("cmd"), rate);
    if (!state) {
      res.status = 400;
      return res.set_content(state.error().message, "text/plain");
    }
    res.set_content(*state, "application/json");
  });
  server_->Post("/api/page-state", [this](const httplib::Request& req, httplib::Response& res) {
    if (req.body.size() > kMaxPageState) {
      res.status = 413;
      return;
    }
    std::lock_guard lock(page_state_mutex_);
    page_state_ = req.body;
    res.status = 204;
  });
  server_->Get("/api/page-state", [this](const httplib::Request&, httplib::Response& res) {
    std::lock_guard lock(page_state_mutex_);
    res.set_content(page_state_, "application/json");
  });
}

Expected<int> DisplayServer::start(const ListenAddress& address) {
  int port = address.port;
  if (port == 0) {
    port = server_->bind_to_any_port(address.host);
    if (port < 0) return make_error("cannot listen on " + address.host);
  } else if (!server_->bind_to_port(address.host, port)) {
    return make_error("cannot listen on " + address.host + ":" + std::to_string(port) +
                      " (in use, or not an address of this machine)");
  }
  thread_ = std::thread([this] { server_->listen_after_bind(); });
  return port;
}

void DisplayServer::stop() {
  picture_.stop();
  if (server_) server_->stop();
  if (thread_.joinable()) thread_.join();
}

}  // namespace skytrack::tool
