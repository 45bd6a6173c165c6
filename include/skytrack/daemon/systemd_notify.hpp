#pragma once
// systemd readiness notification (Type=notify): sends `state` ("READY=1", "RELOADING=1",
// "STOPPING=1", "STATUS=...") as one datagram to $NOTIFY_SOCKET, the sd_notify(3) protocol,
// without linking libsystemd. Does nothing (returns false) when not run by systemd.
#include <string_view>

namespace skytrack::daemon {

bool notify_systemd(std::string_view state);

}  // namespace skytrack::daemon
