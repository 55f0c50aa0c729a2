// libFuzzer target for the language server (`sled lsp`): random edits to an open document, each
// followed by a request at a random position, and random bytes as the protocol stream itself.
// Nothing a client sends may crash the server or trip a sanitizer.
//
// Input: bytes starting with `{` or `C` are a raw message stream (after a valid `initialize`).
// Otherwise the bytes up to the first 0xFF are the document's text, and the rest is an edit
// script: per edit, 5 bytes (start line, start column, end line, end column, length) and that
// many bytes of inserted text (at most 16 edits).
//
//   build-asan/tests/fuzz/sled_lsp_fuzzer -max_total_time=60 CORPUS_DIR
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "compiler/lsp/server.h"

namespace {

using sled::lsp::Json;

std::string Frame(const std::string& body) {
  return "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

const std::string kInitialize =
    R"({"jsonrpc":"2.0","id":0,"method":"initialize","params":{"capabilities":{}}})";

Json At(int line, int character) { return {{"line", line}, {"character", character}}; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  sled::lsp::AnalysisOptions options;
  options.stdlib = std::string(SLED_SOURCE_ROOT) + "/stdlib";
  sled::lsp::Server server(options);
  if (!bytes.empty() && (bytes[0] == '{' || bytes[0] == 'C')) {
    std::istringstream in(Frame(kInitialize) + bytes);
    std::ostringstream out;
    (void)server.Run(in, out);
    return 0;
  }
  (void)server.Handle(kInitialize);
  const std::size_t split = bytes.find('\xFF');
  // Inside the source tree, so relative imports reach real modules as well as missing ones.
  const std::string uri = "file://" + std::string(SLED_SOURCE_ROOT) + "/examples/fuzz.sled";
  const Json open = {
      {"jsonrpc", "2.0"},
      {"method", "textDocument/didOpen"},
      {"params",
       {{"textDocument", {{"uri", uri}, {"version", 1}, {"text", bytes.substr(0, split)}}}}}};
  (void)server.Handle(open.dump(-1, ' ', false, Json::error_handler_t::replace));
  static const char* const kRequests[] = {"textDocument/hover",          "textDocument/definition",
                                          "textDocument/references",     "textDocument/completion",
                                          "textDocument/documentSymbol", "textDocument/formatting",
                                          "textDocument/codeAction"};
  std::size_t at = split == std::string::npos ? bytes.size() : split + 1;
  int version = 1;
  // Each edit re-checks the document: a bounded count keeps every input well inside the
  // fuzzer's time limit, whatever its length.
  constexpr int kMaxEdits = 16;
  while (at + 5 <= bytes.size() && version <= kMaxEdits) {
    const auto* edit = reinterpret_cast<const std::uint8_t*>(bytes.data() + at);
    const std::size_t length = std::min<std::size_t>(edit[4], bytes.size() - at - 5);
    const Json change = {
        {"jsonrpc", "2.0"},
        {"method", "textDocument/didChange"},
        {"params",
         {{"textDocument", {{"uri", uri}, {"version", ++version}}},
          {"contentChanges",
           {{{"range", {{"start", At(edit[0], edit[1])}, {"end", At(edit[2], edit[3])}}},
             {"text", bytes.substr(at + 5, length)}}}}}}};
    (void)server.Handle(change.dump(-1, ' ', false, Json::error_handler_t::replace));
    const Json request = {
        {"jsonrpc", "2.0"},
        {"id", version},
        {"method", kRequests[edit[0] % std::size(kRequests)]},
        {"params",
         {{"textDocument", {{"uri", uri}}},
          {"position", At(edit[2], edit[3])},
          {"range", {{"start", At(edit[0], edit[1])}, {"end", At(edit[2], edit[3])}}},
          {"context", {{"includeDeclaration", true}, {"diagnostics", Json::array()}}}}}};
    (void)server.Handle(request.dump());
    at += 5 + length;
  }
  (void)server.Handle(R"({"jsonrpc":"2.0","id":-1,"method":"shutdown"})");
  return 0;
}
