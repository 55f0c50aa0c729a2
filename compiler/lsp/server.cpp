#include "compiler/lsp/server.h"

#include <iostream>
#include <stdexcept>

#include <fmt/format.h>

#include "compiler/lsp/completion.h"
#include "compiler/lsp/hover.h"
#include "compiler/lsp/json_rpc.h"
#include "compiler/lsp/navigation.h"
#include "lang/format/formatter.h"

namespace sled::lsp {
namespace {

// JSON-RPC and LSP error codes.
constexpr int kParseError = -32700;
constexpr int kInvalidRequest = -32600;
constexpr int kMethodNotFound = -32601;
constexpr int kInvalidParams = -32602;
constexpr int kInternalError = -32603;
constexpr int kServerNotInitialized = -32002;
constexpr int kRequestFailed = -32803;

// A request that cannot be answered: becomes an error response.
struct RequestError : std::runtime_error {
  RequestError(int error_code, const std::string& message)
      : std::runtime_error(message), code(error_code) {}
  int code;
};

// JSON nested deeper than this is refused before parsing: no LSP message comes near it, and
// copying or printing a value recurses once per level.
constexpr int kMaxJsonDepth = 128;

bool NestedTooDeeply(const std::string& body) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < body.size(); ++i) {
    const char c = body[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

std::string Dump(const Json& json) {
  // Text from the client may hold invalid UTF-8: replace it rather than throw.
  return json.dump(-1, ' ', false, Json::error_handler_t::replace);
}

const Json& Field(const Json& object, const char* name) {
  static const Json kNull;
  if (!object.is_object()) return kNull;
  const auto it = object.find(name);
  return it == object.end() ? kNull : *it;
}

std::string StringField(const Json& object, const char* name) {
  const Json& value = Field(object, name);
  if (!value.is_string()) {
    throw RequestError(kInvalidParams, fmt::format("`{}` must be a string", name));
  }
  return value.get<std::string>();
}

Json Response(const Json& id, Json result) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}};
}

Json ErrorResponse(const Json& id, int code, const std::string& message) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}};
}

}  // namespace

Server::Server(AnalysisOptions options) : options_(std::move(options)) {}
Server::~Server() = default;

void Server::Notify(const std::string& method, Json params) {
  outgoing_.push_back(
      Dump({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}}));
}

void Server::Log(const std::string& message) {
  Notify("window/logMessage", {{"type", 3}, {"message", "sled: " + message}});
}

std::vector<std::string> Server::Handle(const std::string& body) {
  outgoing_.clear();
  if (NestedTooDeeply(body)) {
    outgoing_.push_back(Dump(ErrorResponse(nullptr, kInvalidRequest, "JSON nested too deeply")));
    return std::move(outgoing_);
  }
  const Json message = Json::parse(body, nullptr, /*allow_exceptions=*/false);
  if (message.is_discarded()) {
    outgoing_.push_back(Dump(ErrorResponse(nullptr, kParseError, "the message is not JSON")));
    return std::move(outgoing_);
  }
  const Json& method = Field(message, "method");
  const Json& id = Field(message, "id");
  const bool valid_id = id.is_number_integer() || id.is_string();
  if (!method.is_string()) {
    // A response to a request of ours (we send none), or garbage.
    if (!message.is_object() || (!message.contains("result") && !message.contains("error"))) {
      outgoing_.push_back(Dump(ErrorResponse(valid_id ? id : Json(nullptr), kInvalidRequest,
                                             "a message needs a `method`")));
    }
    return std::move(outgoing_);
  }
  const bool is_request = message.contains("id");
  if (is_request && !valid_id) {
    outgoing_.push_back(
        Dump(ErrorResponse(nullptr, kInvalidRequest, "a request id is a number or a string")));
    return std::move(outgoing_);
  }
  const std::string name = method.get<std::string>();
  // The responses come after the notifications the request queued (diagnostics).
  try {
    Json result = Dispatch(name, Field(message, "params"), is_request);
    if (is_request) outgoing_.push_back(Dump(Response(id, std::move(result))));
  } catch (const RequestError& error) {
    if (is_request) {
      outgoing_.push_back(Dump(ErrorResponse(id, error.code, error.what())));
    } else {
      Log(fmt::format("`{}`: {}", name, error.what()));
    }
  } catch (const std::exception& error) {
    if (is_request) {
      outgoing_.push_back(Dump(ErrorResponse(id, kInternalError, error.what())));
    } else {
      Log(fmt::format("`{}` failed: {}", name, error.what()));
    }
  }
  return std::move(outgoing_);
}

