// textDocument/completion: instructions (with operand snippets) where an
// instruction goes; after one, what its operand takes by the opcode
// table's format: labels, points, variables, input and output numbers,
// ON/OFF, comparisons.
#include <fmt/format.h>

#include <set>

#include "base/ascii.h"
#include "tools/lsp/features/features.h"
#include "vm/io_lines.h"

namespace rs::lsp {

namespace {

// LSP CompletionItemKind values.
constexpr int kFunctionItem = 3, kVariableItem = 6, kValueItem = 12, kKeywordItem = 14, kReferenceItem = 18,
              kEnumMemberItem = 20, kConstantItem = 21, kOperatorItem = 24;

Json item(std::string label, int kind, std::string detail) {
  return {{"label", std::move(label)}, {"kind", kind}, {"detail", std::move(detail)}};
}

std::string choices(const std::vector<std::string>& options, std::string_view fallback) {
  if (options.empty()) return fmt::format("{}", fallback);
  std::string out = "|";
  for (std::size_t i = 0; i < options.size(); ++i) out += (i ? "," : "") + options[i];
  return out + "|";
}

std::vector<std::string> labelNames(const ProgramIndex& index) {
  std::vector<std::string> out;
  for (const IndexedInstruction& in : index.instructions())
    if (!in.label.empty()) out.emplace_back(in.label);
  return out;
}

std::vector<std::string> pointNames(const ProgramIndex& index) {
  std::vector<std::string> out;
  for (const IndexedPoint& p : index.points()) out.emplace_back(p.name);
  return out;
}

std::vector<std::string> variableNames(const ProgramIndex& index) {
  std::set<std::string> seen;
  std::vector<std::string> out;
  for (const Occurrence& o : index.occurrences()) {
    if (o.kind != NameKind::Variable) continue;
    std::string upper(o.name);
    for (char& c : upper) c = base::asciiUpper(c);
    if (seen.insert(upper).second) out.emplace_back(o.name);
  }
  return out;
}

// "MOVE ${1:0} ${2:0} ...": the instruction with a placeholder per operand.
std::string snippet(const ProgramContext& p, const vm::OpInfo& op) {
  const ProgramIndex& index = p.analysis.index();
  std::string io = "|1";  // a snippet's choice of every line number
  for (int line = 2; line <= vm::kIoCount; ++line) io += fmt::format(",{}", line);
  io += "|";
  const std::string labels = choices(labelNames(index), ":label");
  std::string s(op.name);
  switch (op.format) {
    case vm::Format::None: break;
    case vm::Format::MotorVector:
      for (std::size_t i = 0; i < p.analysis.cell().target.motors.size(); ++i) s += fmt::format(" ${{{}:0}}", i + 1);
      break;
    case vm::Format::Point: s += fmt::format(" ${{1{}}}", choices(pointNames(index), ":point")); break;
    case vm::Format::Target: s += fmt::format(" ${{1{}}}", labels); break;
    case vm::Format::InputJump: s += fmt::format(" ${{1{}}} ${{2|ON,OFF|}} ${{3{}}}", io, labels); break;
    case vm::Format::Output:
    case vm::Format::Input: s += fmt::format(" ${{1{}}} ${{2|ON,OFF|}}", io); break;
    case vm::Format::VarCompare: s += fmt::format(" ${{1:N}} ${{2|<,>,=|}} ${{3:0}} ${{4{}}}", labels); break;
    case vm::Format::VarValue: s += " ${1:N} ${2:0}"; break;
    case vm::Format::Triple: s += " ${1:0} ${2:0} ${3:0}"; break;
    case vm::Format::Millis: s += " ${1:1}"; break;
    case vm::Format::Distance: s += " ${1:50}"; break;
  }
  return s;
}

std::vector<std::string_view> words(std::string_view s) {
  std::vector<std::string_view> out;
  for (std::size_t i = 0; i < s.size();) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    std::size_t end = i;
    while (end < s.size() && s[end] != ' ' && s[end] != '\t') ++end;
    if (end > i) out.push_back(s.substr(i, end - i));
    i = end;
  }
  return out;
}

}  // namespace

