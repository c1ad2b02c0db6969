#include "tools/live/http_frame.h"

#include <fmt/format.h>

#include "base/ascii.h"
#include "base/file_io.h"
#include "base/text.h"

namespace rs::live {

namespace {

constexpr std::string_view kHeadEnd = "\r\n\r\n";

// The head's header lines as (name, value), the value without its spaces.
template <typename Visit>
void eachHeader(std::string_view head, Visit&& visit) {
  std::size_t pos = head.find("\r\n");  // past the request line
  while (pos != std::string_view::npos && pos + 2 < head.size()) {
    pos += 2;
    const std::size_t end = head.find("\r\n", pos);
    const std::string_view line = head.substr(pos, end == std::string_view::npos ? head.size() - pos : end - pos);
    if (const std::size_t colon = line.find(':'); colon != std::string_view::npos) {
      std::string_view value = line.substr(colon + 1);
      while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.remove_prefix(1);
      while (!value.empty() && (value.back() == ' ' || value.back() == '\t')) value.remove_suffix(1);
      visit(line.substr(0, colon), value, pos);
    }
    pos = end;
  }
}

// RFC 9110's tchar: what a field name is made of (no space, no controls).
bool isTokenChar(char c) {
  if ((c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')) return true;
  return std::string_view("!#$%&'*+-.^_`|~").find(c) != std::string_view::npos;
}

// What RFC 9112 says a server must refuse with 400, and what would let the
// server and cpp-httplib read different headers: a field line that is no
// `name: value` (a name with a space or a control in it, a space before the
// colon, a folded line, no colon at all: section 5.1), two Host headers
// (section 3.2), two Origin headers or an empty one (RFC 6454, 7.3: one
// origin, never none). "" when the head may be read.
std::string whyHeadersRefused(std::string_view head) {
  int hosts = 0, origins = 0;
  std::size_t pos = head.find("\r\n");  // past the request line
  while (pos != std::string_view::npos && pos + 2 < head.size()) {
    pos += 2;
    const std::size_t end = head.find("\r\n", pos);
    const std::string_view line = head.substr(pos, end == std::string_view::npos ? head.size() - pos : end - pos);
    pos = end;
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos)
      return fmt::format("a header line is no 'Name: value' (it has no colon): '{}'", base::safeText(line.substr(0, 40)));
    const std::string_view name = line.substr(0, colon);
    bool token = !name.empty();
    for (char c : name) token = token && isTokenChar(c);
    if (!token)
      return fmt::format("a header's name may not hold a space or a control character, nor be empty (RFC 9112, "
                         "section 5.1: no space before the colon): '{}'",
                         base::safeText(name.substr(0, 40)));
    std::string_view value = line.substr(colon + 1);
    while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.remove_prefix(1);
    if (base::sameName(name, "Host") && ++hosts > 1) return "a request has one Host header, not two";
    if (base::sameName(name, "Origin")) {
      if (++origins > 1) return "a request has one Origin header, not two";
      if (value.find_first_not_of(" \t") == std::string_view::npos) return "an Origin header may not be empty";
    }
  }
  return {};
}

RequestFrame refused(int status, std::string message) {
  RequestFrame f;
  f.state = RequestFrame::State::kRefused;
  f.status = status;
  f.message = std::move(message);
  return f;
}

}  // namespace

RequestFrame frameRequest(std::string_view bytes, std::size_t maxHead, std::size_t maxBody) {
  const std::size_t end = bytes.substr(0, maxHead + kHeadEnd.size()).find(kHeadEnd);
  // A line of the head that ends in a bare LF: cpp-httplib ends lines there,
  // these frames only at CR LF, so the two would read different headers (a
  // Content-Length or an Expect one of them does not see). Refused as soon
  // as it arrives, whatever follows.
  const std::string_view head =
      bytes.substr(0, end == std::string_view::npos ? maxHead + kHeadEnd.size() : end + kHeadEnd.size());
  for (std::size_t lf = head.find('\n'); lf != std::string_view::npos; lf = head.find('\n', lf + 1))
    if (lf == 0 || head[lf - 1] != '\r') return refused(400, "a line of the request's head ends in a bare LF, not CR LF");
  if (end == std::string_view::npos) {
    if (bytes.size() >= maxHead + kHeadEnd.size())
      return refused(431, fmt::format("the request's head is over {}", base::sizeText(maxHead)));
    return {};
  }
  RequestFrame f;
  f.headLength = end + kHeadEnd.size();
  const std::string_view lines = bytes.substr(0, end + 2);  // the last header line keeps its CR LF
  if (std::string why = whyHeadersRefused(lines); !why.empty()) return refused(400, std::move(why));
  std::size_t lengths = 0;
  std::size_t body = 0;
  bool lengthOk = true, chunked = false;
  eachHeader(lines, [&](std::string_view name, std::string_view value, std::size_t) {
    if (base::sameName(name, "Content-Length")) {
      ++lengths;
      body = 0;
      lengthOk = lengthOk && !value.empty() && value.size() <= 18;
      for (char c : value) {
        if (c < '0' || c > '9')
          lengthOk = false;
        else
          body = body * 10 + static_cast<std::size_t>(c - '0');
      }
    } else if (base::sameName(name, "Transfer-Encoding")) {
      chunked = true;
    } else if (base::sameName(name, "Expect")) {
      f.expectsContinue = base::sameName(value, "100-continue");
    }
  });
  if (chunked) return refused(411, "a request body must come with Content-Length (chunked bodies are not accepted)");
  if (lengths > 1 || !lengthOk) return refused(400, "Content-Length must be one whole number");
  if (body > maxBody)
    return refused(
        413, fmt::format("the body is {} bytes; the limit is {} ({} bytes)", body, base::sizeText(maxBody), maxBody));
  if (bytes.size() - f.headLength < body) return f;  // the body is still coming
  f.state = RequestFrame::State::kComplete;
  f.length = f.headLength + body;
  return f;
}

void disarmExpect(std::string& request, std::size_t headLength) {
  eachHeader(std::string_view(request).substr(0, headLength),
             [&](std::string_view name, std::string_view, std::size_t at) {
               if (base::sameName(name, "Expect")) request[at] = 'X';  // "Xxpect": a header nobody reads
             });
}

}  // namespace rs::live
