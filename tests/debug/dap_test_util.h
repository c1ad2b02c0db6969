// Shared by the adapter's tests that script a whole session: the requests
// framed, served by `robotsim dap`'s loop, and the messages it answered.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "tools/dap/serve.h"
#include "tools/wire/framing.h"
#include "tools/wire/json.h"

namespace debugtest {

/// `requests` (seq and type added, in order) served to the end; every message the adapter wrote.
inline std::vector<rs::wire::Json> dapSession(const std::vector<rs::wire::Json>& requests) {
  std::string bytes;
  int seq = 1;
  for (rs::wire::Json r : requests) {
    r["seq"] = seq++;
    r["type"] = "request";
    bytes += rs::wire::frameMessage(r.dump());
  }
  std::istringstream in(bytes);
  std::ostringstream out, log;
  rs::wire::StreamInput input(in);
  rs::wire::StreamOutput output(out);
  rs::dap::serve(input, output, log);
  std::vector<rs::wire::Json> messages;
  for (const rs::wire::Frame& f : rs::wire::parseFrames(out.str())) messages.push_back(rs::wire::Json::parse(f.body));
  return messages;
}

/// The response to request `seq`, or null.
inline const rs::wire::Json* dapResponse(const std::vector<rs::wire::Json>& messages, int seq) {
  for (const rs::wire::Json& m : messages)
    if (m.value("type", "") == "response" && m.value("request_seq", 0) == seq) return &m;
  return nullptr;
}

}  // namespace debugtest
