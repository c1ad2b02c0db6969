// Whether a request to the live-view server comes from its own page or a
// tool on this machine, and not from another site's page in the same
// browser: the Host it was sent to must be this server by a name no one
// else controls (a loopback address, "localhost", the address it listens
// on, or, listening on every address, any IP address: never a DNS name,
// which could be rebound to 127.0.0.1), on this server's port; an Origin,
// when the browser sends one, must be the same; Sec-Fetch-Site, when sent,
// must be "same-origin" or "none" (typed in, or a bookmark), except for the
// page itself opened from elsewhere (a link in another page, the file
// --open hands the browser: a GET the browser marks as a navigation),
// which changes nothing and whose answer the other page cannot read.
#pragma once

#include <string>
#include <string_view>

namespace rs::live {

struct ServerAddress {
  std::string host;  ///< as it listens: "127.0.0.1", "::1", "0.0.0.0", "192.168.1.5"
  int port = 0;
};

struct RequestOrigin {
  std::string_view host;       ///< the Host header
  std::string_view origin;     ///< the Origin header
  std::string_view fetchSite;  ///< Sec-Fetch-Site
  bool navigation = false;     ///< a GET with Sec-Fetch-Mode: navigate (a page opened)
};

/// "" when the request may go on, else the sentence to answer 403 with.
/// An empty header is a missing one (a request without Host is refused).
std::string whyNotSameOrigin(const RequestOrigin& request, const ServerAddress& server);

}  // namespace rs::live
