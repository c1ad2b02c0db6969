// The VS Code extension's TextMate grammar lists the mnemonics by hand
// (editors/vscode/syntaxes/robotsim-program.tmLanguage.json, repository
// "instruction"): this keeps the list true to kOps both ways, naming what
// differs, and its control-flow group true to the flags.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>

#include "vm/opcodes.h"

namespace {

using Words = std::set<std::string>;

// Each pattern's words, by scope name: "\\b(?i:GOTO|JMPIN)\\b" gives GOTO, JMPIN.
std::map<std::string, Words> grammarMnemonics(const nlohmann::json& grammar) {
  std::map<std::string, Words> out;
  static const std::regex alternatives(R"(^\\b\(\?i:([A-Za-z|]+)\)\\b$)");
  for (const nlohmann::json& p : grammar.at("repository").at("instruction").at("patterns")) {
    const std::string match = p.at("match").get<std::string>();
    std::smatch m;
    REQUIRE(std::regex_match(match, m, alternatives));  // a shape this test can read
    Words& words = out[p.at("name").get<std::string>()];
    std::string all = m[1].str();
    for (std::size_t at = 0, bar; at <= all.size(); at = bar + 1) {
      bar = all.find('|', at);
      if (bar == std::string::npos) bar = all.size();
      words.insert(all.substr(at, bar - at));
    }
  }
  return out;
}

// "" if the two agree, else what each has that the other lacks.
std::string keywordDifferences(const Words& grammar, const Words& table) {
  std::string missing, extra;
  for (const std::string& w : table)
    if (!grammar.count(w)) missing += (missing.empty() ? "" : ", ") + w;
  for (const std::string& w : grammar)
    if (!table.count(w)) extra += (extra.empty() ? "" : ", ") + w;
  std::string out;
  if (!missing.empty()) out += "in kOps, not in the grammar: " + missing;
  if (!extra.empty()) out += std::string(out.empty() ? "" : "; ") + "in the grammar, not in kOps: " + extra;
  return out;
}

Words tableMnemonics(bool (*keep)(const rs::vm::OpInfo&)) {
  Words out;
  for (const rs::vm::OpInfo& op : rs::vm::kOps)
    if (keep(op)) out.insert(std::string(op.name));
  return out;
}

nlohmann::json programGrammar() {
  std::ifstream in(std::string(ROBOTSIM_SOURCE_DIR) + "/editors/vscode/syntaxes/robotsim-program.tmLanguage.json");
  REQUIRE(in);
  return nlohmann::json::parse(in);
}

}  // namespace

TEST_CASE("the TextMate grammar's mnemonics are kOps' exactly, each in one group", "[vm][opcodes][editor]") {
  const std::map<std::string, Words> groups = grammarMnemonics(programGrammar());
  Words all;
  std::size_t listed = 0;
  for (const auto& [scope, words] : groups) all.insert(words.begin(), words.end()), listed += words.size();
  CHECK(keywordDifferences(all, tableMnemonics([](const rs::vm::OpInfo&) { return true; })) == "");
  CHECK(listed == all.size());  // no mnemonic in two groups
}

// Control flow is what the flags say changes where the program goes on:
// a jump, a call, a return, an end.
TEST_CASE("the TextMate grammar's control keywords are the opcodes that jump or do not fall through",
          "[vm][opcodes][editor]") {
  const std::map<std::string, Words> groups = grammarMnemonics(programGrammar());
  REQUIRE(groups.count("keyword.control.robotsim"));
  CHECK(keywordDifferences(groups.at("keyword.control.robotsim"), tableMnemonics([](const rs::vm::OpInfo& op) {
                             return (op.flags & rs::vm::kJumps) || !(op.flags & rs::vm::kFallsThrough);
                           })) == "");
  REQUIRE(groups.count("keyword.other.variable.robotsim"));
  CHECK(keywordDifferences(groups.at("keyword.other.variable.robotsim"), tableMnemonics([](const rs::vm::OpInfo& op) {
                             return (op.flags & rs::vm::kWritesVariable) != 0;
                           })) == "");
}

TEST_CASE("the grammar check names what differs, both ways", "[vm][opcodes][editor]") {
  nlohmann::json grammar = programGrammar();
  // A grammar that forgot DELAY and knows a MOVEL kOps has not.
  for (nlohmann::json& p : grammar["repository"]["instruction"]["patterns"]) {
    std::string match = p["match"].get<std::string>();
    if (const auto at = match.find("|DELAY"); at != std::string::npos) match.erase(at, 6);
    if (const auto at = match.find("MOVE|"); at != std::string::npos) match.insert(at, "MOVEL|");
    p["match"] = match;
  }
  Words all;
  for (const auto& [scope, words] : grammarMnemonics(grammar)) all.insert(words.begin(), words.end());
  CHECK(keywordDifferences(all, tableMnemonics([](const rs::vm::OpInfo&) { return true; })) ==
        "in kOps, not in the grammar: DELAY; in the grammar, not in kOps: MOVEL");
}
