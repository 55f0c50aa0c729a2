// The language server tested as an editor uses it: `sled lsp` in its own process, spoken to
// over a pipe by the client in lsp_client.h. Open, change, diagnostics, hover, definition,
// references, completion, formatting, symbols, code actions, shutdown; and malformed messages,
// which must never end the server.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/lsp/lsp_client.h"

namespace sled::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A scene with one misspelled segment name (`pelvs`) on line 8 (0-based 7).
constexpr std::string_view kScene = R"(scenario "lsp test" {
  import std.humans.male50 as occupant
  param gap = 5 mm
  let double_gap = gap * 2
  time { end = 10 ms  output_every = 1 ms }
  vehicle sled { motion = half_sine(delta_v = 56 km/h, duration = 100 ms, axis = -x) }
  plane seat_pan on sled { corners = (0 mm, -250 mm, double_gap), (500, -250, 0) mm, (0, 250, 0) mm }
  contact occupant.pelvs with seat_pan { force = 20 kN/m  friction = 0.4 }
  initial occupant { position = (250, 0, 600) mm }
}
)";

// Where each thing the tests point at is: 0-based line and UTF-16 column.
Json At(int line, int character) { return {{"line", line}, {"character", character}}; }

class LspProtocolTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("sled_lsp_test_" + std::to_string(getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
    path_ = folder_ / "scene.sled";
    std::ofstream(path_) << kScene;
    uri_ = "file://" + path_.string();
    ASSERT_TRUE(client_.started());
    const Json response = client_.Request(
        "initialize", {{"processId", nullptr},
                       {"rootUri", nullptr},
                       {"capabilities", Json::object()},
                       {"initializationOptions",
                        {{"stdlib", (fs::path(SLED_SOURCE_ROOT) / "stdlib").string()}}}});
    ASSERT_TRUE(response.contains("result")) << response.dump();
    capabilities_ = response["result"]["capabilities"];
    client_.Notify("initialized", Json::object());
  }
  void TearDown() override {
    std::error_code error;
    fs::remove_all(folder_, error);
  }

  Json Open(std::string_view text) {
    client_.Notify(
        "textDocument/didOpen",
        {{"textDocument",
          {{"uri", uri_}, {"languageId", "sled"}, {"version", 1}, {"text", std::string(text)}}}});
    return client_.AwaitDiagnostics(uri_);
  }

  Json Request(const std::string& method, Json position) {
    return client_.Request(method,
                           {{"textDocument", {{"uri", uri_}}}, {"position", std::move(position)}});
  }

  fs::path folder_;
  fs::path path_;
  std::string uri_;
  LspClient client_;
  Json capabilities_;
};

TEST_F(LspProtocolTest, InitializeAnnouncesEveryFeature) {
  for (const char* feature :
       {"hoverProvider", "definitionProvider", "referencesProvider", "completionProvider",
        "documentFormattingProvider", "documentSymbolProvider", "codeActionProvider"}) {
    EXPECT_TRUE(capabilities_.contains(feature)) << feature;
  }
  EXPECT_EQ(capabilities_["textDocumentSync"]["change"], 2);  // incremental
}

TEST_F(LspProtocolTest, OpenPublishesTheCheckersDiagnosticsWithCodeHintAndExplainLink) {
  const Json published = Open(kScene);
  ASSERT_EQ(published["diagnostics"].size(), 1u) << published.dump(2);
  const Json& diagnostic = published["diagnostics"][0];
  EXPECT_EQ(diagnostic["code"], "E0204");
  EXPECT_EQ(diagnostic["severity"], 1);
  EXPECT_EQ(diagnostic["range"]["start"], At(7, 10));
  EXPECT_EQ(diagnostic["range"]["end"], At(7, 24));
  EXPECT_THAT(diagnostic["message"].get<std::string>(),
              HasSubstr("help: did you mean `occupant.pelvis`?"));
  // The explanation `sled explain E0204` prints, as a page the editor can open.
  const std::string href = diagnostic["codeDescription"]["href"];
  ASSERT_THAT(href, HasSubstr("E0204.md"));
  std::ifstream page(href.substr(std::string("file://").size()));
  std::string first_line;
  std::getline(page, first_line);
  EXPECT_THAT(first_line, HasSubstr("E0204"));
}

