// `sled lsp`: the language server. Speaks JSON-RPC over a stream pair (stdin and stdout), keeps
// the open documents, re-checks a document on every change through sled::Compile and publishes
// its diagnostics, and answers hover, definition, references, completion, formatting, document
// symbols and code actions (docs/editors.md).
//
// Robustness: any message (malformed JSON, a wrong field type, a position past the end, an
// unknown method) gets an error response or is dropped with a log message; nothing a client
// sends ends the server except `exit` or the end of its input.
#pragma once

#include <iosfwd>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "compiler/lsp/analysis.h"
#include "compiler/lsp/diagnostics.h"
#include "compiler/lsp/protocol.h"
#include "compiler/lsp/text_document.h"

namespace sled::lsp {

class Server {
 public:
  explicit Server(AnalysisOptions options = {});
  ~Server();

  // Reads messages from `in` and writes responses and notifications to `out` until `exit` or
  // the end of input. The exit code: 0 after `shutdown` then `exit`, else 1 (as the protocol
  // asks).
  int Run(std::istream& in, std::ostream& out);

  // Handles one message body; returns the bodies of the messages to send, in order.
  std::vector<std::string> Handle(const std::string& body);

  bool exited() const { return exited_; }
  bool shut_down() const { return shut_down_; }

 private:
  struct Document {
    std::unique_ptr<TextDocument> text;
    std::unique_ptr<Analysis> analysis;
    std::set<std::string> published;  // URIs that got diagnostics from this document
  };

  Json Dispatch(const std::string& method, const Json& params, bool is_request);
  Json Initialize(const Json& params);
  void DidOpen(const Json& params);
  void DidChange(const Json& params);
  void DidClose(const Json& params);
  Json Formatting(const Json& params);
  // Re-checks a document and queues its diagnostics.
  void Recheck(Document& document);
  // The open document a request names; throws a request error when it is not open.
  Document& DocumentOf(const Json& params);
  std::uint32_t OffsetOf(const Document& document, const Json& params) const;
  void Notify(const std::string& method, Json params);
  void Log(const std::string& message);

  AnalysisOptions options_;
  ExplainLinks explain_links_;
  std::map<std::string, Document> documents_;
  std::vector<std::string> outgoing_;
  bool initialized_ = false;
  bool shut_down_ = false;
  bool exited_ = false;
};

// `sled lsp`: serves on the process's stdin and stdout.
int RunLanguageServer(const AnalysisOptions& options);

}  // namespace sled::lsp