Json Server::Dispatch(const std::string& method, const Json& params, bool is_request) {
  if (method == "initialize") return Initialize(params);
  if (method == "exit") {
    exited_ = true;
    return nullptr;
  }
  if (!initialized_) {
    if (is_request) throw RequestError(kServerNotInitialized, "`initialize` comes first");
    return nullptr;
  }
  if (shut_down_ && is_request) throw RequestError(kInvalidRequest, "the server was shut down");
  if (method == "shutdown") {
    shut_down_ = true;
    return nullptr;
  }
  if (method == "textDocument/didOpen") {
    DidOpen(params);
    return nullptr;
  }
  if (method == "textDocument/didChange") {
    DidChange(params);
    return nullptr;
  }
  if (method == "textDocument/didClose") {
    DidClose(params);
    return nullptr;
  }
  if (method == "textDocument/formatting") return Formatting(params);
  if (method == "textDocument/hover") {
    Document& document = DocumentOf(params);
    const auto hover = Hover(*document.analysis, OffsetOf(document, params));
    if (!hover) return nullptr;
    RangeConverter ranges(document.analysis->sources());
    return {{"contents", {{"kind", "markdown"}, {"value", hover->markdown}}},
            {"range", RangeJson(ranges.RangeOf(hover->range))}};
  }
  if (method == "textDocument/definition" || method == "textDocument/references") {
    Document& document = DocumentOf(params);
    RangeConverter ranges(document.analysis->sources());
    ranges.SetUri(document.analysis->file(), document.text->uri());
    const std::uint32_t offset = OffsetOf(document, params);
    if (method == "textDocument/definition") return Definition(*document.analysis, ranges, offset);
    const Json& include = Field(Field(params, "context"), "includeDeclaration");
    return References(*document.analysis, ranges, offset,
                      include.is_boolean() && include.get<bool>());
  }
  if (method == "textDocument/completion") {
    Document& document = DocumentOf(params);
    return Completions(*document.analysis, document.text->text(), OffsetOf(document, params));
  }
  if (method == "textDocument/documentSymbol") {
    Document& document = DocumentOf(params);
    RangeConverter ranges(document.analysis->sources());
    return DocumentSymbols(*document.analysis, ranges);
  }
  if (method == "textDocument/codeAction") {
    Document& document = DocumentOf(params);
    const auto range = RangeFrom(Field(params, "range"));
    if (!range) throw RequestError(kInvalidParams, "`range` is missing or malformed");
    RangeConverter ranges(document.analysis->sources());
    ranges.SetUri(document.analysis->file(), document.text->uri());
    return CodeActions(*document.analysis, ranges, document.text->uri(),
                       document.text->OffsetOf(range->start), document.text->OffsetOf(range->end),
                       explain_links_);
  }
  if (is_request) throw RequestError(kMethodNotFound, fmt::format("no method `{}`", method));
  return nullptr;  // notifications the server does not use ($/cancelRequest, didSave, ...)
}

Json Server::Initialize(const Json& params) {
  if (initialized_) throw RequestError(kInvalidRequest, "`initialize` was already sent");
  initialized_ = true;
  const Json& settings = Field(params, "initializationOptions");
  if (const Json& stdlib = Field(settings, "stdlib"); stdlib.is_string()) {
    options_.stdlib = stdlib.get<std::string>();
  }
  if (const Json& path = Field(settings, "modulePath"); path.is_array()) {
    for (const Json& folder : path) {
      if (folder.is_string()) options_.module_path.push_back(folder.get<std::string>());
    }
  }
  return {{"capabilities",
           {{"positionEncoding", "utf-16"},
            {"textDocumentSync", {{"openClose", true}, {"change", 2}}},
            {"hoverProvider", true},
            {"definitionProvider", true},
            {"referencesProvider", true},
            {"completionProvider", {{"triggerCharacters", {".", " "}}}},
            {"documentFormattingProvider", true},
            {"documentSymbolProvider", true},
            {"codeActionProvider", {{"codeActionKinds", {"quickfix"}}}}}},
          {"serverInfo", {{"name", "sled"}}}};
}

Server::Document& Server::DocumentOf(const Json& params) {
  const std::string uri = StringField(Field(params, "textDocument"), "uri");
  const auto it = documents_.find(uri);
  if (it == documents_.end()) {
    throw RequestError(kRequestFailed, fmt::format("`{}` is not open", uri));
  }
  return it->second;
}