TEST_F(LspProtocolTest, AnIncrementalChangeRechecks) {
  Open(kScene);
  // Insert the missing `i` of `pelvs`.
  client_.Notify("textDocument/didChange",
                 {{"textDocument", {{"uri", uri_}, {"version", 2}}},
                  {"contentChanges",
                   {{{"range", {{"start", At(7, 23)}, {"end", At(7, 23)}}}, {"text", "i"}}}}});
  Json published = client_.AwaitDiagnostics(uri_);
  EXPECT_EQ(published["version"], 2);
  EXPECT_TRUE(published["diagnostics"].empty()) << published.dump(2);
  // Two edits in one change apply in order: a line inserted above `param gap = 5 mm`, then its
  // unit (now on line 3) made a mass, which the plane's corner (now line 7) cannot take.
  client_.Notify("textDocument/didChange",
                 {{"textDocument", {{"uri", uri_}, {"version", 3}}},
                  {"contentChanges",
                   {{{"range", {{"start", At(2, 0)}, {"end", At(2, 0)}}}, {"text", "  // gap\n"}},
                    {{"range", {{"start", At(3, 16)}, {"end", At(3, 18)}}}, {"text", "kg"}}}}});
  published = client_.AwaitDiagnostics(uri_);
  ASSERT_EQ(published["diagnostics"].size(), 1u) << published.dump(2);
  EXPECT_EQ(published["diagnostics"][0]["code"], "E0302");
  EXPECT_EQ(published["diagnostics"][0]["range"]["start"], At(7, 53));
}

TEST_F(LspProtocolTest, HoverShowsSegmentMassAndInertiaAndWhereItIsDeclared) {
  Open(kScene);
  client_.Notify("textDocument/didChange",
                 {{"textDocument", {{"uri", uri_}, {"version", 2}}},
                  {"contentChanges",
                   {{{"range", {{"start", At(7, 23)}, {"end", At(7, 23)}}}, {"text", "i"}}}}});
  client_.AwaitDiagnostics(uri_);
  const Json hover = Request("textDocument/hover", At(7, 20));
  const std::string text = hover["result"]["contents"]["value"];
  EXPECT_THAT(text, HasSubstr("**segment** `occupant.pelvis`"));
  // stdlib/humans/male50.sled: `mass = 8.71 kg`, `inertia = (0.0815, 0.0449, 0.0893) kg*m^2`.
  EXPECT_THAT(text, HasSubstr("- mass: 8.71 kg"));
  EXPECT_THAT(text, HasSubstr("- principal inertia: (0.0815, 0.0449, 0.0893) kg*m^2"));
  EXPECT_THAT(text, HasSubstr("male50.sled"));
  EXPECT_THAT(text, HasSubstr("segment pelvis {"));
}

TEST_F(LspProtocolTest, HoverShowsQuantitiesInSiAndParameterValues) {
  Open(kScene);
  // `56 km/h` on line 5.
  std::string text = Request("textDocument/hover", At(5, 47))["result"]["contents"]["value"];
  EXPECT_THAT(text, HasSubstr("56 km/h"));
  EXPECT_THAT(text, HasSubstr("= 15.5556 m/s"));
  // The use of `gap` in `let double_gap = gap * 2`: its value in SI.
  text = Request("textDocument/hover", At(3, 20))["result"]["contents"]["value"];
  EXPECT_THAT(text, HasSubstr("**parameter** `gap`"));
  EXPECT_THAT(text, HasSubstr("- value: 0.005 m"));
  // `double_gap`, computed from it.
  text = Request("textDocument/hover", At(6, 55))["result"]["contents"]["value"];
  EXPECT_THAT(text, HasSubstr("- value: 0.01 m"));
  // An attribute keyword: its schema entry.
  text = Request("textDocument/hover", At(4, 10))["result"]["contents"]["value"];
  EXPECT_THAT(text, HasSubstr("**end**"));
  EXPECT_THAT(text, HasSubstr("time"));
}