LineContext lineContext(const ProgramContext& p, Position at) {
  LineContext c;
  const std::string_view line = p.doc.line(at.line);
  const std::string_view before = line.substr(0, bytesFor(line, at.character, p.enc));
  const diag::Pos header = p.analysis.index().pointsHeader();
  if (before.find(';') != std::string_view::npos || (header.line != 0 && at.line + 1 >= header.line)) return c;
  c.usable = true;
  std::vector<std::string_view> w = words(before);
  const bool typing = !before.empty() && before.back() != ' ' && before.back() != '\t';
  if (typing) c.partial = w.back(), w.pop_back();
  if (!w.empty() && w.front().size() > 1 && w.front().back() == ':') w.erase(w.begin());
  if (w.empty()) {
    c.atHead = !(typing && c.partial.back() == ':');
    return c;
  }
  c.op = vm::opByName(w.front());
  c.operand = w.size() - 1;
  return c;
}

Json completion(const ProgramContext& p, Position at, bool snippets) {
  const LineContext c = lineContext(p, at);
  Json items = Json::array();
  if (!c.usable) return items;
  const ProgramIndex& index = p.analysis.index();
  if (c.atHead) {
    for (const vm::OpInfo& op : vm::kOps) {
      Json i = item(std::string(op.name), kKeywordItem, fmt::format("{}{}", op.name, vm::info(op.format).usage));
      i["documentation"] = {{"kind", "markdown"}, {"value", fmt::format("{}\n\n{}", op.meaning, op.detail)}};
      if (snippets && op.format != vm::Format::None) {
        i["insertText"] = snippet(p, op);
        i["insertTextFormat"] = 2;
      }
      items.push_back(std::move(i));
    }
    return items;
  }
  if (!c.op) return items;
  const vm::Format f = vm::info(*c.op).format;
  const auto labels = [&] {
    for (const IndexedInstruction& in : index.instructions())
      if (!in.label.empty())
        items.push_back(item(std::string(in.label), index.isSubroutine(in.label) ? kFunctionItem : kReferenceItem,
                             fmt::format("instruction {} (line {})", in.number, in.pos.line)));
  };
  const auto io = [&](const char* what) {
    for (int n = 1; n <= vm::kIoCount; ++n) items.push_back(item(std::to_string(n), kValueItem, fmt::format("{} {}", what, n)));
  };
  const auto onOff = [&] {
    items.push_back(item("ON", kEnumMemberItem, "switched on"));
    items.push_back(item("OFF", kEnumMemberItem, "switched off"));
  };
  const auto variables = [&] {
    for (const std::string& v : variableNames(index)) items.push_back(item(v, kVariableItem, "variable"));
  };
  switch (f) {
    case vm::Format::Point:
      if (c.operand == 0)
        for (const IndexedPoint& point : index.points()) {
          std::string values;
          for (const std::int32_t v : point.values) values += fmt::format("{}{}", values.empty() ? "" : " ", v);
          if (!point.pose.empty()) values += fmt::format("{}(from {})", values.empty() ? "" : " ", point.pose);
          items.push_back(item(std::string(point.name), kConstantItem, values));
        }
      break;
    case vm::Format::Target:
      if (c.operand == 0) labels();
      break;
    case vm::Format::InputJump:
      if (c.operand == 0) io("input");
      if (c.operand == 1) onOff();
      if (c.operand == 2) labels();
      break;
    case vm::Format::Input:
    case vm::Format::Output:
      if (c.operand == 0) io(f == vm::Format::Output ? "output" : "input");
      if (c.operand == 1) onOff();
      break;
    case vm::Format::VarCompare:
      if (c.operand == 0) variables();
      if (c.operand == 1)
        for (const char* cmp : {"<", ">", "="}) items.push_back(item(cmp, kOperatorItem, "comparison"));
      if (c.operand == 3) labels();
      break;
    case vm::Format::VarValue:
      if (c.operand == 0) variables();
      break;
    default: break;
  }
  return items;
}

}  // namespace rs::lsp