std::uint32_t Server::OffsetOf(const Document& document, const Json& params) const {
  const auto position = PositionFrom(Field(params, "position"));
  if (!position) throw RequestError(kInvalidParams, "`position` is missing or malformed");
  return document.text->OffsetOf(*position);
}

void Server::DidOpen(const Json& params) {
  const Json& item = Field(params, "textDocument");
  const std::string uri = StringField(item, "uri");
  const std::string text = StringField(item, "text");
  const Json& version = Field(item, "version");
  Document& document = documents_[uri];
  document.text = std::make_unique<TextDocument>(
      uri, text, version.is_number_integer() ? version.get<std::int64_t>() : 0);
  Recheck(document);
}

void Server::DidChange(const Json& params) {
  Document& document = DocumentOf(params);
  const Json& version = Field(Field(params, "textDocument"), "version");
  const Json& changes = Field(params, "contentChanges");
  if (!changes.is_array()) throw RequestError(kInvalidParams, "`contentChanges` must be a list");
  for (const Json& change : changes) {
    const std::string text = StringField(change, "text");
    const Json& range = Field(change, "range");
    if (range.is_null()) {
      document.text->Replace(text);
    } else if (const auto parsed = RangeFrom(range)) {
      document.text->Edit(*parsed, text);
    } else {
      throw RequestError(kInvalidParams, "a change's `range` is malformed");
    }
  }
  if (version.is_number_integer()) document.text->set_version(version.get<std::int64_t>());
  Recheck(document);
}

void Server::DidClose(const Json& params) {
  const std::string uri = StringField(Field(params, "textDocument"), "uri");
  const auto it = documents_.find(uri);
  if (it == documents_.end()) return;
  for (const std::string& published : it->second.published) {
    Notify("textDocument/publishDiagnostics", {{"uri", published}, {"diagnostics", Json::array()}});
  }
  documents_.erase(it);
}

void Server::Recheck(Document& document) {
  document.analysis =
      std::make_unique<Analysis>(document.text->text(), PathOfUri(document.text->uri()), options_);
  RangeConverter ranges(document.analysis->sources());
  ranges.SetUri(document.analysis->file(), document.text->uri());
  std::map<std::string, Json> by_uri = DiagnosticsByUri(*document.analysis, ranges, explain_links_);
  // Files that had diagnostics from the last check and have none now are cleared.
  for (const std::string& uri : document.published) {
    if (!by_uri.contains(uri)) by_uri[uri] = Json::array();
  }
  document.published.clear();
  for (auto& [uri, diagnostics] : by_uri) {
    if (!diagnostics.empty()) document.published.insert(uri);
    Json params = {{"uri", uri}, {"diagnostics", std::move(diagnostics)}};
    if (uri == document.text->uri()) params["version"] = document.text->version();
    Notify("textDocument/publishDiagnostics", std::move(params));
  }
  document.published.insert(document.text->uri());
}

Json Server::Formatting(const Json& params) {
  Document& document = DocumentOf(params);
  lang::SourceManager sources;
  const lang::FileId file = sources.Add(PathOfUri(document.text->uri()), document.text->text());
  lang::DiagnosticCollector ignored;  // the document's diagnostics are published already
  const std::optional<std::string> formatted = lang::FormatBuffer(sources, file, ignored);
  if (!formatted) {
    throw RequestError(kRequestFailed,
                       "the file has syntax errors; formatting would lose the statements the "
                       "parser skipped");
  }
  if (*formatted == document.text->text()) return Json::array();
  const Position end =
      document.text->PositionOf(static_cast<std::uint32_t>(document.text->text().size()));
  return Json::array({{{"range", RangeJson({{0, 0}, end})}, {"newText", *formatted}}});
}

int Server::Run(std::istream& in, std::ostream& out) {
  while (!exited_) {
    IncomingMessage message = ReadMessage(in);
    if (message.status == IncomingMessage::Status::kEnd) break;
    if (message.status == IncomingMessage::Status::kBadHeader) {
      outgoing_.clear();
      Log(message.problem);
      for (const std::string& body : outgoing_) WriteMessage(out, body);
      if (!in.good()) break;
      continue;
    }
    for (const std::string& body : Handle(message.body)) WriteMessage(out, body);
  }
  return exited_ && shut_down_ ? 0 : 1;
}

int RunLanguageServer(const AnalysisOptions& options) {
  std::ios::sync_with_stdio(false);
  Server server(options);
  return server.Run(std::cin, std::cout);
}

}  // namespace sled::lsp