TEST_F(LspProtocolTest, DefinitionGoesIntoTheStandardLibraryAndReferencesFindEveryUse) {
  Open(kScene);
  const Json definition = Request("textDocument/definition", At(7, 12))["result"];
  // `occupant.pelvs` does not resolve: no definition, and no error either.
  EXPECT_TRUE(definition.is_null()) << definition.dump();
  const Json surface = Request("textDocument/definition", At(7, 32))["result"];
  EXPECT_EQ(surface["uri"], uri_);
  EXPECT_EQ(surface["range"]["start"], At(6, 8));

  client_.Notify("textDocument/didChange",
                 {{"textDocument", {{"uri", uri_}, {"version", 2}}},
                  {"contentChanges",
                   {{{"range", {{"start", At(7, 23)}, {"end", At(7, 23)}}}, {"text", "i"}}}}});
  client_.AwaitDiagnostics(uri_);
  const Json pelvis = Request("textDocument/definition", At(7, 20))["result"];
  EXPECT_THAT(pelvis["uri"].get<std::string>(), HasSubstr("stdlib/humans/male50.sled"));
  EXPECT_EQ(pelvis["range"]["start"]["line"], 81);  // `segment pelvis {` is line 82

  const Json references = client_.Request("textDocument/references",
                                          {{"textDocument", {{"uri", uri_}}},
                                           {"position", At(2, 9)},
                                           {"context", {{"includeDeclaration", true}}}})["result"];
  ASSERT_EQ(references.size(), 2u) << references.dump(2);
  EXPECT_EQ(references[0]["range"]["start"], At(2, 8));
  EXPECT_EQ(references[1]["range"]["start"], At(3, 19));
}

std::vector<std::string> Labels(const Json& items) {
  std::vector<std::string> labels;
  for (const Json& item : items) labels.push_back(item["label"]);
  return labels;
}

TEST_F(LspProtocolTest, CompletionOffersKeywordsUnitsAndNames) {
  Open(kScene);
  // After `time { `: the time block's attributes.
  auto labels = Labels(Request("textDocument/completion", At(4, 9))["result"]);
  EXPECT_THAT(labels, ::testing::IsSupersetOf({"end", "output_every"}));
  EXPECT_THAT(labels, ::testing::Not(::testing::Contains("mass")));
  // After `10 ` in `end = 10 ms`: units.
  labels = Labels(Request("textDocument/completion", At(4, 18))["result"]);
  EXPECT_THAT(labels, ::testing::IsSupersetOf({"ms", "s", "m"}));
  // In the contact's target: the segments of the imported body.
  labels = Labels(Request("textDocument/completion", At(7, 19))["result"]);
  EXPECT_THAT(labels, ::testing::IsSupersetOf({"occupant.pelvis", "occupant.head", "seat_pan"}));
  // At the start of a line in the scenario: its declarations and attributes.
  client_.Notify("textDocument/didChange",
                 {{"textDocument", {{"uri", uri_}, {"version", 2}}},
                  {"contentChanges",
                   {{{"range", {{"start", At(8, 0)}, {"end", At(8, 0)}}}, {"text", "  \n"}}}}});
  client_.AwaitDiagnostics(uri_);
  labels = Labels(Request("textDocument/completion", At(8, 2))["result"]);
  EXPECT_THAT(labels, ::testing::IsSupersetOf({"contact", "belt", "gravity", "output"}));
}

TEST_F(LspProtocolTest, FormattingGivesWhatSledFmtWrites) {
  Open("scenario \"f\" {\n    param  gap=5 mm\n  time {end = 1 s\noutput_every = 1 ms}\n}");
  const Json edits = client_.Request(
      "textDocument/formatting",
      {{"textDocument", {{"uri", uri_}}}, {"options", {{"tabSize", 2}, {"insertSpaces", true}}}});
  ASSERT_EQ(edits["result"].size(), 1u) << edits.dump(2);
  EXPECT_EQ(edits["result"][0]["newText"],
            "scenario \"f\" {\n  param gap = 5 mm\n  time {\n    end = 1 s\n    output_every = 1 "
            "ms\n  }\n}\n");
  // A file with syntax errors is not formatted (the parser's skipped statements would go).
  client_.Notify("textDocument/didChange",
                 {{"textDocument", {{"uri", uri_}, {"version", 2}}},
                  {"contentChanges", {{{"text", "scenario \"f\" {\n  time { end = = }\n}\n"}}}}});
  client_.AwaitDiagnostics(uri_);
  const Json refused = client_.Request(
      "textDocument/formatting", {{"textDocument", {{"uri", uri_}}}, {"options", Json::object()}});
  EXPECT_TRUE(refused.contains("error")) << refused.dump();
}

