#include "tools/live/request_origin.h"

#include <arpa/inet.h>
#include <fmt/format.h>

#include <charconv>
#include <optional>

#include "base/ascii.h"
#include "base/text.h"

namespace rs::live {

namespace {

struct HostAndPort {
  std::string name;  // lower case, an IPv6 address without its brackets
  std::optional<int> port;
};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

std::optional<HostAndPort> splitHost(std::string_view text) {
  HostAndPort h;
  std::string_view rest;
  if (text.starts_with('[')) {
    const std::size_t close = text.find(']');
    if (close == std::string_view::npos) return std::nullopt;
    h.name = lower(text.substr(1, close - 1));
    rest = text.substr(close + 1);
  } else {
    const std::size_t colon = text.find(':');
    if (colon != std::string_view::npos && text.find(':', colon + 1) != std::string_view::npos) return std::nullopt;
    h.name = lower(text.substr(0, colon));
    rest = colon == std::string_view::npos ? std::string_view() : text.substr(colon);
  }
  if (h.name.empty()) return std::nullopt;
  if (rest.empty()) return h;
  if (rest[0] != ':' || rest.size() < 2 || rest.size() > 6) return std::nullopt;
  int port = 0;
  const auto [end, ec] = std::from_chars(rest.data() + 1, rest.data() + rest.size(), port);
  if (ec != std::errc() || end != rest.data() + rest.size() || port > 65535) return std::nullopt;
  h.port = port;
  return h;
}

std::optional<in_addr> ipv4(const std::string& name) {
  in_addr a{};
  if (inet_pton(AF_INET, name.c_str(), &a) != 1) return std::nullopt;
  return a;
}

std::optional<in6_addr> ipv6(const std::string& name) {
  in6_addr a{};
  if (inet_pton(AF_INET6, name.c_str(), &a) != 1) return std::nullopt;
  return a;
}

bool isLoopbackName(const std::string& name) {
  if (name == "localhost") return true;
  if (const auto v4 = ipv4(name)) return (ntohl(v4->s_addr) >> 24) == 127;
  if (const auto v6 = ipv6(name)) return IN6_IS_ADDR_LOOPBACK(&*v6);
  return false;
}

// The same address written either way ("::1" and "0:0::1").
bool sameAddress(const std::string& a, const std::string& b) {
  if (a == b) return true;
  if (const auto x = ipv4(a), y = ipv4(b); x && y) return x->s_addr == y->s_addr;
  if (const auto x = ipv6(a), y = ipv6(b); x && y) return IN6_ARE_ADDR_EQUAL(&*x, &*y);
  return false;
}

std::string shown(std::string_view header) { return base::safeText(header.substr(0, 100)); }

}  // namespace

std::string whyNotSameOrigin(const RequestOrigin& request, const ServerAddress& server) {
  const std::string_view host = request.host, origin = request.origin, fetchSite = request.fetchSite;
  if (host.empty()) return "a request needs a Host header (the address it was sent to)";
  const std::string listen = lower(server.host);
  const bool everywhere = listen == "0.0.0.0" || listen == "::";
  const std::optional<HostAndPort> h = splitHost(host);
  const bool nameOk = h && (isLoopbackName(h->name) || sameAddress(h->name, listen) ||
                            (everywhere && (ipv4(h->name) || ipv6(h->name))));
  if (!nameOk || h->port.value_or(80) != server.port)
    return fmt::format(
        "this server answers requests sent to 127.0.0.1:{0} or localhost:{0}{1}, not to '{2}': a page of another "
        "site cannot reach it through a name of its own",
        server.port, everywhere || isLoopbackName(listen) ? "" : fmt::format(" or {}:{}", server.host, server.port),
        shown(host));
  if (!origin.empty() && lower(origin) != "http://" + lower(host))
    return fmt::format(
        "a request from the page of another site ('{}') is refused: only the page this server serves sends it "
        "commands",
        shown(origin));
  if (!fetchSite.empty() && !base::sameName(fetchSite, "same-origin") && !base::sameName(fetchSite, "none") &&
      !request.navigation)
    return fmt::format("a request the browser marks as sent from another site ('{}') is refused", shown(fetchSite));
  return {};
}

}  // namespace rs::live
