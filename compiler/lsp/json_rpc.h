// The base protocol of the Language Server Protocol: JSON-RPC messages framed by a
// `Content-Length` header, over a byte stream (the server's stdin and stdout).
#pragma once

#include <cstddef>
#include <istream>
#include <optional>
#include <ostream>
#include <string>

namespace sled::lsp {

// The largest message body the server accepts: a document larger than sled reads from disk
// (lang::kMaxFileBytes) cannot come in an edit either.
inline constexpr std::size_t kMaxMessageBytes = std::size_t{256} << 20;

struct IncomingMessage {
  enum class Status {
    kOk,         // `body` holds the message's bytes (not yet parsed as JSON)
    kEnd,        // the stream ended between messages
    kBadHeader,  // a header without a valid Content-Length, or an oversized one: skipped
  };
  Status status = Status::kEnd;
  std::string body;
  std::string problem;  // kBadHeader: what was wrong, for the log
};

// Reads the next framed message. A bad header is reported and its body (when its length is
// known and sane) skipped, so one garbled message does not end the session.
IncomingMessage ReadMessage(std::istream& in);

// Writes one framed message and flushes.
void WriteMessage(std::ostream& out, const std::string& body);

}  // namespace sled::lsp