TEST_F(LspProtocolTest, SymbolsOutlineTheScene) {
  Open(kScene);
  const Json symbols =
      client_.Request("textDocument/documentSymbol", {{"textDocument", {{"uri", uri_}}}})["result"];
  ASSERT_EQ(symbols.size(), 1u);
  EXPECT_EQ(symbols[0]["name"], "lsp test");
  std::vector<std::string> names;
  for (const Json& child : symbols[0]["children"]) names.push_back(child["name"]);
  EXPECT_THAT(names, ::testing::IsSupersetOf({"occupant", "gap", "double_gap", "time", "sled",
                                              "seat_pan", "occupant.pelvs with seat_pan"}));
}

TEST_F(LspProtocolTest, CodeActionReplacesAMisspelledName) {
  Open(kScene);
  const Json actions = client_.Request("textDocument/codeAction",
                                       {{"textDocument", {{"uri", uri_}}},
                                        {"range", {{"start", At(7, 12)}, {"end", At(7, 12)}}},
                                        {"context", {{"diagnostics", Json::array()}}}})["result"];
  ASSERT_EQ(actions.size(), 1u) << actions.dump(2);
  EXPECT_EQ(actions[0]["title"], "Replace with `occupant.pelvis`");
  const Json& edit = actions[0]["edit"]["changes"][uri_][0];
  EXPECT_EQ(edit["newText"], "occupant.pelvis");
  EXPECT_EQ(edit["range"]["start"], At(7, 10));
  EXPECT_EQ(edit["range"]["end"], At(7, 24));
}

TEST_F(LspProtocolTest, ShutdownThenExitEndsWithZero) {
  Open(kScene);
  const Json response = client_.Request("shutdown", nullptr);
  EXPECT_TRUE(response.contains("result") && response["result"].is_null()) << response.dump();
  client_.Notify("exit", nullptr);
  EXPECT_EQ(client_.CloseAndWait(), 0);
}

TEST_F(LspProtocolTest, MalformedMessagesNeverEndTheServer) {
  Open(kScene);
  client_.SendBody("{not json");
  client_.SendBody("[1, 2, 3]");
  client_.SendBody(std::string(10000, '[') + std::string(10000, ']'));
  client_.SendRaw("Content-Length: banana\r\n\r\n");
  client_.SendRaw("X-Nothing: 1\r\n\r\n");
  client_.SendBody(R"({"jsonrpc":"2.0","id":{"a":1},"method":"textDocument/hover"})");
  client_.SendBody(
      R"({"jsonrpc":"2.0","id":7,"method":"textDocument/hover","params":{"textDocument":{"uri":5}}})");
  client_.SendBody(
      R"({"jsonrpc":"2.0","id":8,"method":"textDocument/hover","params":{"textDocument":{"uri":"file:///nowhere.sled"},"position":{"line":0,"character":0}}})");
  client_.SendBody(R"({"jsonrpc":"2.0","id":9,"method":"no/suchMethod","params":{}})");
  client_.SendBody(
      R"({"jsonrpc":"2.0","method":"textDocument/didChange","params":{"textDocument":{"uri":")" +
      uri_ +
      R"("},"contentChanges":[{"range":{"start":{"line":999,"character":999},"end":{"line":0,"character":-1}},"text":"x"}]}})");
  // Positions far past the end are clamped to it.
  const Json hover = Request("textDocument/hover", At(100000, 100000));
  EXPECT_TRUE(hover.contains("result")) << hover.dump();
  EXPECT_EQ(client_.AwaitResponse(7)["error"]["code"], -32602);
  // The errors came in order before; the server still answers, and still checks edits.
  const Json symbols =
      client_.Request("textDocument/documentSymbol", {{"textDocument", {{"uri", uri_}}}});
  EXPECT_EQ(symbols["result"].size(), 1u);
  // Without shutdown, the end of input ends the server with 1.
  EXPECT_EQ(client_.CloseAndWait(), 1);
}

}  // namespace
}  // namespace sled::testing
