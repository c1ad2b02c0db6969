// Whether a request to the live-view server comes from its own page or a
// tool on this machine, and not from another site's page in the same
// browser: the Host it was sent to must be this server by a name no one
// else controls (a loopback address, "localhost", the address it listens
// on, or, listening on every address, any IP address: never a DNS name,
// which could be rebound to 127.0.0.1), on this server's port; an Origin,
// when the browser sends one, must be the same; Sec-Fetch-Site, when sent,
// must be "same-origin" or "none" (typed in, or a bookmark).
#pragma once

#include <string>
#include <string_view>

namespace rs::teach {

struct ServerAddress {
  std::string host;  ///< as it listens: "127.0.0.1", "::1", "0.0.0.0", "192.168.1.5"
  int port = 0;
};

/// "" when the request may go on, else the sentence to answer 403 with.
/// An empty header is a missing one (a request without Host is refused).
std::string whyNotSameOrigin(std::string_view host, std::string_view origin, std::string_view fetchSite,
                             const ServerAddress& server);

}  // namespace rs::teach
