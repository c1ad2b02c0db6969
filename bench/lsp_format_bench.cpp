// Formatting a large document in the language server (issue 26: 50 MB took
// 10.8 s at a 2.17 GB peak). A `robotsim lsp` process is given a whole
// session on its stdin: initialize, the document opened, a hover (which
// makes its analysis: the compile and the index of names), formatting,
// then shutdown and exit; and the same session without the formatting. Their
// peak RSS (by GNU time) and wall times, against the document's size: what
// formatting adds, and the whole. The document is written to the session
// file as it is generated, so that the driver stays far smaller than the
// server it measures. Every line of it is laid out anew (blanks before
// instructions and comments that are not in the columns), the worst case.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "bench/bench_support.h"
#include "bench/benchmarks.h"
#include "bench/timing.h"
#include "tools/lsp/jsonrpc.h"

namespace rs::bench {

namespace {

const std::string kFormatUri = "file:///bench/format.rsp";

// Line i of the document: blocks of five instructions, each block a label,
// a loop and a comment, laid out unevenly (blanks and tabs).
std::string formatLine(std::size_t i) {
  const std::size_t block = i / 5;
  switch (i % 5) {
    case 0: return fmt::format("b{}: SET N{} 0 ; block {}\n", block, block % 50, block);
    case 1: return "   MOVE 10 -10 5 0 0 ;   a step\n";
    case 2: return fmt::format("\tADD N{}   1\n", block % 50);
    case 3: return fmt::format("  JMPVAR N{} < 3    b{}\n", block % 50, block);
    default: return fmt::format(" GOTO b{}   ; next\n", block + 1);
  }
}

// A line as a piece of a JSON string (the lines hold no quote, backslash
// or control character but tabs and the line break).
std::string escaped(const std::string& line) {
  std::string out;
  for (const char c : line) out += c == '\n' ? std::string("\\n") : c == '\t' ? std::string("\\t") : std::string(1, c);
  return out;
}

std::string frame(const std::string& body) { return lsp::frameMessage(body); }

// The session: the document's didOpen is written in pieces, its length
// worked out first.
std::uintmax_t writeSession(const std::string& path, bool format, std::size_t documentBytes) {
  std::size_t lines = 0, bytes = 0, json = 0;
  for (; bytes < documentBytes; ++lines) {
    const std::string line = formatLine(lines);
    bytes += line.size(), json += escaped(line).size();
  }
  const std::string end = fmt::format("b{}: END\n", lines / 5 + 1);
  bytes += end.size(), json += escaped(end).size();
  const std::string head = fmt::format(
      R"({{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{{"textDocument":{{"uri":"{}","languageId":"robotsim-program","version":1,"text":")",
      kFormatUri);
  const std::string tail = "\"}}}";
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << frame(R"({"jsonrpc":"2.0","id":1,"method":"initialize","params":{"capabilities":{}}})");
  out << frame(R"({"jsonrpc":"2.0","method":"initialized","params":{}})");
  out << fmt::format("Content-Length: {}\r\n\r\n", head.size() + json + tail.size()) << head;
  for (std::size_t i = 0; i < lines; ++i) out << escaped(formatLine(i));
  out << escaped(end) << tail;
  // A hover makes the document's analysis (its compile and index) in both
  // sessions: the difference between them is the formatting's own.
  out << frame(fmt::format(R"({{"jsonrpc":"2.0","id":4,"method":"textDocument/hover","params":{{"textDocument":{{"uri":"{}"}},"position":{{"line":0,"character":0}}}}}})",
                           kFormatUri));
  if (format)
    out << frame(fmt::format(R"({{"jsonrpc":"2.0","id":2,"method":"textDocument/formatting","params":{{"textDocument":{{"uri":"{}"}},"options":{{"tabSize":8,"insertSpaces":true}}}}}})",
                             kFormatUri));
  out << frame(R"({"jsonrpc":"2.0","id":3,"method":"shutdown","params":null})");
  out << frame(R"({"jsonrpc":"2.0","method":"exit"})");
  if (!out) throw std::runtime_error("cannot write " + path);
  return bytes;
}

}  // namespace

nlohmann::json benchLspFormat(const Options& options) {
  const std::size_t documentBytes = sized(options, std::size_t{50'000'000}, std::size_t{200'000});
  fmt::print("\nlanguage server: formatting a {} MB document\n", static_cast<double>(documentBytes) / 1e6);
  std::filesystem::create_directories(options.workDir);
  nlohmann::json out;
  double document = 0;
  for (const bool format : {false, true}) {
    const std::string session = options.workDir + (format ? "/lsp_format.bin" : "/lsp_open.bin");
    document = static_cast<double>(writeSession(session, format, documentBytes));
    progress(format ? "open, format, exit" : "open, exit");
    const std::string reply = options.workDir + "/lsp_format_reply.bin";
    const ProcessRun run = runLspSession(options, session, reply);
    const std::uintmax_t replied = std::filesystem::file_size(reply);
    if (format && replied < documentBytes) throw std::runtime_error("the formatting answer is missing");
    if (!format && replied > 4096) throw std::runtime_error("the document was not opened as it should be");
    const double mib = static_cast<double>(run.maxRssKiB) / 1024;
    out[format ? "open_format" : "open"] = {{"seconds", run.seconds},   {"cpu_seconds", run.cpuSeconds},
                                            {"max_rss_kib", run.maxRssKiB}, {"reply_bytes", replied}};
    fmt::print("  {:<28} {:7.2f} s wall, {:6.2f} s CPU, peak {:7.1f} MiB = {:4.2f}x the document\n",
               format ? "open, format, exit" : "open, exit", run.seconds, run.cpuSeconds, mib,
               mib * 1024 * 1024 / document);
    std::filesystem::remove(session);
    std::filesystem::remove(reply);
  }
  out["document_bytes"] = document;
  const double added = static_cast<double>(out["open_format"]["max_rss_kib"].get<long>() - out["open"]["max_rss_kib"].get<long>()) * 1024;
  out["formatting_adds_per_byte"] = added / document;
  fmt::print("  formatting adds {:.1f} MiB to the peak: {:.2f} bytes a document byte\n", added / 1024 / 1024,
             added / document);
  return out;
}

}  // namespace rs::bench
