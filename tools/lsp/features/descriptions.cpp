// Robot and workcell descriptions (.rsd) and stimuli files (.stim):
// diagnostics from their readers, symbols, hover (a robot link's D-H row,
// a colour's name and number, a device, a stimulus line in words), and go
// to definition (a sensor a wire names, the object a conveyor runs) and across files (a name another file defines: its file on the
// library path).
#include <fmt/format.h>

#include <filesystem>

#include "base/ascii.h"
#include "base/file_io.h"
#include "base/number_text.h"
#include "compiler/description/description.h"
#include "compiler/description/library.h"
#include "tools/lsp/device_text.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"
#include "tools/lsp/uri.h"
#include "model/kinematics/dh.h"
#include "compiler/stimuli/stimuli.h"

namespace rs::lsp {

using base::formatNumber;

Json fileDiagnosticsJson(const Document& doc, Encoding enc, const std::vector<diag::Diagnostic>& list,
                         const std::string& file) {
  Json out = Json::array();
  for (const diag::Diagnostic& d : list) {
    if (d.file != file) continue;
    Json j = {{"range", toJson(doc.wordAt(d.pos, enc))},
              {"severity", d.severity == diag::Severity::Error ? 1 : d.severity == diag::Severity::Warning ? 2 : 3},
              {"source", "robotsim"},
              {"message", d.hint.empty() ? d.message : d.message + "\nhint: " + d.hint}};
    if (!d.code.empty()) j["code"] = d.code;
    out.push_back(std::move(j));
  }
  return out;
}

namespace {

namespace fs = std::filesystem;

std::string nameOf(const Document& doc) {
  const std::string path = pathOfUri(doc.uri());
  return path.empty() ? doc.uri() : path;
}


struct Parsed {
  compiler::DescriptionFile file;
  std::vector<diag::Diagnostic> diagnostics;
};

Parsed parse(const Document& doc) {
  diag::Diagnostics d(nameOf(doc));
  Parsed p{compiler::parseDescription(std::make_unique<diag::SourceFile>(nameOf(doc), doc.text()), d), {}};
  p.diagnostics = d.sorted();
  return p;
}

// A library that reads the document as the editor holds it, saved or not.
// False when the document has no file path (an untitled buffer).
bool libraryOf(const Document& doc, compiler::Library& library) {
  const std::string path = pathOfUri(doc.uri());
  if (path.empty()) return false;
  library.overlay(path, doc.text());
  return true;
}

// The word (name characters) under a position, and its range.
std::string wordUnder(const Document& doc, Encoding enc, Position at, Range& range) {
  const std::string_view line = doc.line(at.line);
  std::size_t i = bytesFor(line, at.character, enc), b = i, e = i;
  const auto part = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'; };
  while (b > 0 && part(line[b - 1])) --b;
  while (e < line.size() && part(line[e])) ++e;
  range = {{at.line, unitsOf(line.substr(0, b), enc)}, {at.line, unitsOf(line.substr(0, e), enc)}};
  return std::string(line.substr(b, e - b));
}

// The word before position `at`'s word on its line (the keyword in "COLOR RED").
std::string wordBefore(const Document& doc, Encoding enc, const Range& word) {
  const std::string_view line = doc.line(word.start.line);
  std::size_t e = bytesFor(line, word.start.character, enc);
  while (e > 0 && (line[e - 1] == ' ' || line[e - 1] == '\t')) --e;
  std::size_t b = e;
  while (b > 0 && line[b - 1] != ' ' && line[b - 1] != '\t') --b;
  return std::string(line.substr(b, e - b));
}

// Every name one definition refers to, with where.
std::vector<const compiler::NameRef*> referencesIn(const compiler::DescriptionFile& f) {
  std::vector<const compiler::NameRef*> out;
  for (const compiler::GripperDef& g : f.grippers) out.insert(out.end(), {&g.base, &g.finger2, &g.finger3});
  for (const compiler::RobotDef& r : f.robots) {
    for (const compiler::RobotLinkDef& l : r.links) out.push_back(&l.link);
    out.push_back(&r.gripper);
  }
  for (const compiler::WorkcellDef& w : f.workcells)
    for (const compiler::PlacementDef& p : w.placements) out.push_back(&p.what);
  return out;
}

const compiler::NameRef* referenceAt(const compiler::DescriptionFile& f, diag::Pos pos) {
  for (const compiler::NameRef* r : referencesIn(f))
    if (!r->name.empty() && r->pos.line == pos.line && pos.col >= r->pos.col && pos.col <= r->pos.col + r->name.size())
      return r;
  return nullptr;
}

// A definition's name range: the word after its keyword.
Range definitionName(const Document& doc, Encoding enc, diag::Pos keyword, const std::string& name) {
  const Position at = doc.fromPos(keyword, Encoding::Utf8);
  const std::string_view line = doc.line(at.line);
  const std::size_t i = line.find(name, at.character);
  if (i == std::string_view::npos) return doc.wordAt(keyword, enc);
  return {{at.line, unitsOf(line.substr(0, i), enc)}, {at.line, unitsOf(line.substr(0, i + name.size()), enc)}};
}

template <class Def>
void symbolsOf(const Document& doc, Encoding enc, const std::vector<Def>& defs, int kind, const char* what, Json& out) {
  for (const Def& d : defs) {
    const Range name = definitionName(doc, enc, d.pos, d.name);
    const Range line{{name.start.line, 0}, {name.start.line, unitsOf(doc.line(name.start.line), enc)}};
    out.push_back({{"name", d.name}, {"detail", what}, {"kind", kind}, {"range", toJson(line)},
                   {"selectionRange", toJson(name)}});
  }
}

bool covers(diag::Pos name, std::size_t length, diag::Pos pos) {
  return name.line == pos.line && pos.col >= name.col && pos.col <= name.col + length;
}

// Every signal a workcell's devices read, for go to definition.
std::vector<const workcell::Signal*> signalsIn(const workcell::Devices& d) {
  std::vector<const workcell::Signal*> out;
  for (const workcell::Conveyor& v : d.conveyors) out.push_back(&v.run);
  for (const workcell::Feeder& f : d.feeders)
    if (f.when) out.push_back(&*f.when);
  for (const workcell::Wire& w : d.wires) out.push_back(&w.source);
  return out;
}

const workcell::Sensor* sensorNamed(const workcell::Devices& d, const std::string& name) {
  for (const workcell::Sensor& s : d.sensors)
    if (base::sameName(s.name, name)) return &s;
  return nullptr;
}

// Hover on a device's name, where it is declared or where a signal names it.
std::string deviceHover(const workcell::Devices& d, diag::Pos pos) {
  for (const workcell::Sensor& s : d.sensors)
    if (covers(s.pos, s.name.size(), pos)) return sensorSentence(s);
  for (const workcell::Signal* s : signalsIn(d))
    if (s->kind == workcell::Signal::Kind::Sensor && covers(s->pos, s->name.size(), pos))
      if (const workcell::Sensor* sensor = sensorNamed(d, s->name)) return sensorSentence(*sensor);
  for (const workcell::Conveyor& v : d.conveyors)
    if (covers(v.pos, v.name.size(), pos)) return conveyorSentence(v);
  for (const workcell::Feeder& f : d.feeders)
    if (covers(f.pos, f.name.size(), pos)) return feederSentence(f);
  for (const workcell::Sink& k : d.sinks)
    if (covers(k.pos, k.name.size(), pos)) return sinkSentence(k);
  for (const workcell::Wire& w : d.wires)
    if (w.pos.line == pos.line) return wireSentence(w);
  return {};
}

}  // namespace

Json descriptionDiagnostics(const Document& doc, Encoding enc) {
  Parsed p = parse(doc);
  std::vector<diag::Diagnostic> all = p.diagnostics;
  // Names resolved and robots built by the library, from the editor's text.
  compiler::Library library(compiler::librarySearchPath({}));
  if (all.empty() && (!p.file.robots.empty() || !p.file.workcells.empty()) && libraryOf(doc, library)) {
    library.workcell(nameOf(doc));
    all.insert(all.end(), library.diagnostics().begin(), library.diagnostics().end());
  }
  return fileDiagnosticsJson(doc, enc, all, nameOf(doc));
}

Json descriptionSymbols(const Document& doc, Encoding enc) {
  const Parsed p = parse(doc);
  Json out = Json::array();
  symbolsOf(doc, enc, p.file.links, symbol_kind::kStruct, "link", out);
  symbolsOf(doc, enc, p.file.objects, symbol_kind::kObject, "object", out);
  symbolsOf(doc, enc, p.file.grippers, symbol_kind::kClass, "gripper", out);
  symbolsOf(doc, enc, p.file.robots, symbol_kind::kClass, "robot", out);
  symbolsOf(doc, enc, p.file.workcells, symbol_kind::kNamespace, "workcell", out);
  std::sort(out.begin(), out.end(), [](const Json& a, const Json& b) {
    return a["range"]["start"]["line"].get<int>() < b["range"]["start"]["line"].get<int>();
  });
  return out;
}

Json descriptionHover(const Document& doc, Encoding enc, Position at, const std::vector<fs::path>& searchPath) {
  Range range;
  const std::string word = wordUnder(doc, enc, at, range);
  if (word.empty()) return nullptr;
  const auto reply = [&](std::string text) {
    return Json{{"contents", {{"kind", "markdown"}, {"value", std::move(text)}}}, {"range", toJson(range)}};
  };
  if (base::sameName(wordBefore(doc, enc, range), "COLOR"))
    if (const auto c = compiler::colorByName(word))
      return reply(fmt::format("colour **{}** (EGA colour {})", compiler::colorName(*c), static_cast<int>(*c)));
  const Parsed p = parse(doc);
  const diag::Pos pos = doc.toPos(at, enc);
  for (const compiler::WorkcellDef& w : p.file.workcells)
    if (std::string text = deviceHover(w.devices, pos); !text.empty()) return reply(std::move(text));
  for (const compiler::RobotDef& r : p.file.robots)
    for (std::size_t i = 0; i < r.links.size(); ++i) {
      const compiler::NameRef& l = r.links[i].link;
      if (l.pos.line != pos.line || pos.col < l.pos.col || pos.col > l.pos.col + l.name.size()) continue;
      if (i == 0) return reply(fmt::format("link `{}`: the base of {} (frame 0)", l.name, r.name));
      compiler::Library library(searchPath);
      const std::optional<workcell::Robot> robot =
          libraryOf(doc, library) ? library.robot(nameOf(doc)) : std::nullopt;
      if (!robot || !robot->chain || static_cast<int>(i) > robot->chain->size())
        return reply(fmt::format("link `{}`: link {} of {}", l.name, i, r.name));
      const kinematics::DhRow row = robot->chain->table()[i - 1];
      const bool revolute = row.type == kinematics::JointType::Revolute;
      return reply(fmt::format(
          "link `{}`: link {} of {}\n\nD-H row {} ({}): theta = {}, alpha = {}, a = {}, d = {} (home {})", l.name, i, r.name, i,
          kinematics::jointTypeName(row.type), revolute ? fmt::format("theta{}", i) : formatNumber(row.theta),
          formatNumber(row.alpha), formatNumber(row.a), revolute ? formatNumber(row.d) : fmt::format("d{}", i),
          formatNumber(row.home())));
    }
  return nullptr;
}

Json definitionInFile(const std::string& file, const std::string& name, Encoding enc) {
  // A description file is small; one over the bound is still the place, at its top.
  constexpr std::size_t kMaxDescriptionBytes = std::size_t{4} << 20;
  base::FileRead read = base::readFile(file, kMaxDescriptionBytes);
  if (!read.bytes) return location(uriOfPath(file), Range{});
  const Document doc(uriOfPath(file), Language::Description, 0, std::move(*read.bytes));
  const Parsed p = parse(doc);
  const auto in = [&](const auto& defs) -> std::optional<Range> {
    for (const auto& d : defs)
      if (base::sameName(d.name, name)) return definitionName(doc, enc, d.pos, d.name);
    return std::nullopt;
  };
  // What a name stands for first: a workcell or a robot (what --cell takes), then the parts.
  for (const std::optional<Range>& r :
       {in(p.file.workcells), in(p.file.robots), in(p.file.grippers), in(p.file.objects), in(p.file.links)})
    if (r) return location(doc.uri(), *r);
  // A file named by its path (`; cell: ../cell.rsd`): what --cell loads from it, its first workcell, else robot.
  if (!p.file.workcells.empty())
    return location(doc.uri(), definitionName(doc, enc, p.file.workcells[0].pos, p.file.workcells[0].name));
  if (!p.file.robots.empty())
    return location(doc.uri(), definitionName(doc, enc, p.file.robots[0].pos, p.file.robots[0].name));
  return location(doc.uri(), Range{});
}

namespace {

// A ROBOT placement's label (AS, else the description's name) and where it stands.
const compiler::NameRef& labelRef(const compiler::PlacementDef& pl) { return pl.as.name.empty() ? pl.what : pl.as; }

// The ROBOT line of one of `f`'s workcells labelled `label`, as a location in `doc`.
Json robotLabelled(const Document& doc, Encoding enc, const compiler::DescriptionFile& f, const std::string& label) {
  for (const compiler::WorkcellDef& w : f.workcells)
    for (const compiler::PlacementDef& pl : w.placements)
      if (pl.isRobot && base::sameName(labelRef(pl).name, label))
        return location(doc.uri(), definitionName(doc, enc, labelRef(pl).pos, labelRef(pl).name));
  return nullptr;
}

// Issue 36: a robot's label in a signal or a wire (`left.OUT 1`, `TO
// right.IN 2`) goes to its ROBOT line; a ROBOT's PROGRAM to that file.
Json robotDefinition(const Document& doc, Encoding enc, const compiler::DescriptionFile& f, diag::Pos pos) {
  for (const compiler::WorkcellDef& w : f.workcells) {
    for (const workcell::Signal* s : signalsIn(w.devices))
      if (!s->robot.empty() && covers(s->pos, s->robot.size(), pos)) return robotLabelled(doc, enc, f, s->robot);
    for (const workcell::Wire& wire : w.devices.wires)
      if (!wire.robot.empty() && covers(wire.inputPos, wire.robot.size(), pos))
        return robotLabelled(doc, enc, f, wire.robot);
    for (const compiler::PlacementDef& pl : w.placements) {
      if (!pl.isRobot || pl.program.name.empty() || !covers(pl.program.pos, pl.program.name.size(), pos)) continue;
      const std::string path = pathOfUri(doc.uri());
      std::error_code ec;
      const fs::path file = (fs::path(path).parent_path() / pl.program.name).lexically_normal();
      if (path.empty() || !fs::is_regular_file(file, ec)) return nullptr;
      return location(uriOfPath(file.string()), Range{});
    }
  }
  return nullptr;
}

}  // namespace

Json robotDefinitionInFile(const std::string& file, const std::string& label, Encoding enc) {
  constexpr std::size_t kMaxDescriptionBytes = std::size_t{4} << 20;  // as definitionInFile
  base::FileRead read = base::readFile(file, kMaxDescriptionBytes);
  if (!read.bytes) return nullptr;
  const Document doc(uriOfPath(file), Language::Description, 0, std::move(*read.bytes));
  return robotLabelled(doc, enc, parse(doc).file, label);
}

Json descriptionDefinition(const Document& doc, Encoding enc, Position at, const std::vector<fs::path>& searchPath) {
  const Parsed p = parse(doc);
  const diag::Pos pos = doc.toPos(at, enc);
  // A sensor a signal names (`WIRE eye TO IN 1`): its SENSOR line; an
  // object a CONVEYOR names: its OBJECT line.
  for (const compiler::WorkcellDef& w : p.file.workcells) {
    for (const workcell::Signal* s : signalsIn(w.devices))
      if (s->kind == workcell::Signal::Kind::Sensor && covers(s->pos, s->name.size(), pos))
        if (const workcell::Sensor* sensor = sensorNamed(w.devices, s->name))
          return location(doc.uri(), definitionName(doc, enc, sensor->pos, sensor->name));
    for (const workcell::Conveyor& v : w.devices.conveyors)
      if (covers(v.pos, v.name.size(), pos))
        for (const compiler::PlacementDef& pl : w.placements)
          if (!pl.isRobot && base::sameName(pl.as.name.empty() ? pl.what.name : pl.as.name, v.name))
            return location(doc.uri(), definitionName(doc, enc, pl.as.name.empty() ? pl.what.pos : pl.as.pos,
                                                      pl.as.name.empty() ? pl.what.name : pl.as.name));
  }
  if (Json robot = robotDefinition(doc, enc, p.file, pos); !robot.is_null()) return robot;
  const compiler::NameRef* ref = referenceAt(p.file, pos);
  if (!ref) return nullptr;
  // Defined in this file?
  const auto here = [&](const auto& defs) -> std::optional<Range> {
    for (const auto& d : defs)
      if (d.name == ref->name) return definitionName(doc, enc, d.pos, d.name);
    return std::nullopt;
  };
  for (const std::optional<Range>& r :
       {here(p.file.links), here(p.file.objects), here(p.file.grippers), here(p.file.robots), here(p.file.workcells)})
    if (r) return location(doc.uri(), *r);
  const std::string file = findDescriptionFile(ref->name, searchPath);
  if (file.empty()) return nullptr;
  return definitionInFile(file, ref->name, enc);
}

Json stimuliDiagnostics(const Document& doc, Encoding enc) {
  const diag::Result<stimuli::Stimuli> parsed = stimuli::parseStimuli(doc.text(), nameOf(doc));
  Json out = Json::array();
  for (const diag::Diagnostic& d : parsed.failures()) {
    // Stimuli columns count bytes: convert through UTF-8.
    const Position start = d.pos.line == 0 ? Position{} : Position{d.pos.line - 1, d.pos.col - 1};
    const std::uint32_t line = start.line;
    const Position s{line, unitsOf(doc.line(line).substr(0, std::min<std::size_t>(start.character, doc.line(line).size())), enc)};
    const Position e{line, unitsOf(doc.line(line), enc)};
    Json j = {{"range", toJson(Range{s, e})}, {"severity", 1}, {"source", "robotsim"}, {"message", d.message}};
    if (!d.code.empty()) j["code"] = d.code;
    out.push_back(std::move(j));
  }
  return out;
}

Json stimuliSymbols(const Document& doc, Encoding enc) {
  Json out = Json::array();
  for (std::uint32_t l = 0; l < doc.lineCount(); ++l) {
    const std::string_view code = codeOf(doc.line(l));
    const std::size_t first = code.find_first_not_of(" \t");
    if (first == std::string_view::npos) continue;
    const Range r{{l, unitsOf(code.substr(0, first), enc)}, {l, unitsOf(code, enc)}};
    out.push_back({{"name", std::string(code.substr(first))}, {"kind", symbol_kind::kEvent}, {"range", toJson(r)},
                   {"selectionRange", toJson(r)}});
  }
  return out;
}

Json stimuliHover(const Document& doc, Encoding enc, Position at) {
  const std::string_view code = codeOf(doc.line(at.line));
  if (code.find_first_not_of(" \t") == std::string_view::npos) return nullptr;
  const diag::Result<stimuli::Stimuli> one = stimuli::parseStimuli(code, "line");
  if (!one) return nullptr;
  const auto state = [](bool on) { return on ? "ON" : "OFF"; };
  std::string text;
  for (const stimuli::InputChange& c : one->changes)
    text = fmt::format("at {} input {} turns {}", formatSeconds(c.at), c.input, state(c.on));
  for (const stimuli::ReactiveRule& r : one->rules)
    text = fmt::format("whenever output {} turns {}, input {} turns {} {} later", r.output, state(r.outputOn), r.input,
                       state(r.inputOn), formatSeconds(r.delay));
  if (text.empty()) return nullptr;
  const Range r{{at.line, 0}, {at.line, unitsOf(code, enc)}};
  return {{"contents", {{"kind", "markdown"}, {"value", text}}}, {"range", toJson(r)}};
}

}  // namespace rs::lsp
